#ifndef softgrasp_explicit_internal_force_operator_h
#define softgrasp_explicit_internal_force_operator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <memory>
#include <softgrasp/explicit/vectorized_force_kernel.h>
#include <softgrasp/materials/material_library.h>
#include <vector>

namespace softgrasp
{
  /**
   * Matrix-free internal forces of a total-Lagrangian hyperelastic solid,
   *   f_int,i = sum_cells int P(F) : grad N_i dV,   F = I + grad u,
   * with deal.II's MatrixFree/FEEvaluation (sum factorisation; SIMD over
   * cells where deal.II is built with vectorisation) for a displacement
   * field FESystem(FE_Q(p), dim), p = 1 or 2, on Gauss quadrature with
   * p + 1 points per direction. The stress comes from the material
   * library's batch path (Material::first_piola_batch()), the same formulas
   * as the implicit solver's; cells are grouped by material id so that a
   * batch shares one material. 2D is plane strain.
   *
   * This is the kernel of the explicit solver: one apply() per time step.
   * Two implementations of the same forces: the vectorised kernel
   * (VectorizedForceKernel, explicit SIMD over cells; the default) and the
   * reference kernel (FEEvaluation, one cell at a time with deal.II's
   * vectorisation width), which also handles the cells with hanging-node
   * constraints of the vectorised one.
   */
  template <int dim> class InternalForceOperator
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    /// Which implementation evaluates the forces.
    enum class Kernel
    {
      vectorized, ///< VectorizedForceKernel (reference for constrained cells)
      reference   ///< FEEvaluation for every cell
    };

    /// The volumetric response.
    enum class Dilatation
    {
      pointwise,        ///< J = det F at each point (displacement form)
      element_constant, ///< u-p-J with P0 pressure (mean dilatation)
      element_linear    ///< u-p-J with P1 pressure (Q2-P1)
    };

    /// What apply() found besides the forces.
    struct Result
    {
      double energy = 0; ///< int Psi dV, summed over all ranks (J; J/m 2D)
      double min_J  = 1; ///< smallest det F at a quadrature point (all ranks)
    };

    /**
     * @p constraints: hanging-node constraints only (Dirichlet values are
     * the integrator's business; their rows keep their internal force, the
     * reaction). With Dilatation::element_constant, the volumetric
     * response uses one dilatation per element, J_e = v_e / V_e (the
     * element's deformed over its reference volume) and the pressure
     * p = U'(J_e): the u-p-J form with constant pressure per element, which
     * does not lock for nearly incompressible tissue. With
     * Dilatation::element_linear, J~ and p~ are the element-wise linear L2
     * projections of ElementDilatation (Q2-P1). Either is the quasi-static
     * solver's element of the same pressure degree. The vectorised kernel
     * has no linear projection: element_linear evaluates every cell with
     * the reference kernel.
     */
    InternalForceOperator(const dealii::Mapping<dim>              &mapping,
                          const dealii::DoFHandler<dim>           &dofs,
                          const dealii::AffineConstraints<double> &constraints,
                          const MaterialLibrary                   &materials,
                          const Dilatation dilatation = Dilatation::pointwise,
                          const Kernel     kernel     = Kernel::vectorized);

    void initialize_dof_vector(VectorType &vector) const;

    /**
     * f = f_int(u). @p u needs its ghost values (it is updated here). Where
     * det F <= 0 at a quadrature point the stress is not evaluated there
     * (min_J reports it; the caller stops the run).
     */
    Result apply(const VectorType &u, VectorType &f) const;

    const dealii::MatrixFree<dim, double> &matrix_free() const;

  private:
    template <int degree>
    void local_apply(const dealii::MatrixFree<dim, double>       &data,
                     VectorType                                  &dst,
                     const VectorType                            &src,
                     const std::pair<unsigned int, unsigned int> &cells) const;

    /// The reference kernel on the cell batches in @p cells.
    void apply_reference(const VectorType                &u,
                         VectorType                      &f,
                         const std::vector<unsigned int> &cells) const;

    dealii::MatrixFree<dim, double>             data;
    std::unique_ptr<VectorizedForceKernel<dim>> vectorized;
    const MaterialLibrary                      &materials;
    unsigned int                                degree;
    Dilatation                                  dilatation;
    /// Structural directions per (cell batch, quadrature point, lane), for
    /// anisotropic materials only (empty otherwise).
    std::vector<StructuralDirections> directions;
    mutable double                    energy = 0, min_J = 1;
  };
} // namespace softgrasp

#endif
