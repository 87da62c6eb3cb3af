#ifndef softgrasp_postprocess_section_cut_h
#define softgrasp_postprocess_section_cut_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <mpi.h>
#include <softgrasp/mechanics/solid_system.h>
#include <vector>

namespace softgrasp
{
  /**
   * A planar section of the body: the mesh cut by a plane given in the
   * reference configuration, as the polygons where the plane cuts each
   * cell (their corners in the reference and the deformed configuration,
   * the cell's material id and its largest principal strain e_max at the
   * cell centre), and the cut of one boundary (e.g. the skin) as line
   * segments. The corners lie on the cells' edges, where the displacement
   * is interpolated linearly between the vertices (straight-edged cells;
   * the refined mesh's vertices lie on the curved surfaces). m throughout.
   */
  struct Section
  {
    struct Polygon
    {
      std::vector<dealii::Point<3>> reference, deformed;
      dealii::types::material_id    material = 0;
      double                        e_max    = 0;
    };
    struct Segment
    {
      dealii::Point<3> reference[2], deformed[2];
    };

    dealii::Point<3>     origin; ///< a point of the plane (m)
    dealii::Tensor<1, 3> normal; ///< unit normal of the plane
    std::vector<Polygon> polygons;
    std::vector<Segment> outline;

    /**
     * Cut @p system (at its current displacement) by the plane through
     * @p origin with normal @p normal; the outline is the cut of boundary
     * @p outline_id. Collective; the result is complete on rank 0 (other
     * ranks get an empty section).
     */
    static Section cut(const SolidSystem<3>            &system,
                       const dealii::Point<3>          &origin,
                       const dealii::Tensor<1, 3>      &normal,
                       const dealii::types::boundary_id outline_id,
                       MPI_Comm                         comm);
  };
} // namespace softgrasp

#endif
