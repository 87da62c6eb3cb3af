#include <softgrasp/base/input_error.h>
#include <softgrasp/grasp/arm_grasp_study.h>

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
    const auto *limb =
        dynamic_cast<const LayeredLimb *>(&solver_inputs.mesh.generator());
    if (limb == nullptr)
      throw InputError("The arm grasp study needs 'Mesh/Type = layered "
                       "limb' (it is '" +
                       solver_inputs.mesh.type_name +
                       "'): the rigid arm is made from the same geometry. "
                       "Fix: set 'Mesh/Type = layered limb'; for your own "
                       "anatomical mesh run the generic grasp study.");
    geometry = limb->geometry;
    scene.parse_parameters(prm);
  }

  std::string ArmGraspStudy::rigid_scene(const std::string &hand_file,
                                         const std::string &directory) const
  {
    return scene.write(geometry, hand_file, directory);
  }

  void ArmGraspStudy::set_up_tissue(SolverInputs<3> &inputs,
                                    const Pose      &object) const
  {
    const Pose            frame = LimbScene::limb_frame_in_body(geometry);
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
} // namespace softgrasp
