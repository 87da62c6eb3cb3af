#ifndef softgrasp_materials_material_h
#define softgrasp_materials_material_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <memory>
#include <softgrasp/materials/isochoric_model.h>
#include <softgrasp/materials/volumetric_energy.h>
#include <stdexcept>
#include <string>

namespace softgrasp
{
  /**
   * Thrown when a material is evaluated at a deformation gradient with
   * J = det F <= 0 (an inverted element) or a non-finite F. Solvers catch it
   * to cut the step back.
   */
  class InvertedMaterialState : public std::runtime_error
  {
  public:
    explicit InvertedMaterialState(const double J);
    const double J;
  };

  /**
   * Input and output of Material::first_piola_block() for up to
   * point_block_size points, structure of arrays (the vectorised stress
   * kernel of the explicit solver). Tensors are stored row by row, F_ij at
   * [3 i + j].
   */
  struct MaterialPointBlock
  {
    unsigned int               n_points = 0;
    std::array<PointValues, 9> F; ///< deformation gradients, det F > 0 (1)
    /// With given_pressure, the volumetric stress uses pressure (Pa)
    /// instead of U'(J) (the mean-dilatation form).
    bool        given_pressure = false;
    PointValues pressure;
    /// Anisotropic materials: set isochoric.n_directions and
    /// isochoric.directions; the rest of it is scratch space.
    IsochoricPointBlock        isochoric;
    std::array<PointValues, 9> P;      ///< output: first Piola stress (Pa)
    PointValues                energy; ///< output: Psi, or Psi_iso with
                                       ///< given_pressure (Pa)
  };

  /**
   * A hyperelastic material evaluated at one quadrature point: the
   * decoupled strain energy Psi(C) = U(J) + Psi_iso(Cbar), Cbar = J^{-2/3} C,
   * with an IsochoricModel and a VolumetricEnergy, plus a reference density.
   * It returns
   *  - the second Piola-Kirchhoff stress S = 2 dPsi/dC and the material
   *    tangent CC = 2 dS/dC = dS/dE (both Pa), or
   *  - the Kirchhoff stress tau = F S F^T and the spatial tangent
   *    J cc = push-forward of CC (both Pa),
   * and the dilatational wave speed (m/s) for explicit time steps.
   *
   * The chain rule through Cbar(C) is done here, once, for every model:
   *   dCbar/dC = f (II - 1/3 C (x) C^{-1}),  f = J^{-2/3},
   *   dPsi_iso/dC = f DEV(X),  X = dPsi_iso/dCbar,
   * and the second derivative adds the curvature of Cbar(C) contracted with
   * X. Materials are 3D; 2D problems use the plane-strain embedding.
   */
  class Material
  {
  public:
    /// Stress and tangent at one point.
    struct Response
    {
      double                        energy = 0; ///< Psi (Pa)
      dealii::SymmetricTensor<2, 3> stress;     ///< S or tau (Pa)
      dealii::SymmetricTensor<4, 3> tangent;    ///< CC or J cc (Pa)
    };

    Material(std::string                     name,
             std::unique_ptr<IsochoricModel> isochoric_model,
             const VolumetricEnergy         &volumetric_energy,
             const double                    density);

    /// S and (if @p with_tangent) dS/dE at deformation gradient @p F.
    void evaluate_material(const dealii::Tensor<2, 3> &F,
                           const StructuralDirections &directions,
                           const bool                  with_tangent,
                           Response                   &response) const;

    /**
     * As evaluate_material(), but with the volumetric stress set by a given
     * pressure @p pressure (Pa) instead of U'(J): S = S_iso + p J C^{-1}, and
     * the tangent holds p fixed. This is the displacement block of mixed
     * (u-p-J) formulations, where p is an independent, element-wise field;
     * the energy returned is the isochoric part only.
     */
    void evaluate_material_with_pressure(const dealii::Tensor<2, 3> &F,
                                         const StructuralDirections &directions,
                                         const double                pressure,
                                         const bool with_tangent,
                                         Response  &response) const;

    /// Spatial counterpart of evaluate_material_with_pressure(): tau, J cc.
    void evaluate_spatial_with_pressure(const dealii::Tensor<2, 3> &F,
                                        const StructuralDirections &directions,
                                        const double                pressure,
                                        const bool with_tangent,
                                        Response  &response) const;

    /// tau and (if @p with_tangent) J cc at deformation gradient @p F.
    void evaluate_spatial(const dealii::Tensor<2, 3> &F,
                          const StructuralDirections &directions,
                          const bool                  with_tangent,
                          Response                   &response) const;

    /**
     * First Piola-Kirchhoff stress P = F S (Pa) and the energy Psi (Pa) for
     * a batch of deformation gradients, one per SIMD lane: the stress of
     * the explicit solver's matrix-free internal forces, from the same
     * formulas as evaluate_material(). Every lane below @p n_lanes must
     * have det F > 0 (check before); the padding lanes from @p n_lanes on
     * must hold a valid F (e.g. the identity) and give P = 0 there.
     * @p directions holds n_lanes entries. With @p pressure, the
     * volumetric stress uses that pressure p (Pa; U'(J) replaced by p, as
     * in evaluate_spatial_with_pressure()) and @p energy holds the
     * isochoric part only: the mean-dilatation (u-p-J) form.
     */
    void first_piola_batch(const dealii::Tensor<2, 3, VectorizedDouble> &F,
                           const StructuralDirections             *directions,
                           const unsigned int                      n_lanes,
                           dealii::Tensor<2, 3, VectorizedDouble> &P,
                           VectorizedDouble                       &energy,
                           const VectorizedDouble *pressure = nullptr) const;

    /**
     * P and Psi for a block of points, as first_piola_batch() but with
     * explicit SIMD over the points (softgrasp/base/simd.h): the explicit
     * solver's vectorised stress kernel. Points from n_points up to the
     * next multiple of 8 are set to F = I here and evaluated too.
     */
    void first_piola_block(MaterialPointBlock &block) const;

    /// Psi(F) (Pa).
    double strain_energy(const dealii::Tensor<2, 3> &F,
                         const StructuralDirections &directions) const;

    /// Cauchy stress sigma = tau / J (Pa).
    dealii::SymmetricTensor<2, 3>
    cauchy_stress(const dealii::Tensor<2, 3> &F,
                  const StructuralDirections &directions) const;

    /**
     * Largest speed (m/s) of a plane longitudinal/shear wave in the current
     * state, from the acoustic tensor Q(N)_ik = A_iJkL N_J N_L / rho_0 of the
     * first elasticity tensor A = dP/dF, maximised over a fixed set of 13
     * reference directions (axes, face and body diagonals) and the principal
     * directions of C. Exact for isotropic materials in the reference state;
     * an estimate otherwise, to be used with a safety factor. Pairs with the
     * reference element size in total-Lagrangian explicit dynamics.
     */
    double
    dilatational_wave_speed(const dealii::Tensor<2, 3> &F,
                            const StructuralDirections &directions) const;

    /// sqrt((kappa + 4/3 mu_0) / rho_0) (m/s), the small-strain value.
    double reference_wave_speed() const;

    /// Structural (fibre) directions at reference position @p X (m).
    StructuralDirections structural_directions(const dealii::Point<3> &X) const;

    /**
     * This material for a body whose own frame is placed by x -> R x + t
     * (a study's placement of a mesh): its fibre direction field, given in
     * the body's own frame, becomes a(X) = R a_own(R^T (X - t)). The
     * constitutive model is shared, not copied.
     */
    std::shared_ptr<const Material>
    placed(const dealii::Tensor<2, 3> &rotation,
           const dealii::Tensor<1, 3> &translation) const;

    double                density() const; ///< reference density rho_0 (kg/m^3)
    double                initial_shear_modulus() const; ///< mu_0 (Pa)
    double                bulk_modulus() const;          ///< kappa (Pa)
    const std::string    &name() const;
    std::string           summary() const;
    const IsochoricModel &isochoric_model() const;
    const VolumetricEnergy &volumetric_energy() const;

  private:
    /// Common path: volumetric stress from a pressure @p p and its
    /// derivative @p dp_dJ (U'(J), U''(J) for the decoupled material).
    void evaluate_decoupled(const dealii::Tensor<2, 3> &F,
                            const StructuralDirections &directions,
                            const bool                  with_tangent,
                            const bool                  given_pressure,
                            const double                pressure,
                            Response                   &response) const;

    /// S, CC -> tau, J cc in place.
    static void push_forward(const dealii::Tensor<2, 3> &F,
                             const bool                  with_tangent,
                             Response                   &response);

    std::string                     material_name;
    std::shared_ptr<IsochoricModel> model;
    /// The placement of the frame the direction field is given in.
    dealii::Tensor<2, 3> frame_rotation = dealii::unit_symmetric_tensor<3>();
    dealii::Tensor<1, 3> frame_translation;
    VolumetricEnergy     volumetric;
    double               rho0;
  };
} // namespace softgrasp

#endif
