#ifndef softgrasp_grasp_arm_grasp_study_h
#define softgrasp_grasp_arm_grasp_study_h

#include <optional>
#include <softgrasp/grasp/indentation_study.h>
#include <softgrasp/grasp/limb_scene.h>
#include <softgrasp/grasp/section_pictures.h>
#include <softgrasp/meshes/layered_limb.h>

namespace softgrasp
{
  /**
   * The arm grasp (the source paper's first case study) on the layered
   * limb ('Mesh/Type = layered limb') or on a user's own limb mesh
   * ('Mesh/Type = file', with the layered limb's ids and frame): the rigid
   * stage grasps a rigid arm made from the limb's skin surface (LimbScene),
   * the finite element stage places the limb at the arm body's recorded
   * pose and drives the fingers into it. See doc/studies.md.
   */
  class ArmGraspStudy : public IndentationStudy
  {
  public:
    static void declare_parameters(dealii::ParameterHandler &prm);

    ArmGraspStudy(MPI_Comm comm, dealii::ParameterHandler &prm);

    std::string rigid_scene(const std::string &hand_file,
                            const std::string &directory) const override;

    /// The limb's geometry (from 'Mesh/Layered limb'); an InputError for
    /// a limb mesh from a file.
    const LimbGeometry &limb() const;
    /// The skin surface the rigid arm is made of (limb frame).
    const LimbSurface &skin_surface() const
    {
      return skin;
    }

    /// The sliced views of the last run (complete on rank 0): vertical,
    /// then horizontal.
    const std::vector<SectionView> &sections() const
    {
      return views;
    }

    /// The limb's axis at the equilibrium state: a point (its centre) and
    /// the unit direction from the shoulder to the elbow (world, m).
    std::pair<Eigen::Vector3d, Eigen::Vector3d> limb_axis() const
    {
      return {centre, axis};
    }

  protected:
    void set_up_tissue(SolverInputs<3> &inputs,
                       const Pose      &object) const override;

    /// The sliced views (paper's fig. 8 and 9): a vertical slice across
    /// the arm through the target link, and a slice parallel to the palm
    /// through the arm's axis at the link, at the equilibrium and the
    /// indented state.
    void postprocess(const Simulation<3>  &solver,
                     const KinematicsData &phases) override;

  private:
    std::optional<LimbGeometry> geometry; ///< of a layered limb
    LimbSurface                 skin;
    LimbScene                   scene;
    std::vector<SectionView>    views;
    Eigen::Vector3d             centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d             axis   = Eigen::Vector3d::UnitX();
  };
} // namespace softgrasp

#endif
