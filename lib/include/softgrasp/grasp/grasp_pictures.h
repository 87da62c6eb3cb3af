#ifndef softgrasp_grasp_grasp_pictures_h
#define softgrasp_grasp_grasp_pictures_h

#include <ostream>
#include <softgrasp/io/kinematics_file.h>
#include <softgrasp/mechanics/solid_system.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * PNG picture (gnuplot) of the deformed surface of @p system coloured by
   * the largest principal Green-Lagrange strain e_max, with the geoms of
   * @p kinematics at time @p time drawn as wire frames (mesh geoms also
   * as grey surfaces): writes <base>_surface.dat, <base>_geoms.dat,
   * <base>_mesh_links.dat, <base>_picture.gnuplot and <base>_picture.png
   * in @p directory. Faces on boundary ids in
   * @p hidden_boundaries (e.g. a rigid core) are left out. Collective; the
   * files are written on rank 0. Lengths drawn in mm.
   */
  void write_grasp_picture(const SolidSystem<3>            &system,
                           const KinematicsData            &kinematics,
                           const double                     time,
                           const std::vector<unsigned int> &hidden_boundaries,
                           const std::string               &directory,
                           const std::string               &base,
                           std::ostream                    &log);

  /**
   * PNG plot (gnuplot) of force against closure per link from the table
   * @p csv_name of IndentationStudy (in @p directory): the finite element
   * normal and
   * lateral force as lines, the rigid simulator's as dashed lines of the
   * same colour, against the closure in @p closure_unit ("rad", "m").
   * Writes <base>_forces.gnuplot and <base>_forces.png.
   */
  void write_force_plot(const std::string              &csv_name,
                        const std::vector<std::string> &links,
                        const std::string              &closure_unit,
                        const std::string              &directory,
                        const std::string              &base,
                        std::ostream                   &log);
} // namespace softgrasp

#endif
