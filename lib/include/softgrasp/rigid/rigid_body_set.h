#ifndef softgrasp_rigid_rigid_body_set_h
#define softgrasp_rigid_rigid_body_set_h

#include <deal.II/base/parameter_handler.h>
#include <optional>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/rigid/rigid_body.h>
#include <string>
#include <vector>

namespace softgrasp
{
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
     * MuJoCo's equilibrium contact normal). Without it the mean normal of
     * the geom's contact patch is used.
     */
    void set_reference_normal(const unsigned int     b,
                              const unsigned int     g,
                              const Eigen::Vector3d &normal);

    /// The reference normal of a geom, if one was given.
    std::optional<Eigen::Vector3d> reference_normal(const unsigned int b,
                                                    const unsigned int g) const;

    const std::vector<RigidBody> &bodies() const;
    bool                          empty() const;

    /// "body/geom" for output tables.
    std::string geom_label(const unsigned int b, const unsigned int g) const;

  private:
    std::vector<RigidBody>                                   body_list;
    std::vector<std::vector<std::optional<Eigen::Vector3d>>> normals;
  };

  /// Read a pose trajectory CSV (header t,x,y,z,qw,qx,qy,qz); errors name
  /// the file, the line and the fix.
  PoseTrajectory read_trajectory_file(const std::string &filename);

  /// Parse "t: x, y, z, qw, qx, qy, qz; ..." (@p source names it in errors).
  PoseTrajectory parse_trajectory(const std::string &text,
                                  const std::string &source);
} // namespace softgrasp

#endif
