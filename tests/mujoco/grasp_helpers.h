// Shared set-up of the MuJoCo bridge tests: the sphere scene's grasp
// parameters from parameter-files/sphere_squeeze.prm, and the coarse arm of
// parameter-files/arm_grasp.prm.
#ifndef softgrasp_tests_grasp_helpers_h
#define softgrasp_tests_grasp_helpers_h

#include <algorithm>
#include <functional>
#include <memory>
#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/grasp/pull_sweep_study.h>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mujoco/grasp_parameters.h>
#include <softgrasp/mujoco/grasp_pull_sweep.h>
#include <softgrasp/solvers/solver_program.h>
#include <sstream>

namespace softgrasp_tests
{
  /// Declare a study's parameters and read the shipped sphere_squeeze.prm.
  inline void read_sphere_squeeze(dealii::ParameterHandler &prm)
  {
    softgrasp::GraspParameters::declare_parameters(prm);
    softgrasp::IndentationStudy::declare_parameters(prm);
    softgrasp::SolverProgram::read_parameters<3>(
        prm, PARAMETER_FILES "/sphere_squeeze.prm");
  }

  /// The shipped sphere_squeeze.prm one refinement coarser (1470
  /// displacement dofs), without pictures, with node-wise contact.
  inline void read_coarse_sphere_squeeze(dealii::ParameterHandler &prm)
  {
    read_sphere_squeeze(prm);
    prm.enter_subsection("Indentation study");
    prm.set("Pictures", false);
    prm.leave_subsection();
    prm.enter_subsection("Mesh");
    prm.set("Global refinements", "2");
    prm.leave_subsection();
    // node-wise: the tests check no node inside a link and compare with
    // the explicit integrator's node-wise contact; on the faces (the
    // implicit default, which studies/sphere_squeeze runs) the nodes of
    // this coarse mesh sit up to 0.5 mm inside the links while the faces'
    // weighted gaps are closed (doc/studies.md)
    prm.enter_subsection("Contact");
    prm.set("Potential integration", "nodes");
    prm.leave_subsection();
  }

  /// Set @p entry of the subsection @p path (outermost first) of @p prm.
  inline void set(dealii::ParameterHandler       &prm,
                  const std::vector<std::string> &path,
                  const std::string              &entry,
                  const std::string              &value)
  {
    for (const auto &section : path)
      prm.enter_subsection(section);
    prm.set(entry, value);
    for (std::size_t i = 0; i < path.size(); ++i)
      prm.leave_subsection();
  }

  /// The coarse layered limb: 16 cells around, 1, 1, 1, 2 radially, 4
  /// along the grasp zone, no fascia (its thin cells set the explicit step).
  inline void set_coarse_limb(dealii::ParameterHandler &prm)
  {
    set(prm, {"Mesh", "Layered limb"}, "Circumferential cells", "16");
    set(prm, {"Mesh", "Layered limb"}, "Radial cells", "1, 1, 1, 2");
    set(prm, {"Mesh", "Layered limb"}, "Grasp zone cells", "4");
    set(prm, {"Mesh", "Layered limb"}, "Fascia thickness", "0");
  }

  /// The shipped arm_grasp.prm (or @p file of parameter-files/) on a
  /// coarse limb (16 cells around, no fascia: its thin cells set the
  /// explicit step), without pictures, a target force or VTU output,
  /// writing into @p directory.
  inline void read_coarse_arm(dealii::ParameterHandler &prm,
                              const std::string        &directory,
                              const std::string        &file = "arm_grasp.prm")
  {
    softgrasp::GraspParameters::declare_parameters(prm);
    softgrasp::ArmGraspStudy::declare_parameters(prm);
    softgrasp::SolverProgram::read_parameters<3>(
        prm, std::string(PARAMETER_FILES) + "/" + file);
    set_coarse_limb(prm);
    set(prm, {"Indentation study"}, "Pictures", "false");
    set(prm, {"Indentation study"}, "Target normal force", "0");
    set(prm, {"Output"}, "Directory", directory);
    set(prm, {"Output"}, "VTU interval", "0");
  }

  /**
   * The shipped grasp_pull_sweep.prm on the coarse limb, explicit, 2
   * levels up to 30 N, a 5 mm pull, no VTU output, writing into @p directory;
   * @p change may set more entries. The rigid stage has run (its log in log).
   */
  struct CoarseSweep
  {
    dealii::ParameterHandler                   prm;
    std::unique_ptr<softgrasp::PullSweepStudy> study;
    std::unique_ptr<softgrasp::GraspPullSweep> sweep;
    std::ostringstream                         log;

    explicit CoarseSweep(
        const std::string                                     &directory,
        const std::function<void(dealii::ParameterHandler &)> &change = {})
    {
      using softgrasp::GraspPullSweep;
      GraspPullSweep::declare_parameters(prm);
      const std::string file = PARAMETER_FILES "/grasp_pull_sweep.prm";
      softgrasp::SolverProgram::read_parameters<3>(prm, file);
      set_coarse_limb(prm);
      set(prm, {"Grasp-and-pull sweep"}, "Levels", "2");
      set(prm, {"Grasp-and-pull sweep"}, "Highest grip force", "30");
      set(prm, {"Grasp-and-pull sweep"}, "Pull distance", "0.005");
      set(prm, {"Grasp-and-pull sweep"}, "Pull samples", "10");
      set(prm, {"Output"}, "Directory", directory);
      set(prm, {"Output"}, "VTU interval", "0");
      // explicit: on this coarse arm 1.3 times as fast as the shipped
      // quasi-static integrator (which wins on the default arm)
      set(prm, {"Time"}, "Integrator", "explicit dynamic");
      if (change)
        change(prm);
      study = std::make_unique<softgrasp::PullSweepStudy>(MPI_COMM_WORLD, prm);
      sweep =
          std::make_unique<GraspPullSweep>(MPI_COMM_WORLD, prm, file, *study);
      sweep->run_rigid(log);
    }
  };

  inline softgrasp::GraspParameters
  sphere_grasp_parameters(dealii::ParameterHandler &prm)
  {
    softgrasp::GraspParameters p;
    p.parse_parameters(prm, PARAMETER_FILES);
    return p;
  }
  /// The largest difference between two grip levels' link force
  /// histories, relative to the largest force (0 if equal); 1 if their
  /// grip (force, time) or shapes differ.
  inline double level_difference(const softgrasp::FeGripLevel &a,
                                 const softgrasp::FeGripLevel &b)
  {
    if (a.links.size() != b.links.size() || a.pulled != b.pulled ||
        a.reached_force != b.reached_force || a.time != b.time)
      return 1;
    double largest = 1e-12, diff = 0;
    for (std::size_t l = 0; l < a.links.size(); ++l)
    {
      const auto &x = a.links[l], &y = b.links[l];
      if (x.link != y.link || x.time.size() != y.time.size())
        return 1;
      for (std::size_t i = 0; i < x.time.size(); ++i)
      {
        largest = std::max(largest, x.force[i].norm());
        diff    = std::max({diff,
                            (x.force[i] - y.force[i]).norm(),
                            std::abs(x.friction[i] - y.friction[i]),
                            std::abs(x.nodal_normal[i] - y.nodal_normal[i])});
      }
    }
    return diff / largest;
  }

  /// @p p (the sphere scene's grasp) with the underactuated gripper around
  /// the sphere instead, as underactuated_squeeze.prm sets it up: closed
  /// by its one actuator 'grip', 0.1 rad of grip and of indentation.
  inline softgrasp::GraspParameters
  underactuated_sphere_grasp(softgrasp::GraspParameters p)
  {
    p.scene_file    = PARAMETER_FILES "/mjcf/underactuated_sphere_scene.xml";
    p.base_position = {0, 0, 0.05};
    p.finger_joints = {};
    p.closing_actuators       = {"grip"};
    p.contact_links           = {"left_distal_link", "right_distal_link"};
    p.closing_speed           = 1;
    p.grip                    = 0.1;
    p.indentation.extra_angle = 0.1;
    return p;
  }

  /// Log whether @p f throws an InputError whose message has a fix and
  /// every one of @p needles (printing it if not), and check that it does.
  template <typename F>
  void expect_input_error(const std::string              &what,
                          F                               f,
                          const std::vector<std::string> &needles)
  {
    std::string message = "no error";
    try
    {
      f();
    }
    catch (const softgrasp::InputError &e)
    {
      message = e.what();
    }
    bool found = message.find("Fix:") != std::string::npos;
    for (const auto &n : needles)
      found = found && message.find(n) != std::string::npos;
    dealii::deallog << what << ": clear error " << found << std::endl;
    if (!found)
      std::cerr << message << std::endl;
    SG_CHECK(found, what);
  }

  /// The equilibrium forces of a kinematics file on a free object: how
  /// many links touch, the smallest and largest force (N) and |sum| (N).
  struct EquilibriumBalance
  {
    std::size_t links    = 0;
    double      smallest = 1e300, largest = 0, sum = 0;
  };
  inline EquilibriumBalance
  equilibrium_balance(const softgrasp::KinematicsData &data)
  {
    EquilibriumBalance result;
    Eigen::Vector3d    sum = Eigen::Vector3d::Zero();
    for (const auto &f : data.equilibrium_forces)
    {
      sum += f.force;
      result.smallest = std::min(result.smallest, f.force.norm());
      result.largest  = std::max(result.largest, f.force.norm());
      ++result.links;
    }
    result.sum = sum.norm();
    return result;
  }

  /**
   * Over the indentation phase of @p data, the largest deviation (m) of a
   * geom named in @p names from moving @p distance along x, as the rigid
   * bodies built from the file place it; @p found counts the geoms.
   */
  inline double indentation_travel_error(const softgrasp::KinematicsData &data,
                                         const std::vector<std::string>  &names,
                                         const double  distance,
                                         unsigned int &found)
  {
    const auto &phase  = data.phase("indentation");
    const auto  bodies = softgrasp::rigid_bodies_from(data);
    double      error  = 0;
    found              = 0;
    for (const auto &body : bodies.bodies())
      for (unsigned int g = 0; g < body.geoms().size(); ++g)
        if (std::find(names.begin(), names.end(), body.geoms()[g].name) !=
            names.end())
        {
          const double start = body.geom_pose(g, phase.start_time).position[0];
          const double end   = body.geom_pose(g, phase.end_time).position[0];
          error = std::max(error, std::abs(std::abs(start - end) - distance));
          ++found;
        }
    return error;
  }
} // namespace softgrasp_tests

#endif
