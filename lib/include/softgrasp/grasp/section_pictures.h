#ifndef softgrasp_grasp_section_pictures_h
#define softgrasp_grasp_section_pictures_h

#include <map>
#include <ostream>
#include <softgrasp/postprocess/section_cut.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * A sliced view of a grasp (the source paper's fig. 8 and 9): a Section
   * of the tissue, the in-plane axes it is drawn in, and the cross-sections
   * of the rigid geoms at the equilibrium state (time 0) and at the
   * indented state.
   */
  struct SectionView
  {
    std::string          name;  ///< file name part, e.g. "vertical"
    std::string          title; ///< what the slice is, for the pictures
    Section              section;
    dealii::Tensor<1, 3> e1, e2; ///< in-plane axes drawn as x and y
    std::vector<std::vector<dealii::Point<3>>> links_equilibrium,
        links_indented; ///< closed outlines (m)

    /// The outlines where the plane cuts the geoms of @p bodies at time
    /// @p time (any Shape: found from its signed distance).
    static std::vector<std::vector<dealii::Point<3>>>
    geom_outlines(const RigidBodySet         &bodies,
                  const double                time,
                  const dealii::Point<3>     &origin,
                  const dealii::Tensor<1, 3> &normal,
                  const dealii::Tensor<1, 3> &e1,
                  const dealii::Tensor<1, 3> &e2);
  };

  /**
   * Write, for @p view (on rank 0): <base>_<name>_section.csv (every
   * polygon corner, reference and deformed, with material id and e_max),
   * <base>_<name>_skin.csv (the skin outline before and after, in-plane
   * coordinates in m), and with gnuplot <base>_<name>_section.png (three
   * panels: tissues at the equilibrium state, tissues at the indented
   * state, e_max at the indented state; the link cross-sections drawn) and
   * <base>_<name>_skin.png (the skin outline before and after). Tissues are
   * named by @p tissue_names (material id -> name).
   */
  void write_section_pictures(
      const SectionView                                       &view,
      const std::map<dealii::types::material_id, std::string> &tissue_names,
      const std::string                                       &directory,
      const std::string                                       &base,
      std::ostream                                            &log);
} // namespace softgrasp

#endif
