#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/arm_grasp_study.h>
#include <softgrasp/grasp/section_pictures.h>
#include <softgrasp/solvers/simulation.h>

namespace softgrasp
{
  using namespace dealii;

  void ArmGraspStudy::declare_parameters(ParameterHandler &prm)
  {
    IndentationStudy::declare_parameters(prm);
    LimbScene::declare_parameters(prm);
  }

  ArmGraspStudy::ArmGraspStudy(MPI_Comm comm, ParameterHandler &prm)
      : IndentationStudy(comm, prm)
  {
    scene.parse_parameters(prm);
    const MeshGenerator<3> &mesh = inputs().mesh.generator();
    if (const auto *limb = dynamic_cast<const LayeredLimb *>(&mesh))
    {
      geometry = limb->geometry;
      skin     = LimbSurface::of_layered_limb(*geometry, scene.facets);
    }
    else
    {
      // A user's own limb mesh: the rigid arm is its coarse skin.
      Triangulation<3> coarse;
      mesh.create_coarse_mesh(coarse);
      skin = LimbSurface::of_mesh(coarse, 0);
    }
  }

  const LimbGeometry &ArmGraspStudy::limb() const
  {
    if (!geometry)
      throw InputError("The arm grasp study runs on a limb mesh from a "
                       "file, which has no layered-limb geometry. Fix: use "
                       "skin_surface() for its shape.");
    return *geometry;
  }

  std::string ArmGraspStudy::rigid_scene(const std::string &hand_file,
                                         const std::string &directory) const
  {
    return scene.write(skin, hand_file, directory);
  }

  void ArmGraspStudy::set_up_tissue(SolverInputs<3> &inputs,
                                    const Pose      &object) const
  {
    const Pose            frame = LimbScene::limb_frame_in_body(skin.length);
    const Eigen::Vector3d t     = object.to_world(frame.position);
    const Eigen::Matrix3d R =
        (object.orientation * frame.orientation).toRotationMatrix();
    Placement<3> placement;
    for (unsigned int i = 0; i < 3; ++i)
    {
      placement.translation[i] = t[i];
      for (unsigned int j = 0; j < 3; ++j)
        placement.rotation[i][j] = R(i, j);
    }
    place_tissue(inputs, placement);
  }

  namespace
  {
    Tensor<1, 3> tensor(const Eigen::Vector3d &v)
    {
      return Tensor<1, 3>({v[0], v[1], v[2]});
    }
  } // namespace

  void ArmGraspStudy::postprocess(const Simulation<3>  &solver,
                                  const KinematicsData &phases)
  {
    const auto        &records = solver.contact_force_history();
    const double       t_end   = records.empty() ? 0 : records.back().time;
    const RigidBodySet bodies  = rigid_bodies_from(phases);
    // The limb's axis (world) and the link the slices go through.
    const KinematicsData::Body *object = nullptr;
    for (const auto &b : phases.bodies)
      if (b.name == study_parameters().object_body)
        object = &b;
    const Pose frame = LimbScene::limb_frame_in_body(skin.length);
    axis             = object->poses.front().orientation *
           (frame.orientation * Eigen::Vector3d::UnitX());
    centre                  = object->poses.front().to_world(frame.position);
    Eigen::Vector3d through = centre;
    for (unsigned int b = 0; b < bodies.bodies().size(); ++b)
      for (unsigned int g = 0; g < bodies.bodies()[b].geoms().size(); ++g)
        if (bodies.geom_label(b, g) == study_parameters().target_link ||
            (study_parameters().target_link.empty() && b == 0 && g == 0))
          through = bodies.bodies()[b].geom_pose(g, t_end).position;
    const Eigen::Vector3d palm_normal =
        phases.bodies.front().poses.back().orientation *
        Eigen::Vector3d::UnitZ();
    std::map<types::material_id, std::string> names;
    for (const auto id : solver.materials().material_ids())
      names[id] = solver.materials().get(id).name();

    // The point of the limb's axis nearest to the link.
    const Eigen::Vector3d on_axis =
        centre + (through - centre).dot(axis) * axis;
    const auto view = [&](const std::string     &name,
                          const std::string     &title,
                          const Eigen::Vector3d &point,
                          const Eigen::Vector3d &normal,
                          const Eigen::Vector3d &up)
    {
      SectionView v;
      v.name                   = name;
      v.title                  = title;
      const Eigen::Vector3d n  = normal.normalized();
      const Eigen::Vector3d e2 = (up - up.dot(n) * n).normalized();
      v.e1                     = tensor(e2.cross(n));
      v.e2                     = tensor(e2);
      const Point<3> origin(point[0], point[1], point[2]);
      v.section =
          Section::cut(solver.system(), origin, tensor(n), 0, communicator());
      v.links_equilibrium =
          SectionView::geom_outlines(bodies, 0, origin, tensor(n), v.e1, v.e2);
      v.links_indented = SectionView::geom_outlines(
          bodies, t_end, origin, tensor(n), v.e1, v.e2);
      if (study_parameters().pictures &&
          Utilities::MPI::this_mpi_process(communicator()) == 0)
        write_section_pictures(v,
                               names,
                               solver.parameters().output.directory,
                               solver.parameters().output.base_name,
                               std::cout);
      views.push_back(std::move(v));
    };
    views.clear();
    view("vertical",
         "vertical slice across the arm through " +
             study_parameters().target_link,
         through,
         axis,
         palm_normal);
    view("horizontal",
         "slice parallel to the palm through the arm's axis at " +
             study_parameters().target_link,
         on_axis,
         palm_normal,
         -axis.cross(palm_normal));
  }
} // namespace softgrasp
