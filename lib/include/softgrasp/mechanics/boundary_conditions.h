#ifndef softgrasp_mechanics_boundary_conditions_h
#define softgrasp_mechanics_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/component_mask.h>
#include <memory>
#include <softgrasp/base/parameter_reader.h>
#include <vector>

namespace softgrasp
{
  /**
   * Loads and supports of a quasi-static solid, read from the "Boundary
   * conditions" subsection. Every expression is a muParser expression of
   * the reference position (x, y[, z], m) and the pseudo-time t (s):
   *
   *  - Dirichlet: prescribed displacement (m) on a boundary id, for a
   *    selection of components;
   *  - Traction: a dead-load traction (Pa) per unit reference area;
   *  - Pressure: a follower pressure (Pa) acting against the current outward
   *    normal of the deformed surface;
   *  - Gravity: a body acceleration (m/s^2), multiplied by each material's
   *    reference density.
   *
   * In 2D (plane strain) forces are per metre of thickness.
   */
  template <int dim> class BoundaryConditions
  {
  public:
    struct Dirichlet
    {
      dealii::types::boundary_id                   boundary_id;
      dealii::ComponentMask                        components;
      std::shared_ptr<dealii::FunctionParser<dim>> displacement; ///< m
    };

    struct Traction
    {
      dealii::types::boundary_id                   boundary_id;
      std::shared_ptr<dealii::FunctionParser<dim>> traction; ///< Pa
    };

    struct Pressure
    {
      dealii::types::boundary_id                   boundary_id;
      std::shared_ptr<dealii::FunctionParser<dim>> pressure; ///< Pa
    };

    /// The id lists and the gravity entry.
    static void declare_parameters(dealii::ParameterHandler &prm);

    /// The pass that declares one subsection per listed boundary id.
    static void add_passes(ParameterReader &reader);

    void parse_parameters(dealii::ParameterHandler &prm);

    /// Set the pseudo-time t (s) of every expression.
    void set_time(const double time);

    /// Body acceleration (m/s^2) at reference point @p X.
    dealii::Tensor<1, dim> gravity(const dealii::Point<dim> &X) const;

    bool has_gravity() const;

    /// True if a follower load makes the tangent unsymmetric.
    bool has_follower_loads() const;

    /// Boundary ids whose reaction force is reported (Dirichlet ones).
    std::vector<dealii::types::boundary_id> reaction_boundary_ids() const;

    std::vector<Dirichlet> dirichlet;
    std::vector<Traction>  tractions;
    std::vector<Pressure>  pressures;

  private:
    std::shared_ptr<dealii::FunctionParser<dim>> body_acceleration;
    bool                                         gravity_is_zero = true;
  };
} // namespace softgrasp

#endif
