#ifndef softgrasp_grasp_indentation_study_h
#define softgrasp_grasp_indentation_study_h

#include <deal.II/base/parameter_handler.h>
#include <mpi.h>
#include <softgrasp/io/history_writer.h>
#include <softgrasp/io/kinematics_file.h>
#include <string>

namespace softgrasp
{
  template <int dim> class MechanicsSolver;

  /**
   * The finite element half of a grasp study: from the equilibrium grasp a
   * rigid-body simulator recorded (a kinematics file), drive the same rigid
   * finger links further into the tissue along the recorded "indentation"
   * phase, until its end or until a target normal force on a chosen link.
   *
   * The run is a MechanicsSolver<3> ('Time/Integrator': quasi-static or
   * explicit dynamic) on the .prm's mesh, materials and
   * contact settings; the study sets
   *  - the rigid bodies: every body of the file with geoms (capsules stay
   *    capsules), moving on the recorded poses, with the equilibrium contact
   *    normals as reference normals for the normal/lateral split;
   *  - "Time/End time" to the phase's duration (time 0 = equilibrium);
   *  - "Mesh/Ball/Center" to the grasped object's recorded position, if the
   *    mesh is a generated ball.
   *
   * Afterwards it writes <base>_links.csv: per step the closure (rad) and,
   * per link, the finite element normal, lateral and friction-only force
   * next to the rigid simulator's normal and lateral force at the same
   * closure; and (with gnuplot) <base>_forces.png, force against closure
   * per link, and <base>_picture.png, the indented body coloured by e_max
   * with the link geoms drawn. SI units throughout.
   */
  class IndentationStudy
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);

    IndentationStudy(MPI_Comm comm, dealii::ParameterHandler &prm);

    /// Run on @p kinematics (read from the file, or just computed).
    void run(const KinematicsData &kinematics);

    /// The kinematics file named in the .prm (relative to @p directory).
    std::string kinematics_file(const std::string &directory) const;

    /// True if the .prm asks to run the rigid-body simulator first.
    bool rigid_stage_requested() const
    {
      return run_rigid;
    }

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

  private:
    void write_link_table(const MechanicsSolver<3> &solver,
                          const KinematicsData     &phase);

    MPI_Comm                  comm;
    dealii::ParameterHandler &prm;
    std::string               file_name;
    std::string               target_link;
    double                    target_force  = 0; ///< N; 0: none
    bool                      make_pictures = true;
    bool                      run_rigid     = true;
    double                    extra_angle   = 0;
    Summary                   result;
    HistoryWriter             table;
  };
} // namespace softgrasp

#endif
