// Shared by the tests and benchmarks that run the softgrasp program's
// shipped problems: the text of a problem file, adjusted, and the ball
// octant written as a Gmsh file (as a user's mesher writes it).
#ifndef softgrasp_tests_contact_problem_file_h
#define softgrasp_tests_contact_problem_file_h

#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/tria.h>
#include <fstream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <sstream>
#include <string>

namespace softgrasp_tests
{
  /// The text of the problem file @p path without its 'Dimension' line
  /// (the program's entry), followed by @p overrides (a later 'set' wins).
  inline std::string problem_text(const std::string &path,
                                  const std::string &overrides = "")
  {
    std::istringstream in(softgrasp::ParameterReader::file_text(path));
    std::string        text, line;
    while (std::getline(in, line))
      if (line.rfind("set Dimension", 0) != 0)
        text += line + "\n";
    return text + overrides;
  }

  /// @p text without the subsection @p name (at any depth, with its
  /// content): a mesh type's entries when the test switches 'Mesh/Type'.
  inline std::string without_subsection(const std::string &text,
                                        const std::string &name)
  {
    std::istringstream in(text);
    std::string        kept, line;
    int                depth = 0; // inside the removed subsection
    while (std::getline(in, line))
    {
      const auto        first = line.find_first_not_of(' ');
      const std::string word =
          first == std::string::npos ? "" : line.substr(first);
      if (depth == 0 && word == "subsection " + name)
        depth = 1;
      else if (depth > 0 && word.rfind("subsection ", 0) == 0)
        ++depth;
      else if (depth > 0 && word == "end")
        --depth;
      else if (depth == 0)
        kept += line + "\n";
    }
    return kept;
  }

#ifdef PROBLEM_DIR
  /// problem_text() of the shipped problem @p name.
  inline std::string problem(const std::string &name,
                             const std::string &overrides)
  {
    return problem_text(PROBLEM_DIR "/" + name, overrides);
  }

  /// tube_drag.prm frictionless with @p axial_cells over its fine zone,
  /// quasi-static: pressed 5 mm until t = 0.5 s, pulled 4 mm until
  /// t = 1 s in steps of 0.0625 s; output into @p directory.
  inline std::string frictionless_tube_pull(const unsigned int axial_cells,
                                            const std::string &directory)
  {
    return problem(
        "tube_drag.prm",
        "subsection Mesh\n subsection Tube\n  set Fine zone cells = " +
            std::to_string(axial_cells) +
            "\n end\nend\n"
            "subsection Contact\n set Friction coefficient = 0\nend\n"
            "subsection Rigid bodies\n subsection Body finger\n"
            "  set Trajectory = 0: -0.005, 0, 0.0405, 1, 0, 0, 0; "
            "0.5: -0.005, 0, 0.0355, 1, 0, 0, 0; "
            "1: -0.001, 0, 0.0355, 1, 0, 0, 0\n end\nend\n"
            "subsection Time\n set Integrator = quasi-static\n"
            " set End time = 1\n set Time step = 0.0625\n set Phases =\nend\n"
            "subsection Output\n set Directory = " +
            directory + "\n set VTU interval = 0\n set Verbose = false\nend\n");
  }
#endif

  /// The ball generator's octant (R = 20 mm) refined @p refinements times,
  /// written as Gmsh to @p name with its ids and full precision:
  /// straight-sided cells with their vertices on the sphere.
  inline void write_ball_octant(const unsigned int refinements,
                                const std::string &name)
  {
    dealii::ParameterHandler prm;
    softgrasp::MeshFactory<3>::declare_parameters(prm);
    prm.parse_input_from_string(
        "subsection Mesh\n set Type = ball\n subsection Ball\n"
        "  set Radius = 0.02\n  set Sector = octant\n end\nend\n");
    softgrasp::MeshFactory<3> factory;
    factory.parse_parameters(prm);
    dealii::Triangulation<3> tria;
    factory.create_coarse_mesh(tria);
    tria.refine_global(refinements);
    dealii::GridOut out;
    out.set_flags(dealii::GridOutFlags::Msh(true));
    std::ofstream file(name);
    file.precision(17); // vertices on the sphere to round-off
    out.write_msh(tria, file);
  }

  /// 'Mesh' entries reading the octant file @p name, refined
  /// @p refinements times, with the sphere's manifolds or without.
  inline std::string ball_octant_file_mesh(const std::string &name,
                                           const unsigned int refinements,
                                           const bool         manifolds)
  {
    return " set Type = file\n set Global refinements = " +
           std::to_string(refinements) + "\n subsection File\n" +
           "  set File name = " + name + "\n  set Manifolds = " +
           (manifolds ? "boundary 0: sphere 0, 0, 0; material 0: transfinite"
                      : "") +
           "\n end\n";
  }
} // namespace softgrasp_tests

#endif
