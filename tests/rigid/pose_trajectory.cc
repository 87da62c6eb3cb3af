// Pose trajectories: linear interpolation of positions, slerp of
// orientations (a quarter turn about z interpolates to an eighth turn at
// mid-time; the shorter arc is taken for q and -q), clamping outside the
// samples, and clear errors for bad samples (non-increasing or NaN times,
// zero or NaN quaternions, mismatched lengths).
#include "../tests.h"

#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/pose_trajectory.h>

using namespace softgrasp;

int
main()
{
  softgrasp_tests::initlog(8);
  const double pi = M_PI;
  Pose         a, b;
  b.position = Eigen::Vector3d(0.1, 0, -0.2);
  b.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(pi / 2, Eigen::Vector3d::UnitZ()));
  const PoseTrajectory trajectory({0.0, 2.0}, {a, b}, "test");

  const Pose              mid = trajectory.pose(1.0);
  const Eigen::AngleAxisd rotation(mid.orientation);
  dealii::deallog << "t = 1: position (" << mid.position.transpose()
                  << "), rotation " << rotation.angle() * 180 / pi
                  << " deg about (" << rotation.axis().transpose() << ")"
                  << std::endl;
  SG_CHECK((mid.position - Eigen::Vector3d(0.05, 0, -0.1)).norm() < 1e-15,
           "lerp");
  SG_CHECK(std::abs(rotation.angle() - pi / 4) < 1e-14, "slerp angle");
  SG_CHECK((mid.to_world(Eigen::Vector3d::UnitX()) - mid.position -
            Eigen::Vector3d(std::sqrt(0.5), std::sqrt(0.5), 0))
                   .norm() < 1e-14,
           "rotated axis");
  SG_CHECK((mid.to_local(mid.to_world(Eigen::Vector3d(1, 2, 3))) -
            Eigen::Vector3d(1, 2, 3))
                   .norm() < 1e-14,
           "to_local inverts to_world");
  SG_CHECK((trajectory.pose(-1).position - a.position).norm() == 0 &&
               (trajectory.pose(5).position - b.position).norm() == 0,
           "constant outside the samples");

  // -q is the same orientation: the shorter arc must still be 45 degrees
  Pose c = b;
  c.orientation.coeffs() *= -1;
  const Eigen::AngleAxisd short_arc(
      PoseTrajectory({0.0, 2.0}, {a, c}, "test").pose(1.0).orientation);
  SG_CHECK(std::abs(std::abs(short_arc.angle()) - pi / 4) < 1e-14 ||
               std::abs(std::abs(short_arc.angle()) - (2 * pi - pi / 4)) <
                   1e-14,
           "slerp takes the shorter arc");
  dealii::deallog << "q and -q give the same 45 deg midpoint" << std::endl;

  Pose zero;
  zero.orientation.coeffs().setZero();
  Pose nan_pose;
  nan_pose.position[1] = NAN;
  const std::vector<std::pair<std::vector<double>, std::vector<Pose>>> bad = {
      {{0.0, 1.0, 1.0}, {a, b, a}},
      {{0.0, NAN}, {a, b}},
      {{0.0, 1.0}, {a, zero}},
      {{0.0, 1.0}, {nan_pose, b}},
      {{0.0, 1.0}, {a}}};
  for (const auto &[times, poses] : bad)
  {
    try
    {
      PoseTrajectory(times, poses, "the test file");
      SG_CHECK(false, "a bad trajectory must be rejected");
    }
    catch (const InputError &e)
    {
      const std::string message = e.what();
      SG_CHECK(message.find("sample") != std::string::npos &&
                   message.find("the test file") != std::string::npos,
               "the message names the source and the sample");
      dealii::deallog << message.substr(0, message.find(". Fix")) << std::endl;
    }
  }
}
