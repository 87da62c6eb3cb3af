#ifndef softgrasp_grasp_indentation_study_h
#define softgrasp_grasp_indentation_study_h

#include <deal.II/base/parameter_handler.h>
#include <mpi.h>
#include <softgrasp/grasp/link_force_history.h>
#include <softgrasp/io/history_writer.h>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/postprocess/tissue_injury.h>
#include <softgrasp/solvers/solver_inputs.h>
#include <string>
#include <vector>

namespace softgrasp
{
  template <int dim> class Simulation;

  /// The settings of a grasp study's finite element stage ("Indentation
  /// study" subsection), parsed once.
  struct GraspStudyParameters
  {
    /// Where the tissue mesh goes: at the object body's recorded pose
    /// (position and orientation), or at its position only (a ball whose
    /// mesh stays aligned with the world axes).
    enum class Placement
    {
      pose,
      position
    };

    std::string              kinematics_file = "kinematics.h5";
    bool                     run_rigid_stage = true;
    std::string              object_body     = "object";
    std::vector<std::string> phases          = {"indentation"};
    Placement                placement       = Placement::pose;
    std::string              target_link;      ///< body/geom; empty: none
    double                   target_force = 0; ///< N; 0: none
    bool                     pictures     = true;
    InjuryThresholds         injury; ///< 'Injury assessment'

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The finite element half of a grasp study: from the grasp a rigid-body
   * simulator recorded (a kinematics file), drive the same rigid finger
   * links into the tissue along the recorded phases ('Phases', in order,
   * e.g. "indentation, pull"), until their end or until a target normal
   * force on a chosen link.
   *
   * The run is a Simulation<3> ('Time/Integrator': quasi-static or
   * explicit dynamic) built from typed SolverInputs, parsed once from the
   * .prm; the study sets, in those typed values (never in the .prm):
   *  - the rigid bodies: every body of the file with geoms, moving on the
   *    recorded poses, with the equilibrium contact normals as reference
   *    normals for the normal/lateral split;
   *  - the end time: the phases' duration (time 0 = start of the first);
   *  - the tissue mesh's placement at the object body's recorded pose
   *    (set_up_tissue(), which a study may override, e.g. to supply its
   *    own mesh or fixed boundaries).
   *
   * Afterwards it writes <base>_links.csv: per step the closure (rad) and,
   * per link, the finite element normal, lateral and friction-only force
   * next to the rigid simulator's normal and lateral force at the same
   * time; and (with gnuplot) <base>_forces.png and <base>_picture.png;
   * and the per-tissue injury assessment of the final state
   * (TissueInjury: <base>_injury.csv, <base>_skin_pressure.csv).
   * A study adds its own output in postprocess(). SI units throughout.
   */
  class IndentationStudy
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);

    /// Parse the study's and the solver's settings from @p prm.
    IndentationStudy(MPI_Comm comm, dealii::ParameterHandler &prm);
    virtual ~IndentationStudy() = default;

    /// Run on @p kinematics (read from the file, or just computed).
    void run(const KinematicsData &kinematics);

    /// The kinematics file named in the .prm (relative to @p directory).
    std::string kinematics_file(const std::string &directory) const;

    /// True if the .prm asks to run the rigid-body simulator first.
    bool rigid_stage_requested() const
    {
      return parameters.run_rigid_stage;
    }

    /**
     * The MuJoCo scene of the rigid stage, from the .prm's @p scene_file:
     * that file itself, or (a study that builds its scene from its tissue's
     * geometry) a scene written into @p directory. Called on rank 0.
     */
    virtual std::string rigid_scene(const std::string &scene_file,
                                    const std::string &directory) const;

    /// Results of the last run() (rank 0 and all ranks).
    struct Summary
    {
      double       closure     = 0; ///< rad reached
      bool         target_met  = false;
      unsigned int steps       = 0;
      double       balance     = 0;       ///< |sum F_links - R| / max |F_link|
      double       penetration = 0;       ///< deepest nodal gap violation (m)
      std::vector<std::string> links;     ///< body/geom in contact
      std::vector<double>      normal_fe; ///< N, final, per link
      std::vector<double>      normal_rigid; ///< N, MuJoCo, same closure
    };
    const Summary &summary() const;

    /// The side-by-side table (FE and rigid simulator) of the last run.
    const HistoryWriter &link_table() const;

    /// The finite element force history of every link of the last run.
    const std::vector<LinkForceHistory> &link_forces() const;

    /// The injury assessment of the last run's final state.
    const TissueInjury<3> &injury() const
    {
      return injury_assessment;
    }

    /// The typed solver inputs parsed from the .prm.
    const SolverInputs<3> &inputs() const
    {
      return solver_inputs;
    }

    /**
     * The typed solver inputs of a run over the recorded samples @p cut
     * (time 0 = its first sample): the rigid bodies moving on them, the
     * end time, the tissue placed at the object body's first pose, and the
     * placement as a resume setting.
     */
    SolverInputs<3> inputs_for(const KinematicsData &cut) const;

    /// The (body, geom) indices of link @p label ("body/geom") in
    /// @p bodies; an InputError naming the entry @p entry and the links.
    static std::pair<unsigned int, unsigned int>
    link_index(const RigidBodySet &bodies,
               const std::string  &label,
               const std::string  &entry);

    /// The last recorded state of a run: how well the link forces balance
    /// the supports' reactions (|sum F_links - R| / max |F_link|) and the
    /// deepest nodal penetration of a link (m). Collective.
    struct StateCheck
    {
      double balance     = 0;
      double penetration = 0;
    };
    StateCheck final_state_check(const Simulation<3> &solver) const;

  protected:
    /**
     * Put the tissue into @p inputs for a run that starts at the recorded
     * pose @p object of the grasped body: by default the .prm's mesh,
     * placed at that pose ('Tissue placement'). Override to supply another
     * mesh generator, boundary conditions or materials.
     */
    virtual void set_up_tissue(SolverInputs<3> &inputs,
                               const Pose      &object) const;

    /// Place the tissue: the mesh and the materials' fibre direction
    /// fields, both given in the tissue's own frame.
    static void place_tissue(SolverInputs<3>    &inputs,
                             const Placement<3> &placement);

    /// Study-specific output after the run (all ranks, collective).
    virtual void postprocess(const Simulation<3>  &solver,
                             const KinematicsData &phases);

    MPI_Comm communicator() const
    {
      return comm;
    }
    const GraspStudyParameters &study_parameters() const
    {
      return parameters;
    }

  private:
    void summarise(const Simulation<3> &solver, const KinematicsData &phases);
    void write_link_table(const Simulation<3>  &solver,
                          const KinematicsData &phases);
    /// The links that touch in either model (their names into result):
    /// their finite element and MuJoCo histories.
    std::pair<std::vector<const LinkForceHistory *>,
              std::vector<const KinematicsData::LinkHistory *>>
    touching_links(const KinematicsData &phases);
    /// The forces on the links, finite elements against MuJoCo (rank 0).
    void print_links() const;
    /// Assess the final state (all ranks); write and print it on rank 0.
    void assess_injury(const Simulation<3> &solver);

    MPI_Comm             comm;
    GraspStudyParameters parameters;
    SolverInputs<3>      solver_inputs;
    double               extra_angle = 0;
    /// The unit of extra_angle: rad (hinge fingers) or m (slide fingers).
    std::string                   closure_unit = "rad";
    Summary                       result;
    HistoryWriter                 table;
    std::vector<LinkForceHistory> fe_links;
    TissueInjury<3>               injury_assessment;
  };
} // namespace softgrasp

#endif
