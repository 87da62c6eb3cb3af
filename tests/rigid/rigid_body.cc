// A rigid body of two capsule geoms (a proximal and a distal finger link)
// moved by a quaternion trajectory gives at every time the same distances,
// normals and closest points as the same geometry placed directly at the
// interpolated pose; the nearest geom is selected; geom poses compose
// body and local poses.
#include "../tests.h"

#include <random>
#include <softgrasp/rigid/rigid_body.h>

using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog(8);
  std::shared_ptr<const Shape> link =
      create_shape("capsule", {0.01, 0.02, 0}, "link");
  Pose proximal, distal;
  proximal.position = Eigen::Vector3d(0, 0, 0.02);
  distal.position   = Eigen::Vector3d(0, 0, 0.06);
  distal.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));

  Pose start, end;
  end.position    = Eigen::Vector3d(0.01, -0.02, 0.005);
  end.orientation = Eigen::Quaterniond(
      Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 2, 3).normalized()));
  RigidBody moving("finger", PoseTrajectory({0.0, 1.0}, {start, end}, "test"));
  moving.add_geom("proximal", link, proximal);
  moving.add_geom("distal", link, distal);

  std::mt19937                           rng(3);
  std::uniform_real_distribution<double> uniform(-0.05, 0.08);
  double                                 worst = 0;
  for (const double t : {0.0, 0.25, 0.7, 1.0})
  {
    RigidBody placed("placed", PoseTrajectory(moving.trajectory().pose(t)));
    placed.add_geom("proximal", link, proximal);
    placed.add_geom("distal", link, distal);
    for (unsigned int i = 0; i < 500; ++i)
    {
      const Eigen::Vector3d x(uniform(rng), uniform(rng), uniform(rng));
      const auto            a = moving.closest_geom(x, t);
      const auto b = placed.closest_geom(x, 123.0); // static: any time
      SG_CHECK(a.geom == b.geom, "same nearest geom");
      worst = std::max({worst,
                        std::abs(a.distance - b.distance),
                        (a.normal - b.normal).norm() * 0.01,
                        (a.closest - b.closest).norm()});
      // the world query is itself an exact distance field
      worst = std::max(worst, (x - a.closest - a.distance * a.normal).norm());
    }
  }
  SG_CHECK(worst < 1e-14, "moving body equals directly placed body");
  dealii::deallog << "moving body = placed body at 4 times x 500 points"
                  << std::endl;

  // the tip of the distal link at t = 0: local (0, 0, 0.02 + 0.01) rotated
  // by 0.3 rad about x, shifted to z = 0.06
  const Eigen::Vector3d tip(
      0, -0.03 * std::sin(0.3), 0.06 + 0.03 * std::cos(0.3));
  const auto q = moving.closest_geom(
      tip + 0.004 * (tip - Eigen::Vector3d(0,
                                           -0.02 * std::sin(0.3),
                                           0.06 + 0.02 * std::cos(0.3)))
                        .normalized(),
      0.0);
  dealii::deallog << "nearest geom to the distal tip: "
                  << moving.geoms()[q.geom].name << ", d = " << q.distance
                  << std::endl;
  SG_CHECK(q.geom == 1 && std::abs(q.distance - 0.004) < 1e-14,
           "distal tip distance");
}
