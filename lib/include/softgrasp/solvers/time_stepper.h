#ifndef softgrasp_solvers_time_stepper_h
#define softgrasp_solvers_time_stepper_h

#include <deal.II/base/parameter_handler.h>
#include <memory>
#include <softgrasp/base/plugin_registry.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/solvers/simulation_access.h>

namespace softgrasp
{
  /**
   * One way of integrating the solid in time, chosen by 'Time/Integrator'
   * (quasi-static, implicit dynamic, explicit dynamic, or a user's own).
   * The Simulation prepares the run (mesh, solid, contact from
   * make_contact(), a checkpoint's state on resume) and then calls run(),
   * which advances from the state's time to the end time, recording
   * steps, fields and checkpoints through SimulationAccess.
   *
   * Implementations register themselves by name from their own source
   * file (SOFTGRASP_REGISTER_TIME_STEPPER), also from outside the
   * library; the Simulation never lists them. A stepper with settings of
   * its own declares them in a static declare_parameters() (passed at
   * registration); the built-in ones take theirs from SolverParameters.
   */
  template <int dim> class TimeStepper
  {
  public:
    virtual ~TimeStepper() = default;

    /// No settings of its own (the default of a registered stepper).
    static void declare_parameters(dealii::ParameterHandler &)
    {
    }

    /// Whether the solid needs its tangent matrix (Newton) or only its
    /// residuals.
    virtual bool needs_tangent() const = 0;
    /// Whether inertia holds the body, so that a run without supports
    /// and contact is well posed.
    virtual bool has_inertia() const = 0;
    /// The number of fields besides the displacement in its checkpoints,
    /// for the settings @p parameters.
    virtual unsigned int
    n_checkpoint_fields(const SolverParameters &parameters) const = 0;
    /// Refuse inputs this stepper cannot take (before anything is built).
    virtual void check_inputs(const SimulationAccess<dim> &run) const
    {
      (void)run;
    }
    /// The contact enforcement of this stepper, set up on the run's solid
    /// (@p shear_modulus: the stiffest material's, Pa).
    virtual std::unique_ptr<ContactSurface<dim>>
    make_contact(const SimulationAccess<dim> &run, double shear_modulus) = 0;
    /// Advance from the prepared state to the end time (or the stop
    /// criterion); throws a SolverFailure after writing the last good
    /// state if it cannot go on.
    virtual void run(const SimulationAccess<dim> &run) = 0;
  };

  template <int dim>
  using TimeStepperRegistry = PluginRegistry<TimeStepper<dim>>;

  /**
   * Thrown when a run cannot go on (a load step fails after all cut-backs,
   * an explicit step blows up). The message names the step, the time and
   * the cause; the last good state has been written (VTU and checkpoint)
   * before.
   */
  class SolverFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace softgrasp

/**
 * Register the time stepper template @p Class (instantiated for 2D and 3D,
 * default-constructible) under @p name; @p tag is a unique identifier.
 */
#define SOFTGRASP_REGISTER_TIME_STEPPER(Class, tag, name, description)         \
  namespace                                                                    \
  {                                                                            \
    [[maybe_unused]] const bool softgrasp_stepper_2d_##tag =                   \
        ::softgrasp::TimeStepperRegistry<2>::register_plugin(                  \
            name,                                                              \
            description,                                                       \
            &Class<2>::declare_parameters,                                     \
            []() -> std::unique_ptr<::softgrasp::TimeStepper<2>>               \
            { return std::make_unique<Class<2>>(); });                         \
    [[maybe_unused]] const bool softgrasp_stepper_3d_##tag =                   \
        ::softgrasp::TimeStepperRegistry<3>::register_plugin(                  \
            name,                                                              \
            description,                                                       \
            &Class<3>::declare_parameters,                                     \
            []() -> std::unique_ptr<::softgrasp::TimeStepper<3>>               \
            { return std::make_unique<Class<3>>(); });                         \
  }

#endif
