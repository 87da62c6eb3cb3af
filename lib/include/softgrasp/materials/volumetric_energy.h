#ifndef softgrasp_materials_volumetric_energy_h
#define softgrasp_materials_volumetric_energy_h

#include <softgrasp/materials/point_values.h>
#include <string>

namespace softgrasp
{
  /**
   * The volumetric part U(J) of a decoupled strain energy, with bulk modulus
   * kappa (Pa). All choices satisfy U(1) = U'(1) = 0 and U''(1) = kappa:
   *  - quadratic:    U = kappa/2 (J - 1)^2
   *  - logarithmic:  U = kappa/2 (ln J)^2
   *  - Simo-Taylor:  U = kappa/4 (J^2 - 1 - 2 ln J)
   * (see Doll and Schweizerhof 2000 for a comparison). The logarithmic and
   * Simo-Taylor forms grow without bound as J -> 0, which resists element
   * inversion; the quadratic form does not.
   */
  class VolumetricEnergy
  {
  public:
    enum class Type
    {
      quadratic,
      logarithmic,
      simo_taylor
    };

    VolumetricEnergy() = default;
    VolumetricEnergy(const Type type, const double bulk_modulus);

    /// "quadratic|logarithmic|Simo-Taylor", for a Patterns::Selection.
    static std::string names();
    /// The type named @p name; throws an InputError listing the valid names.
    static Type type_from_name(const std::string &name);

    double energy(const double J) const;            ///< U(J), Pa
    double first_derivative(const double J) const;  ///< dU/dJ, Pa
    double second_derivative(const double J) const; ///< d2U/dJ2, Pa

    /**
     * U and dU/dJ (Pa) for a block of points (the vectorised stress
     * kernel): entries up to n_points rounded up to a multiple of 8 are
     * evaluated, so J must hold valid values (J > 0) there.
     */
    void evaluate_block(const unsigned int n_points,
                        const PointValues &J,
                        PointValues       &U,
                        PointValues       &dU) const;

    double      bulk_modulus() const;
    std::string name() const;

  private:
    /// The formulas, for double and simd::Double.
    template <typename Number> Number energy_of(const Number &J) const;
    template <typename Number>
    Number first_derivative_of(const Number &J) const;

    Type   type  = Type::simo_taylor;
    double kappa = 0;
  };
} // namespace softgrasp

#endif
