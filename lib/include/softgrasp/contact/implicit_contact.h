#ifndef softgrasp_contact_implicit_contact_h
#define softgrasp_contact_implicit_contact_h

#include <deal.II/base/timer.h>
#include <memory>
#include <softgrasp/base/plugin_registry.h>
#include <softgrasp/contact/contact_surface.h>
#include <softgrasp/mechanics/nodal_conditions.h>
#include <string>

namespace softgrasp
{
  /**
   * A contact enforcement of the implicit (Newton) solvers: the surface
   * geometry of ContactSurface and the node equations of NodalConditions,
   * plus what a time stepper needs around a load step. Implementations
   * register themselves by name ('Contact/Enforcement') through
   * SOFTGRASP_REGISTER_CONTACT_ENFORCEMENT; the steppers never list them.
   */
  template <int dim>
  class ImplicitContact : public ContactSurface<dim>,
                          public NodalConditions<dim>
  {
  public:
    ImplicitContact(const ContactParameters &parameters,
                    const RigidBodySet      &bodies)
        : ContactSurface<dim>(parameters, bodies)
    {
    }

    /// Record the converged state at @p time (s) as the start of the next
    /// step's slip (call after each converged step and after a restart).
    virtual void accept_step(const SolidSystem<dim> &system,
                             const double            time) = 0;

    /// Start a load step of length @p step (s) (or its retry after a
    /// cut-back) from the state of the last accept_step().
    virtual void begin_step(const double step)
    {
      (void)step;
    }

    /**
     * After a converged Newton solve: update what the solve held fixed
     * (the lagged normal forces and frames, the multipliers of an augmented
     * Lagrangian) and return whether they had settled, so that the step is
     * done; false asks for another Newton solve of the same step. @p report
     * receives one line for the log. Collective.
     */
    virtual bool settle(const SolidSystem<dim> &system, std::string &report)
    {
      (void)system;
      report.clear();
      return true;
    }

    /// The most outer iterations (settle() calls) a step may take.
    virtual unsigned int max_outer_iterations() const
    {
      return 1;
    }

    /**
     * After settle(): how far the friction forces exceed Coulomb's bound
     * against the current normal forces, max_j (|f_t,j| - mu lambda_j),
     * relative to mu max_j lambda_j (0: Coulomb holds at every node; a
     * lagged friction law may exceed it until its lag has settled).
     */
    virtual double coulomb_excess() const
    {
      return 0;
    }

    /// Whether a step whose outer iterations have not settled after
    /// max_outer_iterations() is accepted (with a warning) rather than cut
    /// back.
    virtual bool accept_unsettled() const
    {
      return false;
    }

    /**
     * Finish a step whose lag does not settle another way (the polish):
     * from the next solve on, friction acts against the current normal
     * forces (Coulomb's law exactly; the tangent is then not symmetric and
     * not a Hessian), settle() still updating the multipliers. Returns
     * false if the enforcement has no such mode. Saves the lag.
     */
    virtual bool begin_polish()
    {
      return false;
    }

    /// Leave the polish: keep its lag (@p keep, it settled) or restore the
    /// one saved by begin_polish().
    virtual void end_polish(const bool keep)
    {
      (void)keep;
    }

    /// After how many unsettled outer iterations the polish is tried (and
    /// again after as many more); 0: never.
    virtual unsigned int polish_after() const
    {
      return 0;
    }

    /// The most Newton iterations of one solve this enforcement asks for
    /// (0: 'Newton/Maximum iterations' stands).
    virtual unsigned int max_newton_iterations() const
    {
      return 0;
    }

    /**
     * Implicit dynamics: the lumped mass @p mass (kg per dof; ghosted) and
     * 1/dt^2 of the step (0 restores the quasi-static case), for
     * enforcements that weigh contact against the nodes' inertia.
     */
    virtual void set_inertia(const dealii::TrilinosWrappers::MPI::Vector &mass,
                             const double inverse_dt_squared)
    {
      (void)mass;
      (void)inverse_dt_squared;
    }

    /// Status changes summed over all evaluations since the last
    /// accept_step() (the active-set changes of a load step).
    virtual unsigned int changes_in_step() const = 0;
  };

  /// Builds one kind of ImplicitContact; registered by name.
  template <int dim> class ContactEnforcement
  {
  public:
    virtual ~ContactEnforcement() = default;
    /// No settings besides those of 'Contact'.
    static void declare_parameters(dealii::ParameterHandler &)
    {
    }
    /// The enforcement for @p parameters and @p bodies (@p shear_modulus:
    /// the stiffest material's, Pa).
    virtual std::unique_ptr<ImplicitContact<dim>>
    create(const ContactParameters &parameters,
           const RigidBodySet      &bodies,
           const double             shear_modulus,
           dealii::TimerOutput     &timer) const = 0;
  };

  template <int dim>
  using ContactEnforcementRegistry = PluginRegistry<ContactEnforcement<dim>>;

  /// The enforcement named 'Contact/Enforcement' in @p parameters (for
  /// "automatic": ContactParameters::implicit_enforcement()); an unknown
  /// name lists the registered ones.
  template <int dim>
  std::unique_ptr<ImplicitContact<dim>>
  create_implicit_contact(const ContactParameters &parameters,
                          const RigidBodySet      &bodies,
                          const double             shear_modulus,
                          dealii::TimerOutput     &timer)
  {
    return ContactEnforcementRegistry<dim>::create(
               parameters.implicit_enforcement(), "contact enforcement")
        ->create(parameters, bodies, shear_modulus, timer);
  }
} // namespace softgrasp

/**
 * Register the ImplicitContact template @p Class (constructed from
 * (ContactParameters, RigidBodySet, shear modulus, TimerOutput)) as the
 * contact enforcement @p name; @p tag is a unique identifier.
 */
#define SOFTGRASP_REGISTER_CONTACT_ENFORCEMENT(Class, tag, name, description)  \
  namespace                                                                    \
  {                                                                            \
    template <int d>                                                           \
    class softgrasp_enforcement_##tag                                          \
        : public ::softgrasp::ContactEnforcement<d>                            \
    {                                                                          \
    public:                                                                    \
      std::unique_ptr<::softgrasp::ImplicitContact<d>>                         \
      create(const ::softgrasp::ContactParameters &p,                          \
             const ::softgrasp::RigidBodySet      &b,                          \
             const double                          g,                          \
             ::dealii::TimerOutput                &t) const override                          \
      {                                                                        \
        return std::make_unique<Class<d>>(p, b, g, t);                         \
      }                                                                        \
    };                                                                         \
    [[maybe_unused]] const bool softgrasp_enforcement_2d_##tag =               \
        ::softgrasp::ContactEnforcementRegistry<2>::register_plugin(           \
            name,                                                              \
            description,                                                       \
            &::softgrasp::ContactEnforcement<2>::declare_parameters,           \
            []() -> std::unique_ptr<::softgrasp::ContactEnforcement<2>>        \
            { return std::make_unique<softgrasp_enforcement_##tag<2>>(); });   \
    [[maybe_unused]] const bool softgrasp_enforcement_3d_##tag =               \
        ::softgrasp::ContactEnforcementRegistry<3>::register_plugin(           \
            name,                                                              \
            description,                                                       \
            &::softgrasp::ContactEnforcement<3>::declare_parameters,           \
            []() -> std::unique_ptr<::softgrasp::ContactEnforcement<3>>        \
            { return std::make_unique<softgrasp_enforcement_##tag<3>>(); });   \
  }

#endif
