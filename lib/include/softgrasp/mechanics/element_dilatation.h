#ifndef softgrasp_mechanics_element_dilatation_h
#define softgrasp_mechanics_element_dilatation_h

#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <softgrasp/materials/volumetric_energy.h>
#include <vector>

namespace softgrasp
{
  /// The coefficients of J~ and p~ (Pa) of one element in the P_k basis of
  /// ElementDilatation: the element unknowns of a Newton solve.
  struct DilatationCoefficients
  {
    dealii::Vector<double> J, p;
  };

  /**
   * The element-local fields of the three-field (Hu-Washizu) u-p-J
   * formulation,
   *   Pi(u, p~, J~) = int Psi_iso(Cbar) + U(J~) + p~ (J - J~) dV,
   * with p~ and J~ discontinuous polynomials of degree k (P0 for Q1, P1 for
   * Q2 displacements). Their two stationarity conditions are element-local
   * L2 projections,
   *   J~ = Pi_h J,        p~ = Pi_h U'(J~),
   * so for a given displacement both follow on each element without global
   * unknowns. Linearising p~ through J~ gives the condensed volumetric
   * stiffness
   *   K_con = G^T M^-1 K_JJ M^-1 G,
   * with M the mass matrix of the P_k basis, K_JJ = int N U''(J~) N^T dV and
   * G_ak = int N_a J div_x(N_k) dV. This is the static condensation of
   * deal.II step-44 carried out exactly, and reduces to the mean-dilatation
   * method for P0.
   *
   * The P1 basis is {1, (X - X_c)/h} in reference coordinates, centred and
   * scaled on the element for conditioning.
   *
   * Within a Newton solve J~ and p~ may instead be given (unknowns updated
   * with the Newton increments, as in step-44); then their residuals
   * R_p = int N (J - J~) dV and R_J = int N (U'(J~) - p~) dV need not
   * vanish, and condensing the linearised element equations adds
   * G^T s, s = M^-1 R_J + A R_p, to the internal force. Their increments
   * follow from the displacement increment du as
   *   dJ~ = M^-1 (R_p + G du),   dp~ = s + A G du.
   * At a converged state both residuals vanish and the two ways agree.
   */
  template <int dim> class ElementDilatation
  {
  public:
    /// @p degree of the pressure/dilatation polynomials: 0 or 1.
    explicit ElementDilatation(const unsigned int degree);

    /**
     * Compute J~ and p~ on one element from the quadrature points
     * @p points (reference, m), weights @p JxW (m^3) and the pointwise
     * J = det F at them. Throws InvertedMaterialState if J~ <= 0 anywhere.
     * Without @p with_stiffness the condensed kernel is not computed (the
     * explicit solver needs the forces only).
     */
    void reinit(const std::vector<dealii::Point<dim>> &points,
                const std::vector<double>             &JxW,
                const std::vector<double>             &J,
                const VolumetricEnergy                &energy,
                const bool                             with_stiffness = true);

    /**
     * As reinit(), but with J~ and p~ @p given instead of projected; the
     * condensed kernel is always computed (the force needs it). Throws
     * InvertedMaterialState if J~ <= 0 anywhere.
     */
    void reinit(const std::vector<dealii::Point<dim>> &points,
                const std::vector<double>             &JxW,
                const std::vector<double>             &J,
                const VolumetricEnergy                &energy,
                const DilatationCoefficients          &given);

    /// The coefficients of J~ and p~ of the last reinit().
    void get_coefficients(DilatationCoefficients &result) const;
    /// s = M^-1 R_J + A R_p (Pa), the force correction G^T s and the
    /// offset of dp~; zero after the projecting reinit().
    const dealii::Vector<double> &pressure_offset() const;
    /// M^-1 R_p, the offset of dJ~; zero after the projecting reinit().
    const dealii::Vector<double> &dilatation_offset() const;

    unsigned int n_basis() const;
    /// Basis function @p a at quadrature point @p q.
    double basis(const unsigned int a, const unsigned int q) const;
    /// Projected pressure p~ (Pa) at quadrature point @p q.
    double pressure(const unsigned int q) const;
    /// Projected dilatation J~ at quadrature point @p q.
    double dilatation(const unsigned int q) const;
    /// Element mean of p~ (Pa).
    double mean_pressure() const;
    /// The n_basis x n_basis kernel A = M^-1 K_JJ M^-1 (Pa/m^3).
    const dealii::FullMatrix<double> &condensed_kernel() const;

    /**
     * The augmented splitting of the condensed volumetric stiffness for a
     * block preconditioner, G^T A G = G^T W G + G^T A' G with W = w M^-1
     * (w in Pa) moved into the displacement block and A' = A - W kept in
     * the pressure coupling. w = min(@p gamma, U''_min / 2) keeps A' at
     * least half of A (U''_min: the least U''(J~) over the element's
     * points). Writes A' to @p shifted and to @p schur_inverse the inverse
     * of the approximate pressure Schur complement of the augmented
     * element, S = A'^-1 + M / (mu + w), where M / (mu + w) stands for
     * G (K_uu + G^T W G)^-1 G^T for a solid of shear modulus @p mu (Pa)
     * (the pressure mass matrix approximation of Stokes flow and its
     * augmented Lagrangian form). Bounded as U'' grows without limit: the
     * basis of a block preconditioner robust in the bulk modulus. Returns
     * w.
     */
    double augment(const double                gamma,
                   const double                mu,
                   dealii::FullMatrix<double> &shifted,
                   dealii::FullMatrix<double> &schur_inverse) const;
    /// The inverse of the mass matrix of the P_k basis (1/m^3).
    const dealii::FullMatrix<double> &mass_inverse() const;

  private:
    /// Basis values, mass matrix, its inverse and the moments int N J dV.
    void set_up_basis(const std::vector<dealii::Point<dim>> &points,
                      const std::vector<double>             &JxW,
                      const std::vector<double>             &J);
    /// J~ at the points from its coefficients; throws if not positive.
    void evaluate_dilatation();
    /// p~ at the points and its mean from its coefficients.
    void evaluate_pressure(const std::vector<double> &JxW);
    /// The moments int N U'(J~) dV into @p result.
    void pressure_moments(const std::vector<double> &JxW,
                          const VolumetricEnergy    &energy,
                          dealii::Vector<double>    &result) const;
    /// The kernel A = M^-1 K_JJ M^-1 and the least U''(J~).
    void compute_kernel(const std::vector<double> &JxW,
                        const VolumetricEnergy    &energy);

    unsigned int               degree;
    unsigned int               n_functions;
    unsigned int               n_points = 0;
    std::vector<double>        values; ///< N_a(x_q), a-major
    std::vector<double>        p_tilde, J_tilde;
    double                     p_mean        = 0;
    double                     curvature_min = 0; ///< least U''(J~) (Pa)
    dealii::FullMatrix<double> kernel;
    /// Scratch of reinit(), kept to avoid allocations per cell.
    dealii::FullMatrix<double> mass, M_inverse, scratch;
    dealii::Vector<double>     moments;
    dealii::Vector<double>     J_coefficients, p_coefficients;
    dealii::Vector<double>     J_offset, p_offset;
    dealii::Vector<double>     residual_p, residual_J, mass_times;
  };
} // namespace softgrasp

#endif
