// Coarse arm grasp end to end from the shipped arm_grasp.prm (a coarser
// limb without fascia, a smaller closure): MuJoCo closes the large hand on
// the rigid arm that LimbScene made from the layered limb's geometry, the
// explicit finite element solver drives the same links into the layered
// limb placed at the arm's recorded pose.
//  - the MuJoCo arm is the finite element limb: its mass is the density
//    times the volume of the limb's skin polygon (exact for the faceted
//    surface);
//  - finite elements: no penetration beyond 1 micrometre, the link forces
//    balance the reaction of the humerus (within 5 % of the largest link
//    force; the rest is inertia of the explicit run), and the grip grows
//    with the closure (the distal links carry it on this coarse mesh);
//  - sliced views: in the slice across the arm the skin under the thumb
//    moves inward (towards the arm's axis) by more than 0.5 mm, and in the
//    slice parallel to the palm e_max of skin and fat next to the links
//    (within 35 mm) is more than 3 times its largest value 60 mm or more
//    away from them;
//  - injury table: the largest compression (e_min) of skin and fat lies
//    within 10 mm of a finger link (their largest stretch may lie between
//    the fingers), the largest contact pressure on a link's surface (within
//    0.1 mm), the skin area above the capillary closing pressure is part
//    of the contact area, and more tissue is compressed beyond 0.40 than
//    beyond 0.65.
#include "../tests.h"
#include "grasp_helpers.h"

#include <mujoco/mujoco.h>
#include <softgrasp/mujoco/grasp_simulation.h>

using namespace softgrasp;
using softgrasp_tests::set;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  softgrasp_tests::initlog();
  dealii::ParameterHandler prm;
  // Coarse, 0.1 rad of closure in 5 samples.
  softgrasp_tests::read_coarse_arm(prm, "output-arm");
  set(prm, {"Rigid environment", "Indentation"}, "Extra joint angle", "0.1");
  set(prm, {"Rigid environment", "Indentation"}, "Samples", "5");
  set(prm, {"Time"}, "Time step", "0.05");

  ArmGraspStudy   study(MPI_COMM_WORLD, prm);
  GraspParameters grasp;
  grasp.parse_parameters(prm, PARAMETER_FILES);
  grasp.scene_file = study.rigid_scene(grasp.scene_file, "output-arm");

  // The rigid arm against the finite element limb's geometry.
  {
    char     error[1000] = "";
    mjModel *m = mj_loadXML(grasp.scene_file.c_str(), nullptr, error, 1000);
    SG_CHECK(m != nullptr, std::string("scene loads: ") + error);
    const int    arm    = mj_name2id(m, mjOBJ_BODY, "object");
    const auto  &limb   = study.limb();
    const double R      = limb.semi_axes(4, 0)[0];
    const double n      = 96;
    const double volume = n / 2 * R * R * std::sin(2 * M_PI / n) * limb.length;
    SG_CHECK_CLOSE(m->body_mass[arm], 1050 * volume, 1e-5, 0, "arm mass");
    dealii::deallog << "MuJoCo arm mass = density x limb volume: "
                    << std::round(m->body_mass[arm] * 1000) / 1000 << " kg"
                    << std::endl;
    mj_deleteModel(m);
  }

  std::ostringstream   log;
  GraspSimulation      simulation(grasp, log);
  const KinematicsData data = simulation.run();
  study.run(data);
  const auto &s = study.summary();
  dealii::deallog << "FE: closure " << s.closure << " rad in " << s.steps
                  << " records" << std::endl;
  SG_CHECK(s.penetration < 1e-6, "no penetration beyond 1 micrometre");
  SG_CHECK(s.balance < 0.05, "link forces balance the humerus' reaction");
  dealii::deallog << "penetration < 1 um, balance within 5 %" << std::endl;
  // The grip grows with the closure; on this coarse limb the distal links
  // carry it (the proximal links touch MuJoCo's rigid arm, but the FE skin
  // between the 16 nodes around lies up to 1 mm inside the true surface).
  double middle = 0, last = 0;
  for (const auto &link : study.link_forces())
  {
    middle += link.normal[link.normal.size() / 2];
    last += link.normal.back();
    if (link.link.find("distal") != std::string::npos)
      SG_CHECK(link.normal.back() > 1,
               "every distal link presses: " + link.link);
  }
  SG_CHECK(last > 1.5 * middle && middle > 0,
           "the grip grows as the hand closes");
  dealii::deallog << "every distal link presses with more than 1 N; the sum "
                     "of the link normal forces grows with the closure"
                  << std::endl;

  // The sliced views.
  const auto &views = study.sections();
  SG_CHECK(views.size() == 2, "a vertical and a horizontal slice");
  const auto [centre, axis] = study.limb_axis();
  const auto radial =
      [&, centre = centre, axis = axis](const dealii::Point<3> &p)
  {
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - centre;
    return (d - d.dot(axis) * axis).norm();
  };
  const auto distance_to_links =
      [](const dealii::Point<3>                           &p,
         const std::vector<std::vector<dealii::Point<3>>> &links)
  {
    double d = 1e300;
    for (const auto &outline : links)
      for (const auto &q : outline)
        d = std::min(d, p.distance(q));
    return d;
  };
  {
    const auto &v = views[0];
    SG_CHECK(!v.links_indented.empty(), "the thumb crosses the vertical slice");
    double       moved = 0;
    unsigned int n     = 0;
    for (const auto &segment : v.section.outline)
      for (unsigned int k = 0; k < 2; ++k)
        if (distance_to_links(segment.deformed[k], v.links_indented) < 5e-3)
        {
          moved += radial(segment.deformed[k]) - radial(segment.reference[k]);
          ++n;
        }
    SG_CHECK(n > 0 && moved / n < -0.5e-3,
             "the skin under the thumb moves inward");
    dealii::deallog << "vertical slice: the skin under the thumb moves "
                       "inward by more than 0.5 mm"
                    << std::endl;
  }
  {
    // e_max of skin and fat near the links (within 35 mm: the cells next
    // to them on this coarse mesh) against far from them (beyond 60 mm).
    const auto &v    = views[1];
    double      near = 0, far = 0;
    for (const auto &p : v.section.polygons)
      if (p.material == 1 || p.material == 2)
      {
        dealii::Point<3> mean;
        for (const auto &x : p.deformed)
          mean += x / double(p.deformed.size());
        const double d = distance_to_links(mean, v.links_indented);
        if (d < 35e-3)
          near = std::max(near, p.e_max);
        else if (d > 60e-3)
          far = std::max(far, p.e_max);
      }
    SG_CHECK(near > 3 * far && near > 0.02,
             "e_max of skin and fat peaks next to the finger links");
    dealii::deallog << "horizontal slice: e_max of skin and fat next to the "
                       "links is more than 3 times that far from them"
                    << std::endl;
  }

  // The injury table.
  {
    const auto &injury = study.injury();
    SG_CHECK(injury.tissues().size() == 3,
             "skin, fat, muscle (no fascia, a rigid bone)");
    for (const auto &t : injury.tissues())
    {
      if (t.id == 1 || t.id == 2)
        SG_CHECK(t.e_min.geom_distance < 10e-3,
                 "e_min of " + t.name + " next to a link (" +
                     t.e_min.nearest_geom + ")");
      SG_CHECK(t.volume_compressed[1] <= t.volume_compressed[0],
               "more tissue compressed beyond 0.40 than beyond 0.65");
    }
    const auto &p = injury.surface();
    SG_CHECK(p.maximum.value > 0 && std::abs(p.maximum.geom_distance) < 1e-4,
             "the largest pressure is on a link's surface");
    SG_CHECK(p.area_above[0] > 0 && p.area_above[0] <= p.contact_area,
             "skin area above 4.3 kPa is part of the contact area");
    dealii::deallog << "injury table: e_min of skin and fat next to the "
                       "links; the largest pressure on a link's surface"
                    << std::endl;
  }
}
