#ifndef softgrasp_materials_isochoric_model_h
#define softgrasp_materials_isochoric_model_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/vectorization.h>
#include <softgrasp/base/plugin_registry.h>
#include <softgrasp/materials/point_values.h>
#include <string>

namespace softgrasp
{
  /**
   * Unit reference directions of a material point (fibre families of an
   * anisotropic tissue). Isotropic models ignore them.
   */
  struct StructuralDirections
  {
    static constexpr unsigned int                    max_directions = 2;
    unsigned int                                     n_directions   = 0;
    std::array<dealii::Tensor<1, 3>, max_directions> direction;
  };

  /**
   * Input and output of IsochoricModel::evaluate_block() for up to
   * point_block_size points, structure of arrays. Symmetric components are
   * stored in the order 00, 11, 22, 01, 02, 12. Points from n_points up to
   * the next multiple of 8 may be evaluated too and must hold a valid state
   * (e.g. Cbar = I); their results are ignored.
   */
  struct IsochoricPointBlock
  {
    unsigned int               n_points = 0;
    std::array<PointValues, 6> Cbar; ///< isochoric right Cauchy-Green tensor
    /// Component d of structural direction a at [3 a + d] (anisotropic
    /// models only; n_directions of them per point).
    unsigned int n_directions = 0;
    std::array<PointValues, 3 * StructuralDirections::max_directions>
                               directions;
    PointValues                energy; ///< output: Psi_iso (Pa)
    std::array<PointValues, 6> X;      ///< output: dPsi_iso/dCbar (Pa)
  };

  /**
   * The isochoric part of a decoupled hyperelastic strain energy,
   * Psi_iso(Cbar), as a function of the isochoric right Cauchy-Green tensor
   * Cbar = J^{-2/3} C. An implementation returns the energy and its first
   * and second derivatives with respect to Cbar; the class Material applies
   * the chain rule through Cbar(C), adds the volumetric energy U(J) and
   * returns stresses and consistent tangents. Each model is one file pair
   * and registers itself by name (SOFTGRASP_REGISTER_ISOCHORIC_MODEL).
   *
   * Units: energies in J/m^3 = Pa; parameters in SI units.
   */
  /// A batch of values, one per SIMD lane (points of several cells).
  using VectorizedDouble = dealii::VectorizedArray<double>;

  class IsochoricModel
  {
  public:
    /// Psi, dPsi/dCbar and d2Psi/dCbar2 at one point.
    struct Response
    {
      double                        energy = 0;
      dealii::SymmetricTensor<2, 3> first_derivative;
      dealii::SymmetricTensor<4, 3> second_derivative;
    };

    virtual ~IsochoricModel() = default;

    /**
     * Evaluate at @p Cbar (det Cbar = 1). The second derivative is only
     * computed if @p with_second_derivative is set.
     */
    virtual void evaluate(const dealii::SymmetricTensor<2, 3> &Cbar,
                          const StructuralDirections          &directions,
                          const bool with_second_derivative,
                          Response  &response) const = 0;

    /**
     * W and dW/dCbar for a batch of points, one per lane of the vectorized
     * arguments (the explicit solver's matrix-free internal forces). Lanes
     * from @p n_lanes on are padding and must hold a valid Cbar (e.g. the
     * identity). @p directions has one entry per lane (n_lanes of them) for
     * anisotropic models. The default evaluates lane by lane with
     * evaluate(); models with a vectorizable formula override it, from the
     * same implementation as evaluate().
     */
    virtual void
    evaluate_batch(const dealii::SymmetricTensor<2, 3, VectorizedDouble> &Cbar,
                   const StructuralDirections *directions,
                   const unsigned int          n_lanes,
                   VectorizedDouble           &energy,
                   dealii::SymmetricTensor<2, 3, VectorizedDouble>
                       &first_derivative) const;

    /**
     * W and dW/dCbar for a block of points (the vectorised stress kernel of
     * the explicit solver). The default evaluates point by point with
     * evaluate(); models with a vectorisable formula override it with
     * explicit SIMD (softgrasp/base/simd.h), from the same formula.
     */
    virtual void evaluate_block(IsochoricPointBlock &block) const;

    /// The small-strain shear modulus mu_0 (Pa).
    virtual double initial_shear_modulus() const = 0;

    /// Read the model's parameters; @p path names the subsection in errors.
    virtual void parse_parameters(dealii::ParameterHandler &prm,
                                  const std::string        &path) = 0;

    /// Number of structural directions the model needs (0 if isotropic).
    virtual unsigned int n_structural_directions() const;

    /**
     * The unit structural directions at reference position @p X (m). The
     * default has none; fibre-reinforced models read a direction field.
     */
    virtual StructuralDirections
    structural_directions(const dealii::Point<3> &X) const;

    /// A one-line description with the parameter values, for logs.
    virtual std::string summary() const = 0;
  };

  using IsochoricModelRegistry = PluginRegistry<IsochoricModel>;
} // namespace softgrasp

#define SOFTGRASP_REGISTER_ISOCHORIC_MODEL(Class, name, description)           \
  SOFTGRASP_REGISTER_PLUGIN(                                                   \
      ::softgrasp::IsochoricModel, Class, name, description)

#endif
