#ifndef softgrasp_mechanics_solver_parameters_h
#define softgrasp_mechanics_solver_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>
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

  /// Linear solver of each Newton step.
  enum class LinearSolverType
  {
    direct,   ///< sparse direct (Amesos MUMPS); for small problems
    iterative ///< CG (GMRES with follower loads) + Trilinos ML AMG
  };

  /// Finite element discretisation ("Finite element" subsection).
  struct DiscretizationParameters
  {
    unsigned int degree      = 1; ///< polynomial degree of u, 1 or 2
    Formulation  formulation = Formulation::displacement;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Load/time stepping ("Time" subsection).
  struct TimeParameters
  {
    double       end_time      = 1.0;  ///< s
    double       step_size     = 0.1;  ///< nominal step, s
    double       minimum_step  = 1e-6; ///< smallest step after cut-backs, s
    unsigned int max_cut_backs = 8; ///< halvings of one step before giving up

    static void declare_parameters(dealii::ParameterHandler &prm);
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

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Linear solver ("Linear solver" subsection).
  struct LinearSolverParameters
  {
    LinearSolverType type                  = LinearSolverType::iterative;
    double           relative_tolerance    = 1e-8; ///< of |rhs|; 1
    unsigned int     max_iterations        = 2000;
    double           aggregation_threshold = 1e-4; ///< ML AMG; 1
    unsigned int     smoother_sweeps       = 2;    ///< ML AMG Chebyshev degree

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
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

  /// All solver settings; the materials, mesh and loads are read elsewhere.
  struct SolverParameters
  {
    DiscretizationParameters discretization;
    TimeParameters           time;
    NewtonParameters         newton;
    LinearSolverParameters   linear_solver;
    OutputParameters         output;
    CheckpointParameters     checkpoint;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace softgrasp

#endif
