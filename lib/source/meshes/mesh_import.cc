#include <cctype>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/mesh_import.h>
#include <sstream>

namespace softgrasp
{
  namespace Meshes
  {
    using namespace dealii;

    namespace
    {
      /// Holds what is written to std::cerr while it lives (deal.II's
      /// Abaqus reader prints the error of its internal conversion there,
      /// banner and stack trace included).
      class CerrCapture
      {
      public:
        CerrCapture()
            : saved(std::cerr.rdbuf(captured.rdbuf()))
        {
        }
        ~CerrCapture()
        {
          std::cerr.rdbuf(saved);
        }
        /// The "Additional information" of a captured deal.II exception.
        std::string reason() const
        {
          const std::string text   = captured.str();
          const std::string marker = "Additional information:";
          const auto        begin  = text.find(marker);
          if (begin == std::string::npos)
            return "";
          const auto  end    = text.find("Stacktrace:", begin);
          std::string reason = text.substr(begin + marker.size(),
                                           end == std::string::npos
                                               ? std::string::npos
                                               : end - begin - marker.size());
          std::string words; // one line, single spaces
          for (const char c : reason)
            if (!std::isspace(static_cast<unsigned char>(c)))
              words += c;
            else if (!words.empty() && words.back() != ' ')
              words += ' ';
          return Utilities::trim(words);
        }

      private:
        std::ostringstream captured;
        std::streambuf    *saved;
      };
    } // namespace

    template <int dim>
    void read_mesh_file(Triangulation<dim> &triangulation,
                        const std::string  &filename,
                        const double        scale)
    {
      const std::string extension =
          std::filesystem::path(filename).extension().string();
      if (extension != ".msh" && extension != ".inp")
        throw InputError("Mesh file '" + filename + "' has the extension '" +
                         extension +
                         "', which softgrasp cannot read. Fix: export the "
                         "mesh as Gmsh (.msh) or Abaqus (.inp).");
      std::ifstream in(filename);
      if (!in)
        throw InputError("Cannot open the mesh file '" + filename +
                         "'. Fix: check 'Mesh/File/File name'; relative paths "
                         "are read from the working directory.");
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(triangulation);
      CerrCapture printed;
      try
      {
        if (extension == ".msh")
          grid_in.read_msh(in);
        else
          grid_in.read_abaqus(in);
      }
      catch (const ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        // the Abaqus reader's own error names the cause; its wrapper only
        // says that the conversion failed
        const std::string reason = printed.reason().empty()
                                       ? Utilities::trim(info.str())
                                       : printed.reason();
        throw InputError("The mesh file '" + filename +
                         "' cannot be read as a " + std::to_string(dim) + "D " +
                         (extension == ".msh" ? "Gmsh" : "Abaqus") +
                         " mesh: " + reason +
                         " Fix: check that the file is complete, of the "
                         "right dimension, and contains only hexahedra "
                         "(quadrilaterals in 2D).");
      }
      if (triangulation.n_active_cells() == 0)
        throw InputError("The mesh file '" + filename +
                         "' contains no cells. Fix: export the volume "
                         "elements, not only the surface.");
      if (scale != 1.0)
        GridTools::scale(scale, triangulation);
    }

    template void
    read_mesh_file(Triangulation<2> &, const std::string &, const double);
    template void
    read_mesh_file(Triangulation<3> &, const std::string &, const double);
  } // namespace Meshes
} // namespace softgrasp
