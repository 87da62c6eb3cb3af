#ifndef softgrasp_mechanics_solver_parameters_h
#define softgrasp_mechanics_solver_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <softgrasp/base/run_directory.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /// How the volumetric response is discretised.
  enum class Formulation
  {
    /// Pure displacement; locks for nearly incompressible materials.
    displacement,
    /// Three-field Hu-Washizu u-p-J with element-wise discontinuous
    /// pressure and dilatation of degree k-1 (Q1-P0, Q2-P1), condensed
    /// on each element (as in deal.II step-44), so the global system holds
    /// the displacement only.
    mixed_upJ
  };

  /// Degree of the element-wise pressure and dilatation of 'mixed u-p-J'
  /// ("Finite element/Pressure degree").
  enum class PressureDegree
  {
    below_displacement, ///< k - 1: Q1-P0, Q2-P1 (the default)
    constant            ///< 0: Q1-P0, Q2-P0 (one pressure per element)
  };

  /// Linear solver of each Newton step.
  enum class LinearSolverType
  {
    direct,    ///< sparse direct (Amesos MUMPS); for small problems
    iterative, ///< CG (GMRES where unsymmetric) + Trilinos ML AMG
    automatic  ///< direct up to a number of dofs, iterative above
  };

  /// Smoother of the ML AMG hierarchy ("Linear solver/AMG smoother").
  enum class AmgSmoother
  {
    automatic,             ///< Gauss-Seidel under GMRES, Chebyshev under CG
    chebyshev,             ///< Chebyshev polynomial (symmetric)
    gauss_seidel,          ///< Gauss-Seidel (symmetric Gauss-Seidel under CG)
    symmetric_gauss_seidel ///< forward and backward Gauss-Seidel
  };

  /// The time integrators a program offers: (name, description) pairs,
  /// e.g. the registered time steppers; TimeParameters' default
  /// (quasi-static) is the default if offered, else the first.
  using IntegratorChoices = std::vector<std::pair<std::string, std::string>>;

  /// Finite element discretisation ("Finite element" subsection).
  struct DiscretizationParameters
  {
    unsigned int   degree      = 1; ///< polynomial degree of u, 1 or 2
    Formulation    formulation = Formulation::displacement;
    PressureDegree pressure    = PressureDegree::below_displacement;

    /// The degree of the discontinuous pressure and dilatation of the
    /// mixed formulation (0 or 1); the same in every solver.
    unsigned int pressure_degree() const
    {
      return pressure == PressureDegree::constant ? 0 : degree - 1;
    }
    /// The element's name, e.g. "Q2-P1 u-p-J" or "Q1 displacement".
    std::string element_name() const;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// One phase of the loading with its own stepping (e.g. an indentation,
  /// then a pull): from the previous phase's end (or 0) to @p end.
  struct TimePhase
  {
    double end     = 1.0;  ///< s
    double step    = 0.1;  ///< nominal step or record interval, s
    double minimum = 1e-6; ///< smallest step after cut-backs, s
  };

  /// Load/time stepping ("Time" subsection).
  struct TimeParameters
  {
    /// 'Time/Integrator': the name of a registered time stepper
    std::string integrator = "quasi-static";
    double      end_time   = 1.0; ///< s
    /// nominal load step (quasi-static) or record interval (explicit), s
    double       step_size     = 0.1;
    double       minimum_step  = 1e-6; ///< smallest step after cut-backs, s
    unsigned int max_cut_backs = 8; ///< halvings of one step before giving up
    /// 'Time/Phases'; empty: one phase (end_time, step_size, minimum_step)
    std::vector<TimePhase> phases;

    /// The phases of the run (the one-phase default if none are given);
    /// throws an InputError if given phases do not end at end_time.
    std::vector<TimePhase> phase_list() const;
    /// The phase that the step starting at @p time belongs to.
    TimePhase phase_at(const double time) const;
    /// The start of the phase that the step starting at @p time belongs to.
    double phase_begin(const double time) const;

    static void declare_parameters(dealii::ParameterHandler &prm,
                                   const IntegratorChoices  &integrators);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Newton-Raphson iteration ("Newton" subsection).
  struct NewtonParameters
  {
    unsigned int max_iterations = 15;
    /// converged when |r| <= max(relative * force scale, absolute); 1
    double relative_tolerance = 1e-8;
    double absolute_tolerance = 1e-12; ///< N (force per unit thickness in 2D)
    /// also converged when max |du| <= this times the domain size; 1
    double       increment_tolerance   = 1e-12;
    bool         line_search           = true;
    unsigned int max_line_search_steps = 6; ///< step halvings
    /// iterative linear solves only as tight as Newton's progress needs
    bool inexact_linear_solves = true;
    /// a minimisation starts from the last converged state extrapolated
    /// in time (where that lowers its potential)
    bool extrapolate = true;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Linear solver ("Linear solver" subsection).
  struct LinearSolverParameters
  {
    LinearSolverType type = LinearSolverType::automatic;
    /// automatic: the direct solver up to this many displacement dofs
    dealii::types::global_dof_index direct_limit       = 50000;
    double                          relative_tolerance = 1e-8; ///< of |rhs|; 1
    unsigned int                    max_iterations     = 2000;
    double                          aggregation_threshold = 1e-4; ///< ML AMG; 1
    AmgSmoother                     smoother = AmgSmoother::automatic;
    /// ML AMG: Chebyshev degree or Gauss-Seidel sweeps; 0: the smoother's
    /// own (2 and 1)
    unsigned int smoother_sweeps = 0;
    /// direct: keep MUMPS' ordering and symbolic factorisation over the
    /// Newton iterations of a load step (only the numeric one is redone)
    bool reuse_symbolic_factorization = true;
    /// iterative, mixed u-p-J: AMG on the displacement block with an
    /// element-wise pressure Schur complement (VolumetricOperator) instead
    /// of AMG on the condensed tangent
    bool block_preconditioner = true;
    /// block preconditioner: augmented Lagrangian weight of the
    /// displacement block, in units of the initial shear modulus; 1
    double block_augmentation = 3;
    /// iterative: keep the AMG hierarchy over Newton iterations and load
    /// steps while it serves (LinearSolver)
    bool reuse_amg = true;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);

    /// The solver used for a system of @p n_dofs unknowns (direct or
    /// iterative; automatic resolved by direct_limit).
    LinearSolverType
    resolve(const dealii::types::global_dof_index n_dofs) const;
    /// The smoother for a CG (@p symmetric) or a GMRES solve: never
    /// automatic, and symmetric for CG.
    AmgSmoother smoother_for(const bool symmetric) const;
    /// The name of @p smoother (also ML's "smoother: type").
    static std::string smoother_name(const AmgSmoother smoother);
    /// Smoother sweeps (Chebyshev degree) of @p resolved.
    unsigned int smoother_sweeps_for(const AmgSmoother resolved) const;
    /// Its name for the run summary, e.g. "CG/GMRES + ML AMG".
    static std::string name(const LinearSolverType type);
  };

  /// Files and terminal output ("Output" subsection).
  struct OutputParameters
  {
    std::string  directory    = "output"; ///< created if missing
    std::string  base_name    = "solution";
    unsigned int vtu_interval = 1; ///< every n-th step; 0 = final only
    /// reference points (m) whose displacement goes into the history CSV
    std::vector<std::vector<double>> monitor_points;
    bool                             verbose = true; ///< Newton details
    /// what a new run does with an earlier run's results in the directory
    ExistingResults existing_results = ExistingResults::move_aside;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Checkpoint/restart ("Checkpoint" subsection).
  struct CheckpointParameters
  {
    unsigned int interval = 0;     ///< every n-th step; 0 = never
    bool         resume   = false; ///< restart from the last checkpoint

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Explicit central-difference integration ("Explicit dynamics").
  struct ExplicitParameters
  {
    /// time step = factor x the critical step 2/omega_max; 1
    double safety_factor = 0.8;
    /// recompute the critical step every n steps (as the mesh deforms); 1
    unsigned int stable_step_interval = 100;
    /// > 0: fixed time step, s (checked against the critical step)
    double fixed_time_step = 0;
    /// > 0: scale nodal masses so the step is at least this, s
    double mass_scaling_time_step = 0;
    /// mass-proportional damping alpha, 1/s
    double mass_damping = 0;
    /// stiffness-proportional damping: the fraction xi of critical damping
    /// at the highest frequency (beta = xi x the critical step); 1
    double stiffness_damping = 0;
    /// stop when the relative energy balance error exceeds this; 1
    double energy_balance_limit = 0.05;
    /// internal forces by the vectorised kernel (true) or the reference
    /// FEEvaluation kernel (false); same forces to round-off
    bool vectorized_force_kernel = true;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// All solver settings; the materials, mesh and loads are read elsewhere.
  /// Refusal of runs too large for the machines ("Run limits").
  struct LimitParameters
  {
    /// refuse runs estimated to need more memory than the machines have,
    /// or more than maximum_steps load steps or recorded states
    bool         check_size    = true;
    unsigned int maximum_steps = 1000000; ///< 1
    /// largest number of explicit integration steps (stable step); 1
    double maximum_explicit_steps = 1e8;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  struct SolverParameters
  {
    DiscretizationParameters discretization;
    TimeParameters           time;
    NewtonParameters         newton;
    LinearSolverParameters   linear_solver;
    OutputParameters         output;
    CheckpointParameters     checkpoint;
    ExplicitParameters       explicit_dynamics;
    LimitParameters          limits;

    /// @p integrators: the valid values of 'Time/Integrator'.
    static void declare_parameters(dealii::ParameterHandler &prm,
                                   const IntegratorChoices  &integrators);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace softgrasp

#endif
