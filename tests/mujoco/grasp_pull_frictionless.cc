// Translation invariance of the finite element pull: the arm of the
// grasp-and-pull sweep is a straight limb along the pull axis (world y).
// Without friction ('Contact/Friction coefficient = 0'; MuJoCo's levels
// keep theirs), closed to 3 N on the thumb's proximal link and pulled 5 mm,
// the tissue can push the links along only by pressure on their sides, and
// on a straight limb a translated deformation costs nothing: the links'
// total force along the pull vanishes up to the discretisation. The limb
// is the coarse one with 16 cells along the grasp zone (6.25 mm: a contact
// node must not be alone on a link, or the link runs over it onto its end
// cap). Checked at every record of the pull after the closed state:
//  - no link carries friction;
//  - the links' total drag is below 5 % of their total normal force (it
//    oscillates by 2.5 % as the links pass the skin's nodes; the frictional
//    pull of tests/mujoco/grasp_pull_fe meets 9-11 %), and its mean over
//    the pull below 1 %;
//  - the total normal force stays within 2 % of its value when the pull
//    starts;
//  - at the end the link forces balance the humerus within 5 % (the rest is
//    the inertia of the explicit run).
#include "../tests.h"
#include "grasp_helpers.h"

#include <filesystem>

using namespace softgrasp;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  std::filesystem::remove_all("output-frictionless");
  softgrasp_tests::CoarseSweep s(
      "output-frictionless",
      [](dealii::ParameterHandler &prm)
      {
        softgrasp_tests::set(prm, {"Contact"}, "Friction coefficient", "0");
        softgrasp_tests::set(
            prm, {"Mesh", "Layered limb"}, "Grasp zone cells", "16");
        softgrasp_tests::set(
            prm, {"Mesh", "Layered limb"}, "Circumferential cells", "16");
        softgrasp_tests::set(
            prm, {"Grasp-and-pull sweep"}, "Lowest grip force", "3");
        softgrasp_tests::set(
            prm, {"Grasp-and-pull sweep"}, "Highest grip force", "6");
      });
  s.sweep->close(s.log, 1);
  s.sweep->pull(1, s.log);
  const FeGripLevel &level = s.sweep->fe_levels().front();
  SG_CHECK(level.pulled, "the pull runs to its end: " + level.failure);
  SG_CHECK(level.balance < 0.05, "link forces balance the humerus");
  const std::size_t records = level.links.front().time.size();
  double            worst = 0, mean = 0, normal_start = 0;
  for (std::size_t i = 0; i < records; ++i)
  {
    double drag = 0, normal = 0, friction = 0;
    for (const auto &link : level.links)
    {
      drag -= link.force[i][1];
      normal += link.normal[i];
      friction = std::max(friction, link.friction[i]);
    }
    if (i == 0) // the closed state
    {
      normal_start = normal;
      continue;
    }
    SG_CHECK(friction < 1e-9 * normal, "no friction");
    SG_CHECK(std::abs(normal - normal_start) < 0.02 * normal_start,
             "a steady normal force");
    worst = std::max(worst, std::abs(drag) / normal);
    mean += drag / normal / (records - 1);
  }
  SG_CHECK(records > 5, "the pull is recorded");
  SG_CHECK(worst < 0.05, "no drag on a straight limb without friction");
  SG_CHECK(std::abs(mean) < 0.01, "no mean drag");
  dealii::deallog << "frictionless pull on the straight limb: no friction, "
                     "a steady normal force, |drag| below 5 % of it at every "
                     "record and below 1 % on average, link forces balance "
                     "the humerus"
                  << std::endl;
}
