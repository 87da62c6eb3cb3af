#ifndef softgrasp_rigid_rigid_body_set_h
#define softgrasp_rigid_rigid_body_set_h

#include <deal.II/base/parameter_handler.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/rigid/rigid_body.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * How the contact force on a geom is split into its normal part
   * (n n^T) F and its lateral part (I - n n^T) F: by which direction n.
   */
  struct ReferenceNormal
  {
    enum class Kind
    {
      /// The area-weighted mean normal of the geom's contact patch, with
      /// the components across symmetry planes that the patch touches
      /// removed (the mean normal of the whole, mirrored patch).
      patch_mean,
      /// A fixed world direction (given, or MuJoCo's equilibrium contact
      /// normal from a kinematics file).
      world,
      /// A direction fixed in the geom's frame, turning with the geom.
      geom_frame
    };
    Kind            kind      = Kind::patch_mean;
    Eigen::Vector3d direction = Eigen::Vector3d::Zero(); ///< unit

    /// Parse the entry 'Reference normal' (@p path names it in errors):
    /// "" or "patch mean", "x, y, z" (world) or "geom: x, y, z".
    static ReferenceNormal parse(const std::string &text,
                                 const std::string &path);
  };

  /**
   * The rigid contactors of a run (fingers, indenters, plates), read from
   * the subsection "Rigid bodies" of a .prm file or added in code.
   *
   * @code
   * subsection Rigid bodies
   *   set Names = indenter
   *   subsection Body indenter
   *     set Geom names = ball
   *     set Trajectory = 0: 0, 0, 0.0101, 1, 0, 0, 0; 1: 0, 0, 0.0095, 1, 0, 0,
   * 0 subsection Geom ball set Type = sphere set Size = 0.01 end end end
   * @endcode
   *
   * A body has geoms (MuJoCo's types; a geom is what a force history is
   * reported for, e.g. one finger link) at poses in the body frame, and a
   * pose trajectory given as samples "t: x, y, z, qw, qx, qy, qz; ..." in the
   * .prm or as a CSV file with the columns t,x,y,z,qw,qx,qy,qz.
   */
  class RigidBodySet
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);
    static void add_passes(ParameterReader &reader);
    void        parse_parameters(dealii::ParameterHandler &prm);

    /// Add a body built in code; returns its index.
    unsigned int add_body(const RigidBody &body);

    /**
     * Fix the reference normal (world frame, unit) used to split the force
     * on geom @p g of body @p b into normal and lateral parts (e.g.
     * MuJoCo's equilibrium contact normal): ReferenceNormal::Kind::world.
     */
    void set_reference_normal(const unsigned int     b,
                              const unsigned int     g,
                              const Eigen::Vector3d &normal);

    /// How the force on geom @p g of body @p b is split.
    const ReferenceNormal &reference_normal(const unsigned int b,
                                            const unsigned int g) const;

    const std::vector<RigidBody> &bodies() const;
    bool                          empty() const;

    /// "body/geom" for output tables.
    std::string geom_label(const unsigned int b, const unsigned int g) const;

  private:
    std::vector<RigidBody>                    body_list;
    std::vector<std::vector<ReferenceNormal>> normals;
  };

  /// Read a pose trajectory CSV (header t,x,y,z,qw,qx,qy,qz); errors name
  /// the file, the line and the fix.
  PoseTrajectory read_trajectory_file(const std::string &filename);

  /// Parse "t: x, y, z, qw, qx, qy, qz; ..." (@p source names it in errors).
  PoseTrajectory parse_trajectory(const std::string &text,
                                  const std::string &source);
} // namespace softgrasp

#endif
