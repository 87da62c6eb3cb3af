// Bad input and failing runs stop with a clear message that names the cause
// and the fix, and lose nothing already computed:
//  - missing, misnamed and malformed mesh files; an unmapped material id; a
//    broken load expression; a misspelled entry; a monitor point with the
//    wrong number of coordinates; resuming without a checkpoint;
//  - a load step too large to converge is cut back and then succeeds;
//  - when the cut-backs run out, the run stops with the step, time and
//    residual history, after writing the last converged state (VTU and
//    checkpoint).
#include "../solver_factory.h"
#include "../tests.h"

#include <filesystem>
#include <fstream>
#include <softgrasp/base/input_error.h>

using namespace softgrasp_tests;

std::string
block_prm(const std::string &mesh,
          const std::string &extra,
          const double       compression,
          const std::string &directory)
{
  std::ostringstream s;
  s << "subsection Mesh\n"
    << mesh << "\n subsection Block\n  set Upper corner = 0.01, 0.01, 0.01\n"
    << " end\nend\n"
    << "subsection Finite element\n set Polynomial degree = 1\n"
    << " set Formulation = mixed u-p-J\nend\n"
    << "subsection Materials\n set Material ids = 0\n"
    << " subsection Material 0\n  set Preset = subcutaneous fat\n end\nend\n"
    << "subsection Boundary conditions\n set Dirichlet boundary ids = 4, 5\n"
    << " subsection Dirichlet boundary 5\n  set Displacement = 0; 0; "
    << -compression * 0.01 << " * t\n end\nend\n"
    << "subsection Time\n set Time step = 1\nend\n"
    << "subsection Linear solver\n set Type = direct\nend\n"
    << "subsection Output\n set Directory = " << directory
    << "\n set Verbose = false\nend\n"
    << extra;
  return s.str();
}

template <typename Exception>
void
expect_error(const std::string              &what,
             const std::string              &prm,
             const std::vector<std::string> &phrases)
{
  try
  {
    make_solver<3>(prm)->run();
  }
  catch (const Exception &e)
  {
    const std::string message = e.what();
    for (const std::string &phrase : phrases)
      SG_CHECK(message.find(phrase) != std::string::npos,
               what + ": the message names '" + phrase + "': " + message);
    dealii::deallog << what << ": stops with a message naming";
    for (const std::string &phrase : phrases)
      dealii::deallog << " '" << phrase << "'";
    dealii::deallog << std::endl;
    return;
  }
  SG_CHECK(false, what + ": no error was raised");
}

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  using softgrasp::InputError;
  using softgrasp::SolverFailure;

  expect_error<InputError>(
      "missing mesh file",
      block_prm("set Type = file\nsubsection File\n set File name = "
                "nowhere.msh\nend",
                "",
                0.1,
                "out-bad"),
      {"Cannot open the mesh file 'nowhere.msh'", "Fix:"});
  expect_error<InputError>(
      "unsupported mesh format",
      block_prm("set Type = file\nsubsection File\n set File name = "
                "mesh.stl\nend",
                "",
                0.1,
                "out-bad"),
      {"extension '.stl'", "Gmsh (.msh) or Abaqus (.inp)"});
  {
    std::ofstream("broken.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
                                << "$Nodes\n3\n1 0 0 0\n";
  }
  expect_error<InputError>(
      "truncated Gmsh file",
      block_prm("set Type = file\nsubsection File\n set File name = "
                "broken.msh\nend",
                "",
                0.1,
                "out-bad"),
      {"The mesh file 'broken.msh' cannot be read", "Fix:"});
  expect_error<InputError>(
      "unmapped material id",
      block_prm("set Type = block\nset Material id = 3", "", 0.1, "out-bad"),
      {"3", "Materials"});
  expect_error<InputError>(
      "broken load expression",
      block_prm("set Type = block",
                "subsection Boundary conditions\n subsection Dirichlet "
                "boundary 4\n  set Displacement = 0; 0; sin(\n end\nend\n",
                0.1,
                "out-bad"),
      {"Boundary conditions/Dirichlet boundary 4/Displacement", "Fix:"});
  expect_error<InputError>(
      "misspelled entry",
      block_prm(
          "set Type = block\nset Global refinement = 1", "", 0.1, "out-bad"),
      {"Global refinement", "Fix:"});
  expect_error<InputError>(
      "monitor point in 2 coordinates",
      block_prm("set Type = block",
                "subsection Output\n set Monitor points = 0.01, 0.01\nend\n",
                0.1,
                "out-bad"),
      {"Output/Monitor points", "3 coordinates"});
  expect_error<InputError>(
      "resume without checkpoint",
      block_prm("set Type = block",
                "subsection Checkpoint\n set Resume = true\nend\n",
                0.1,
                "out-empty"),
      {"no usable checkpoint", "Resume = false"});

  // 60 % compression in one step does not converge in 3 Newton iterations;
  // halving the step does.
  {
    auto solver = make_solver<3>(
        block_prm("set Type = block",
                  "subsection Newton\n set Maximum iterations = 3\nend\n",
                  0.6,
                  "out-cut"));
    solver->run();
    const auto &history   = solver->history();
    double      cut_backs = 0;
    for (std::size_t r = 0; r < history.rows.size(); ++r)
      cut_backs += history.value(r, "cut_backs");
    dealii::deallog << "60 % compression in one step: converged after "
                    << cut_backs << " cut-back(s) in "
                    << history.rows.size() - 1 << " steps" << std::endl;
    SG_CHECK(cut_backs > 0, "the step was cut back");
    SG_CHECK(std::abs(history.value(history.rows.size() - 1, "time") - 1) <
                 1e-12,
             "the run reaches the end time");
  }

  // The same without cut-backs allowed: stop with the last converged state.
  std::filesystem::remove_all("out-stop");
  expect_error<SolverFailure>(
      "cut-backs exhausted",
      block_prm("set Type = block",
                "subsection Time\n set Maximum cut-backs = 0\nend\n"
                "subsection Newton\n set Maximum iterations = 3\nend\n",
                0.6,
                "out-stop"),
      {"Step 1 (t = 1 s", "Residual history", "last converged state", "Fix:"});
  SG_CHECK(std::filesystem::exists("out-stop/checkpoint/state.txt"),
           "a checkpoint of the last converged state exists");
  SG_CHECK(std::filesystem::exists("out-stop/solution_00000.vtu"),
           "the last converged fields were written");
  dealii::deallog << "last converged state written: checkpoint and VTU"
                  << std::endl;
}
