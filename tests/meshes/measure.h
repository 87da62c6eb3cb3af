// Shared by the mesh tests: volumes per material id and areas per boundary
// id of a (curved) mesh, and their largest error against exact values.
#ifndef softgrasp_tests_meshes_measure_h
#define softgrasp_tests_meshes_measure_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <map>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/meshes/mesh_generator.h>
#include <string>

namespace softgrasp_tests
{
  /// Volume per material id and area per boundary id (MappingQ(2)).
  template <int dim>
  void measure(const dealii::Triangulation<dim> &tria,
               std::map<unsigned int, double>   &volume,
               std::map<unsigned int, double>   &area)
  {
    using namespace dealii;
    const MappingQ<dim>   mapping(2);
    const QGauss<dim>     quadrature(4);
    const QGauss<dim - 1> face_quadrature(4);
    const FE_Nothing<dim> fe;
    FEValues<dim>         values(mapping, fe, quadrature, update_JxW_values);
    FEFaceValues<dim>     face_values(
        mapping, fe, face_quadrature, update_JxW_values);
    for (const auto &cell : tria.active_cell_iterators())
    {
      values.reinit(cell);
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        volume[cell->material_id()] += values.JxW(q);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
        {
          face_values.reinit(cell, f);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
            area[cell->face(f)->boundary_id()] += face_values.JxW(q);
        }
    }
  }

  /// A mesh factory of 'Mesh/Type = @p type' with @p entries in its
  /// subsection @p subsection.
  template <int dim>
  softgrasp::MeshFactory<dim> factory_from(const std::string &type,
                                           const std::string &subsection,
                                           const std::string &entries)
  {
    dealii::ParameterHandler prm;
    softgrasp::MeshFactory<dim>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Mesh\n set Type = " + type +
                                "\n subsection " + subsection + "\n" + entries +
                                " end\nend\n");
    softgrasp::MeshFactory<dim> factory;
    factory.parse_parameters(prm);
    return factory;
  }

  /// A placement that turns the x axis to z (about y) and moves the mesh.
  inline softgrasp::Placement<3> turned_and_moved()
  {
    softgrasp::Placement<3> placement;
    placement.rotation =
        dealii::Tensor<2, 3>({{0., 0., -1.}, {0., 1., 0.}, {1., 0., 0.}});
    placement.translation = dealii::Tensor<1, 3>({0.3, -0.2, 0.1});
    return placement;
  }

  /// The largest |measured - exact| / exact over the ids of @p exact (1
  /// for a missing id).
  inline double
  largest_relative_error(const std::map<unsigned int, double> &measured,
                         const std::map<unsigned int, double> &exact)
  {
    double worst = 0;
    for (const auto &[id, value] : exact)
    {
      const auto it = measured.find(id);
      worst         = std::max(
          worst,
          it == measured.end() ? 1.0 : std::abs(it->second - value) / value);
    }
    return worst;
  }
} // namespace softgrasp_tests

#endif
