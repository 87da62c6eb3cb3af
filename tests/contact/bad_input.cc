// Bad contact input stops with a message that names the parameter (or
// file) and the fix: a contact surface without bodies and bodies without a
// contact surface, an unknown geom type, bad trajectories (times not
// increasing, zero quaternion, NaN, missing file), a mesh geom without its
// file, a body without geoms, a slave boundary id the mesh lacks, an
// unknown contact enforcement and a penalty factor that is neither a
// positive number nor 'automatic'.
#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

using namespace softgrasp_tests;

namespace
{
  std::string base()
  {
    return block("0, 0, 0", "0.01, 0.01, 0.01", "1, 1, 1") +
           neo_hookean(1e4, 0.3) +
           "subsection Boundary conditions\n set Dirichlet boundary ids = 4\n"
           " subsection Dirichlet boundary 4\n  set Components = x, y, z\n"
           " end\nend\nsubsection Output\n set Directory = output-bad\n"
           " set VTU interval = 0\n set Verbose = false\nend\n";
  }

  std::string body(const std::string &trajectory,
                   const std::string &type = "sphere")
  {
    return rigid_body("finger", "tip", type, "0.005", trajectory);
  }

  void expect_error(const std::string &name, const std::string &prm)
  {
    std::string message = "no error";
    try
    {
      auto solver = make_solver<3>(prm);
      solver->run();
    }
    catch (const std::exception &e)
    {
      message = e.what();
    }
    std::string flat;
    for (const char c : message)
      if (!(c == '\n' || c == ' ') || (!flat.empty() && flat.back() != ' '))
        flat += (c == '\n' ? ' ' : c);
    message = flat;
    dealii::deallog << name << ": " << message << std::endl;
    SG_CHECK(message.find("Fix") != std::string::npos ||
                 message.find("one of") != std::string::npos,
             name + ": the message gives the fix");
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();
  const std::string ok = "0: 0, 0, 0.02, 1, 0, 0, 0";
  expect_error("surface without bodies", base() + contact("5", 0));
  expect_error("bodies without surface", base() + body(ok));
  expect_error("unknown geom type",
               base() + contact("5", 0) + body(ok, "sphre"));
  expect_error(
      "times not increasing",
      base() + contact("5", 0) +
          body("0: 0, 0, 0.02, 1, 0, 0, 0; 0: 0, 0, 0.01, 1, 0, 0, 0"));
  expect_error("zero quaternion",
               base() + contact("5", 0) + body("0: 0, 0, 0.02, 0, 0, 0, 0"));
  expect_error("NaN position",
               base() + contact("5", 0) + body("0: 0, nan, 0.02, 1, 0, 0, 0"));
  expect_error("too few numbers",
               base() + contact("5", 0) + body("0: 0, 0, 0.02, 1, 0, 0"));
  expect_error("missing trajectory file",
               base() + contact("5", 0) + body(ok) +
                   "subsection Rigid bodies\n subsection Body finger\n"
                   "  set Trajectory file = no-such-file.csv\n end\nend\n");
  expect_error("mesh geom without file",
               base() + contact("5", 0) + body(ok, "mesh"));
  expect_error("body without geoms",
               base() + contact("5", 0) +
                   "subsection Rigid bodies\n set Names = finger\nend\n");
  expect_error("slave id not on the mesh",
               base() + contact("17", 0) + body(ok));
  // a misspelt enforcement lists the registered ones; a NaN, negative or
  // misspelt penalty factor names 'automatic' and a number
  const std::string enforcement =
      "subsection Contact\n set Enforcement = incremental potentail\nend\n";
  expect_error("unknown contact enforcement",
               base() + contact("5", 0) + body(ok) + enforcement);
  expect_error("NaN penalty factor",
               base() + contact("5", 0) + body(ok) +
                   "subsection Contact\n set Enforcement = incremental "
                   "potential\n set Penalty factor = nan\nend\n");
  for (const std::string factor : {"-5", "autmatic", "1e3x"})
    expect_error("penalty factor " + factor,
                 base() + contact("5", 0) + body(ok) +
                     "subsection Contact\n set Penalty factor = " + factor +
                     "\nend\n");
}
