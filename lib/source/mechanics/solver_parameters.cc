#include <cmath>
#include <deal.II/base/utilities.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_checks.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <utility>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    // One table per enum: the .prm spelling of each choice.
    const std::vector<std::pair<std::string, Formulation>> formulation_names = {
        {"displacement", Formulation::displacement},
        {"mixed u-p-J", Formulation::mixed_upJ}};
    const std::vector<std::pair<std::string, PressureDegree>>
        pressure_degree_names = {{"k-1", PressureDegree::below_displacement},
                                 {"0", PressureDegree::constant}};
    const std::vector<std::pair<std::string, LinearSolverType>> solver_names = {
        {"direct", LinearSolverType::direct},
        {"iterative", LinearSolverType::iterative},
        {"automatic", LinearSolverType::automatic}};
    const std::vector<std::pair<std::string, AmgSmoother>> smoother_names = {
        {"automatic", AmgSmoother::automatic},
        {"Chebyshev", AmgSmoother::chebyshev},
        {"Gauss-Seidel", AmgSmoother::gauss_seidel},
        {"symmetric Gauss-Seidel", AmgSmoother::symmetric_gauss_seidel}};

  } // namespace

  void DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Integer(1, 2),
                      "Degree of the displacement shape functions (Lagrange "
                      "Q1 or Q2). Unit: 1.");
    prm.declare_entry(
        "Formulation",
        "mixed u-p-J",
        Patterns::Selection(choice_pattern(formulation_names)),
        "'displacement': pure displacement (locks for Poisson's ratio near "
        "0.5). 'mixed u-p-J': three-field formulation with element-wise "
        "discontinuous pressure and dilatation of degree k-1, condensed per "
        "element; free of volumetric locking.");
    prm.declare_entry(
        "Pressure degree",
        "k-1",
        Patterns::Selection(choice_pattern(pressure_degree_names)),
        "Degree of the element-wise discontinuous pressure and dilatation of "
        "'mixed u-p-J' (k = 'Polynomial degree'). 'k-1': Q1-P0 and Q2-P1, "
        "the inf-sup stable pairs. '0': one pressure and dilatation per "
        "element (Q2-P0, mean dilatation): cheaper, coarser pressure. Both "
        "solvers "
        "use the same element, so switching 'Time/Integrator' keeps the "
        "discretisation. Unit: 1.");
    prm.leave_subsection();
  }

  void DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite element");
    degree      = prm.get_integer("Polynomial degree");
    formulation = lookup_choice(formulation_names, prm.get("Formulation"));
    pressure = lookup_choice(pressure_degree_names, prm.get("Pressure degree"));
    prm.leave_subsection();
  }

  std::string DiscretizationParameters::element_name() const
  {
    const std::string q = "Q" + std::to_string(degree);
    if (formulation == Formulation::displacement)
      return q + " displacement";
    return q + "-P" + std::to_string(pressure_degree()) + " u-p-J";
  }

  void TimeParameters::declare_parameters(ParameterHandler        &prm,
                                          const IntegratorChoices &integrators)
  {
    if (integrators.empty())
      throw std::logic_error("TimeParameters: no time integrator offered");
    // the typed default if offered, else the first choice
    std::string default_name = integrators.front().first;
    std::string names, descriptions;
    for (const auto &[name, description] : integrators)
    {
      names += (names.empty() ? "" : "|") + name;
      descriptions += " '" + name + "': " + description + ".";
      if (name == TimeParameters().integrator)
        default_name = name;
    }
    prm.enter_subsection("Time");
    prm.declare_entry("Integrator",
                      default_name,
                      Patterns::Selection(names),
                      "Time integration." + descriptions);
    prm.declare_entry("End time",
                      "1",
                      Patterns::Double(0),
                      "End of the run: the variable t in the load "
                      "expressions runs from 0 to it (a pseudo-time in "
                      "quasi-static runs, physical time in explicit dynamic "
                      "ones). Unit: s.");
    prm.declare_entry("Time step",
                      "0.1",
                      Patterns::Double(0),
                      "Quasi-static: the nominal load step. Explicit: the "
                      "interval at which the history, progress and VTU "
                      "output are recorded (the integration step is the "
                      "stable one). Unit: s.");
    prm.declare_entry("Minimum time step",
                      "1e-6",
                      Patterns::Double(0),
                      "A step that does not converge is halved; below this "
                      "size the run stops and writes its last converged "
                      "state. Unit: s.");
    prm.declare_entry("Maximum cut-backs",
                      "8",
                      Patterns::Integer(0, 60),
                      "How often one step may be halved. Unit: 1.");
    prm.declare_entry(
        "Phases",
        "",
        Patterns::Anything(),
        "Stepping per phase of the loading, 'end: step[, minimum]; ...' "
        "(s), phases in time order, the last ending at 'End time'; e.g. "
        "'0.5: 0.05; 1.5: 0.0125, 1e-7' steps by 0.05 s up to 0.5 s (an "
        "indentation) and by 0.0125 s, cut back to at least 1e-7 s, up to "
        "1.5 s (a pull). A step never crosses a phase's end. 'step' is the "
        "nominal load step (quasi-static and implicit dynamic) or the "
        "recording interval (explicit); 'minimum' defaults to 'Minimum "
        "time step'. Empty: one phase with 'Time step'. Unit: s.");
    prm.leave_subsection();
  }

  std::vector<TimePhase> TimeParameters::phase_list() const
  {
    if (phases.empty())
      return {{end_time, step_size, minimum_step}};
    if (std::abs(phases.back().end - end_time) > 1e-9 * end_time)
      throw InputError("'Time/Phases' ends at " +
                       std::to_string(phases.back().end) +
                       " s, but the run ends at " + std::to_string(end_time) +
                       " s ('Time/End time', or the end a study sets). Fix: "
                       "let the last phase end at the end time.");
    return phases;
  }

  TimePhase TimeParameters::phase_at(const double time) const
  {
    const auto list = phase_list();
    for (const auto &phase : list)
      if (time < phase.end - 1e-12 * end_time)
        return phase;
    return list.back();
  }

  double TimeParameters::phase_begin(const double time) const
  {
    double begin = 0;
    for (const auto &phase : phase_list())
    {
      if (time < phase.end - 1e-12 * end_time)
        return begin;
      begin = phase.end;
    }
    return begin;
  }

  namespace
  {
    /// Parse 'Time/Phases' (see its documentation).
    std::vector<TimePhase> parse_phases(const std::string &text,
                                        const double       default_minimum)
    {
      std::vector<TimePhase> phases;
      const std::string      entry = "Parameter 'Time/Phases'";
      for (const auto &item : Utilities::split_string_list(text, ';'))
      {
        const auto          colon = item.find(':');
        std::vector<double> step;
        TimePhase           phase;
        try
        {
          if (colon == std::string::npos)
            throw std::invalid_argument("no ':'");
          phase.end = Utilities::string_to_double(item.substr(0, colon));
          step      = Utilities::string_to_double(
              Utilities::split_string_list(item.substr(colon + 1)));
        }
        catch (...)
        {
          step.clear();
        }
        if (step.empty() || step.size() > 2)
          throw InputError(entry + ": '" + item +
                           "' is not 'end: step' or 'end: step, minimum'. "
                           "Fix: write e.g. '0.5: 0.05; 1.5: 0.0125, 1e-7' "
                           "(s).");
        phase.step         = step[0];
        phase.minimum      = step.size() == 2 ? step[1] : default_minimum;
        const double begin = phases.empty() ? 0.0 : phases.back().end;
        if (!std::isfinite(phase.end) || !std::isfinite(phase.step) ||
            !std::isfinite(phase.minimum))
          throw InputError(entry + ": '" + item +
                           "' has a value that is not a finite number. "
                           "Fix: give every phase a finite end and step, "
                           "e.g. '0.5: 0.05; 1.5: 0.0125' (s).");
        if (!(phase.end > begin) || !(phase.step > 0) || !(phase.minimum > 0) ||
            phase.minimum > phase.step)
          throw InputError(entry + ": in '" + item +
                           "' the end must follow the previous phase's end "
                           "(or 0) and 0 < minimum <= step. Fix: list the "
                           "phases in time order with positive steps (s).");
        phases.push_back(phase);
      }
      return phases;
    }
  } // namespace

  void TimeParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time");
    const CheckedSection section(prm, "Time");
    integrator    = prm.get("Integrator");
    end_time      = section.get_positive("End time", "s");
    step_size     = section.get_positive("Time step", "s");
    minimum_step  = section.get_positive("Minimum time step", "s");
    max_cut_backs = prm.get_integer("Maximum cut-backs");
    phases        = parse_phases(prm.get("Phases"), minimum_step);
    if (minimum_step > step_size)
      throw InputError("Parameter 'Time/Minimum time step' (" +
                       std::to_string(minimum_step) +
                       " s) exceeds 'Time/Time step' (" +
                       std::to_string(step_size) +
                       " s). Fix: make it smaller than the time step.");
    prm.leave_subsection();
    phase_list(); // the phases end at the end time
  }

  void NewtonParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Maximum iterations",
                      "15",
                      Patterns::Integer(1),
                      "Newton iterations per step before the step is cut "
                      "back. Unit: 1.");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "Converged when the residual norm is below this times "
                      "the force scale (the larger of the internal and the "
                      "external nodal force norms). Unit: 1.");
    prm.declare_entry("Absolute tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "Converged when the residual norm is below this. Unit: "
                      "N (N/m in plane strain).");
    prm.declare_entry("Increment tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "Also converged when the largest Newton update is "
                      "below this times the size of the domain, i.e. the "
                      "residual stagnates at round-off (stiff, nearly "
                      "incompressible materials at rest). Unit: 1.");
    prm.declare_entry("Line search",
                      "true",
                      Patterns::Bool(),
                      "Backtracking line search on the residual norm; also "
                      "halves steps that would invert an element.");
    prm.declare_entry("Maximum line search steps",
                      "6",
                      Patterns::Integer(0, 30),
                      "Halvings of one Newton update. Unit: 1.");
    prm.declare_entry(
        "Inexact linear solves",
        "true",
        Patterns::Bool(),
        "Iterative linear solver: stop each solve at the Eisenstat-Walker "
        "forcing term (at most 1e-4 times the right-hand side, tighter as "
        "Newton converges, never tighter than a tenth of the Newton "
        "tolerance needs) instead of 'Linear solver/Relative tolerance' "
        "alone. 'false' solves every step to 'Linear solver/Relative "
        "tolerance'. No effect on the direct solver.");
    prm.declare_entry(
        "Predictor",
        "extrapolated",
        Patterns::Selection("extrapolated|last converged"),
        "Where the Newton solve of an implicit step starts when the step "
        "is the minimisation of a potential ('Contact/Enforcement = "
        "incremental potential'). 'extrapolated': the last converged state "
        "moved on linearly in time, u_n + dt (u_n - u_{n-1}) / dt_{n-1} "
        "(with implicit dynamics u_n + dt v_n), kept only where its "
        "potential is lower than that of u_n; on a drag it carries the "
        "sticking nodes along with the rigid body instead of leaving the "
        "line search to walk them there. 'last converged': start from u_n. "
        "Other enforcements always start from u_n.");
    prm.leave_subsection();
  }

  void NewtonParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations        = prm.get_integer("Maximum iterations");
    relative_tolerance    = prm.get_double("Relative tolerance");
    absolute_tolerance    = prm.get_double("Absolute tolerance");
    increment_tolerance   = prm.get_double("Increment tolerance");
    line_search           = prm.get_bool("Line search");
    max_line_search_steps = prm.get_integer("Maximum line search steps");
    inexact_linear_solves = prm.get_bool("Inexact linear solves");
    extrapolate           = prm.get("Predictor") == "extrapolated";
    prm.leave_subsection();
  }

  // Longer than 80 lines on purpose: one declare_entry after another, in
  // the order of the .prm and its documentation, reads as a table.
  void LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry(
        "Type",
        "automatic",
        Patterns::Selection(choice_pattern(solver_names)),
        "'direct': sparse LU (MUMPS through Amesos), robust, fastest for "
        "small problems, memory growing faster than the dofs. 'iterative': "
        "conjugate gradients (GMRES where follower pressure or sliding "
        "friction makes the tangent unsymmetric) preconditioned by "
        "Trilinos ML algebraic multigrid with the rigid-body modes as near "
        "null space; contact enters as constraints on the contact nodes. "
        "'automatic': direct up to 'Direct solver limit' displacement dofs, "
        "iterative above (doc/solver.md gives the measured crossover).");
    prm.declare_entry("Direct solver limit",
                      "50000",
                      Patterns::Integer(0),
                      "'Type = automatic' uses the direct solver up to this "
                      "many displacement dofs (summed over all ranks). "
                      "Unit: 1.");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Patterns::Double(0, 1),
                      "Krylov stopping criterion relative to the right-hand "
                      "side norm. Unit: 1.");
    prm.declare_entry("Maximum iterations",
                      "2000",
                      Patterns::Integer(1),
                      "Krylov iterations before the Newton step counts as "
                      "failed (and the load step is cut back). Unit: 1.");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "ML aggregation drop tolerance. Unit: 1.");
    prm.declare_entry(
        "AMG smoother",
        "automatic",
        Patterns::Selection(choice_pattern(smoother_names)),
        "Smoother on the levels of the ML AMG hierarchy. 'Chebyshev': a "
        "Chebyshev polynomial of the Jacobi-scaled matrix (symmetric, for "
        "CG and GMRES). 'Gauss-Seidel': Gauss-Seidel sweeps, local to each "
        "rank (fewer Krylov iterations than Chebyshev at lower cost on the "
        "nearly incompressible displacement block; not symmetric, so CG "
        "solves take 'symmetric Gauss-Seidel' instead). 'automatic': "
        "Gauss-Seidel under GMRES (block preconditioner, friction), "
        "Chebyshev under CG (doc/benchmarks.md gives the measurements).");
    prm.declare_entry("AMG smoother sweeps",
                      "0",
                      Patterns::Integer(0, 10),
                      "Degree of the Chebyshev smoother, or Gauss-Seidel "
                      "sweeps before and after each coarse correction; 0: "
                      "2 for Chebyshev, 1 for Gauss-Seidel. Unit: 1.");
    prm.declare_entry(
        "Reuse symbolic factorization",
        "true",
        Patterns::Bool(),
        "Direct solver: compute MUMPS' fill-reducing ordering and symbolic "
        "factorisation at the first Newton iteration of a load step and "
        "redo only the numeric factorisation in the iterations that follow. "
        "'false' redoes both at every Newton iteration (for comparison).");
    prm.declare_entry(
        "Block preconditioner",
        "true",
        Patterns::Bool(),
        "Iterative solver with the mixed u-p-J formulation: build the AMG on "
        "the displacement block alone and correct for the volumetric "
        "(pressure) coupling with an element-wise Schur complement (the "
        "block triangular preconditioner of the saddle point system), so "
        "that the iterations do not grow as Poisson's ratio approaches 0.5. "
        "'false': AMG on the condensed tangent (iterations grow with "
        "kappa/mu). No effect on the direct solver or the displacement "
        "formulation.");
    prm.declare_entry(
        "Block preconditioner augmentation",
        "3",
        Patterns::Double(0, 1000),
        "Block preconditioner: the augmented Lagrangian weight gamma. The "
        "displacement block on which the AMG is built takes "
        "w G^T M^-1 G (w = gamma times the material's initial shear "
        "modulus, at most half the volumetric stiffness U'' of the cell) "
        "and the pressure coupling gives it back, so the Newton step is "
        "unchanged. It makes the pressure Schur complement nearly that of "
        "the mass matrix and the iterations flat under mesh refinement; "
        "0 switches it off (iterations then grow with the mesh, "
        "doc/solver.md). Unit: 1 (a multiple of the shear modulus).");
    prm.declare_entry(
        "Reuse AMG",
        "true",
        Patterns::Bool(),
        "Iterative solver: keep the AMG hierarchy (aggregates, coarse "
        "matrices, smoothers) over Newton iterations and load steps while "
        "the matrix keeps its sparsity pattern; the finest level applies "
        "the current matrix. It is rebuilt once the iterations a solve "
        "needs beyond the first solve's with it took longer than building "
        "it did, and a solve that fails with a kept hierarchy is repeated "
        "with a new one. Measured (doc/benchmarks.md): linear solves 1.2-1.3 "
        "times faster with the block preconditioner (the 108k-dof block at "
        "nu = 0.4999, Hertz contact at nu = 0.45) and on the frictional "
        "sphere_squeeze grasp; 1.25 times slower under CG on the condensed "
        "tangent of the 108k-dof Hertz problem. 'false' builds it at every "
        "Newton iteration.");
    prm.leave_subsection();
  }

  void LinearSolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type                         = lookup_choice(solver_names, prm.get("Type"));
    direct_limit                 = prm.get_integer("Direct solver limit");
    relative_tolerance           = prm.get_double("Relative tolerance");
    max_iterations               = prm.get_integer("Maximum iterations");
    aggregation_threshold        = prm.get_double("AMG aggregation threshold");
    reuse_symbolic_factorization = prm.get_bool("Reuse symbolic factorization");
    smoother        = lookup_choice(smoother_names, prm.get("AMG smoother"));
    smoother_sweeps = prm.get_integer("AMG smoother sweeps");
    block_preconditioner = prm.get_bool("Block preconditioner");
    reuse_amg            = prm.get_bool("Reuse AMG");
    block_augmentation   = prm.get_double("Block preconditioner augmentation");
    prm.leave_subsection();
  }

  AmgSmoother LinearSolverParameters::smoother_for(const bool symmetric) const
  {
    switch (smoother)
    {
    case AmgSmoother::automatic:
      return symmetric ? AmgSmoother::chebyshev : AmgSmoother::gauss_seidel;
    case AmgSmoother::gauss_seidel:
      return symmetric ? AmgSmoother::symmetric_gauss_seidel
                       : AmgSmoother::gauss_seidel;
    default:
      return smoother;
    }
  }

  std::string LinearSolverParameters::smoother_name(const AmgSmoother smoother)
  {
    // the parameter's names are ML's
    for (const auto &[name, value] : smoother_names)
      if (value == smoother)
        return name;
    return "Chebyshev";
  }

  unsigned int
  LinearSolverParameters::smoother_sweeps_for(const AmgSmoother resolved) const
  {
    if (smoother_sweeps > 0)
      return smoother_sweeps;
    return resolved == AmgSmoother::chebyshev ? 2 : 1;
  }

  LinearSolverType
  LinearSolverParameters::resolve(const types::global_dof_index n_dofs) const
  {
    if (type != LinearSolverType::automatic)
      return type;
    return n_dofs <= direct_limit ? LinearSolverType::direct
                                  : LinearSolverType::iterative;
  }

  std::string LinearSolverParameters::name(const LinearSolverType type)
  {
    switch (type)
    {
    case LinearSolverType::direct:
      return "direct (MUMPS)";
    case LinearSolverType::iterative:
      return "CG/GMRES + ML AMG";
    default:
      return "automatic";
    }
  }

  void ExplicitParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Explicit dynamics");
    prm.declare_entry("Safety factor",
                      "0.8",
                      Patterns::Double(0, 1),
                      "The time step is this factor times the critical step "
                      "2/omega_max of the current state (omega_max from a "
                      "power iteration on M^-1 K). Unit: 1.");
    prm.declare_entry("Stable step interval",
                      "100",
                      Patterns::Integer(1),
                      "Recompute the critical step every this many steps, "
                      "as the mesh deforms. Unit: 1.");
    prm.declare_entry("Fixed time step",
                      "0",
                      Patterns::Double(0),
                      "If > 0, integrate with this step instead of the "
                      "stable one; a run whose step exceeds the critical "
                      "step is stopped. Unit: s.");
    prm.declare_entry("Mass scaling time step",
                      "0",
                      Patterns::Double(0),
                      "If > 0, add mass to the nodes of the elements whose "
                      "own stable step h/c is below this, so that the step "
                      "reaches it; the added mass is reported in percent. "
                      "Changes the dynamics: only for quasi-static loading. "
                      "Unit: s.");
    prm.declare_entry("Mass damping",
                      "0",
                      Patterns::Double(0),
                      "Mass-proportional damping alpha: a force -alpha M v "
                      "on every node. For quasi-static loading, about the "
                      "lowest natural frequency 2 pi f_1 (critical damping "
                      "of the first mode). Unit: 1/s.");
    prm.declare_entry(
        "Stiffness damping",
        "0",
        Patterns::Double(0, 1),
        "Stiffness-proportional (Rayleigh) damping, as the fraction xi of "
        "critical damping of the mesh's highest frequency omega_max: a "
        "viscous force -beta K v with beta = 2 xi / omega_max = xi times the "
        "critical step (updated with it; with a 'Fixed time step', the "
        "critical step that step stands for), evaluated as beta times the "
        "rate of the internal forces over the step. A mode of frequency "
        "omega is damped by xi omega / omega_max, so it acts on grid-scale "
        "vibration (contact chatter, the node-scale stick-slip of sliding "
        "frictional contact) and hardly on the slow response. The time step "
        "is shortened by the factor sqrt(1 + xi^2) - xi (0.75 at xi = 0.3). "
        "For frictional sliding in explicit runs, 0.3 (doc/contact.md). "
        "Unit: 1.");
    prm.declare_entry("Energy balance limit",
                      "0.05",
                      Patterns::Double(0),
                      "Stop the run (writing the last good state) when the "
                      "integration creates more energy than this, relative "
                      "to the largest energy term: the sign of an unstable "
                      "step (energy lost, e.g. by impact on a rigid body, "
                      "is dissipation and does not stop it) once the "
                      "created energy has stayed above the limit and grown "
                      "for 10 steps in a row, as an instability does (the "
                      "jump of the relative measure at a rigid body's first "
                      "touch, when all energies are near zero, decays at "
                      "once); it acts after the first 2 % of the run "
                      "(before, the energies are too small for a relative "
                      "measure; unstable steps are caught by the checks for "
                      "inverted elements and non-finite values). 0 switches "
                      "the check off (the balance error is still recorded in "
                      "the history). Unit: 1.");
    prm.declare_entry("Force kernel",
                      "vectorized",
                      Patterns::Selection("vectorized|reference"),
                      "Implementation of the internal forces: 'vectorized' "
                      "(explicit SIMD over cells, the fast default) or "
                      "'reference' (deal.II's FEEvaluation, one cell at a "
                      "time). Both give the same forces to round-off; the "
                      "reference is for comparisons and benchmarks.");
    prm.leave_subsection();
  }

  void ExplicitParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Explicit dynamics");
    const CheckedSection section(prm, "Explicit dynamics");
    safety_factor        = section.get_positive("Safety factor", "1");
    stable_step_interval = prm.get_integer("Stable step interval");
    fixed_time_step      = section.get_positive("Fixed time step", "s", true);
    mass_scaling_time_step =
        section.get_positive("Mass scaling time step", "s", true);
    mass_damping      = section.get_positive("Mass damping", "1/s", true);
    stiffness_damping = section.get_positive("Stiffness damping", "1", true);
    energy_balance_limit =
        section.get_positive("Energy balance limit", "1", true);
    vectorized_force_kernel = prm.get("Force kernel") == "vectorized";
    prm.leave_subsection();
  }

  void LimitParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Run limits");
    prm.declare_entry(
        "Check run size",
        "true",
        Patterns::Bool(),
        "Before a run starts, estimate its memory (from the number of cells "
        "after refinement, the element and the solver) and its number of "
        "load steps or recorded states, and refuse it if the memory exceeds "
        "that of the machines its MPI ranks run on, or the steps exceed "
        "'Maximum steps' (explicit runs: the integration steps exceed "
        "'Maximum explicit steps'). Set to false to run it anyway.");
    prm.declare_entry("Maximum steps",
                      "1000000",
                      Patterns::Integer(1),
                      "Largest number of quasi-static load steps, or of "
                      "recorded states of an explicit run, that 'Time/End "
                      "time' / 'Time/Time step' may imply. Unit: 1.");
    prm.declare_entry("Maximum explicit steps",
                      "1e8",
                      Patterns::Double(1),
                      "Largest number of explicit integration steps (of the "
                      "stable or fixed step) to reach 'Time/End time'; 1e8 "
                      "steps of 200k unknowns take about 10 days on one core. "
                      "Unit: 1.");
    prm.leave_subsection();
  }

  void LimitParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Run limits");
    check_size             = prm.get_bool("Check run size");
    maximum_steps          = prm.get_integer("Maximum steps");
    maximum_explicit_steps = prm.get_double("Maximum explicit steps");
    prm.leave_subsection();
  }

  void
  SolverParameters::declare_parameters(ParameterHandler        &prm,
                                       const IntegratorChoices &integrators)
  {
    DiscretizationParameters::declare_parameters(prm);
    TimeParameters::declare_parameters(prm, integrators);
    NewtonParameters::declare_parameters(prm);
    LinearSolverParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
    CheckpointParameters::declare_parameters(prm);
    ExplicitParameters::declare_parameters(prm);
    LimitParameters::declare_parameters(prm);
  }

  void SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    discretization.parse_parameters(prm);
    time.parse_parameters(prm);
    newton.parse_parameters(prm);
    linear_solver.parse_parameters(prm);
    output.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    explicit_dynamics.parse_parameters(prm);
    limits.parse_parameters(prm);
  }
} // namespace softgrasp
