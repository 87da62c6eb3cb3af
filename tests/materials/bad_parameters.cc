// Bad parameter files stop with an error that names the parameter, the
// value and the allowed range (or the valid names): an unknown model, a
// missing modulus, a negative modulus, nu >= 0.5, both and neither of bulk
// modulus and Poisson's ratio, mismatched Ogden lists, an unknown preset,
// a misspelled entry, a material id without a material.

#include "../tests.h"

#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/material_library.h>

using namespace dealii;
using namespace softgrasp;

void
expect_error(const std::string &label,
             const std::string &material_text,
             const std::string &must_contain)
{
  ParameterHandler prm;
  MaterialLibrary::declare_parameters(prm);
  const std::string text =
      "subsection Materials\n set Material ids = 3\n subsection Material 3\n" +
      material_text + "\n end\nend\n";
  std::string message;
  try
  {
    MaterialLibrary::parse_input_from_string(prm, text);
    MaterialLibrary library;
    library.parse_parameters(prm);
    library.get(7);
  }
  catch (const InputError &e)
  {
    message = e.what();
  }
  catch (const ExceptionBase &e)
  {
    std::ostringstream out;
    e.print_info(out);
    message = out.str();
  }
  SG_CHECK(!message.empty(), label + ": no error was raised");
  SG_CHECK(message.find(must_contain) != std::string::npos,
           label + ": message does not mention '" + must_contain +
               "': " + message);
  deallog << label << ":" << std::endl << "  " << message << std::endl;
}

int
main()
{
  softgrasp_tests::initlog();
  const std::string vol = "set Density = 1000\nsubsection Volumetric\nset "
                          "Poisson's ratio = 0.45\nend\n";
  expect_error("unknown model",
               "set Model = neo-Hooke\n" + vol,
               "Valid names are: Holzapfel-Gasser-Ogden, Mooney-Rivlin, "
               "Ogden, Veronda-Westmann, Yeoh, neo-Hookean");
  expect_error("model not set", vol, "'Materials/Material 3/Model' is not set");
  expect_error("missing modulus",
               "set Model = neo-Hookean\n" + vol,
               "'Materials/Material 3/neo-Hookean/Shear modulus' is not set");
  expect_error("negative modulus",
               "set Model = Mooney-Rivlin\n" + vol +
                   "subsection Mooney-Rivlin\nset C10 = -5\nset C01 = 0\nend",
               "range (0, inf) Pa");
  expect_error("malformed number",
               "set Model = neo-Hookean\n" + vol +
                   "subsection neo-Hookean\nset Shear modulus = 1e4Pa\nend",
               "not a finite number");
  expect_error("Poisson's ratio 0.5",
               "set Model = neo-Hookean\nset Density = 1000\nsubsection "
               "Volumetric\nset Poisson's ratio = 0.5\nend\nsubsection "
               "neo-Hookean\nset Shear modulus = 1e4\nend",
               "outside its allowed range [-1, 0.5)");
  expect_error("both bulk modulus and Poisson's ratio",
               "set Model = neo-Hookean\nset Density = 1000\nsubsection "
               "Volumetric\nset Poisson's ratio = 0.3\nset Bulk modulus = "
               "1e5\nend\nsubsection neo-Hookean\nset Shear modulus = 1e4\nend",
               "both are set");
  expect_error("missing density",
               "set Model = neo-Hookean\nsubsection Volumetric\nset Poisson's "
               "ratio = 0.3\nend\nsubsection neo-Hookean\nset Shear modulus = "
               "1e4\nend",
               "'Materials/Material 3/Density' is not set");
  expect_error(
      "Ogden lists of different length",
      "set Model = Ogden\n" + vol +
          "subsection Ogden\nset Moduli = 1e3, 2e3\nset Exponents = 2\nend",
      "must have the same length");
  expect_error(
      "Ogden unstable term",
      "set Model = Ogden\n" + vol +
          "subsection Ogden\nset Moduli = 1e3\nset Exponents = -2\nend",
      "mu_p alpha_p must be positive");
  expect_error("HGO dispersion out of range",
               "set Model = Holzapfel-Gasser-Ogden\n" + vol +
                   "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = "
                   "1e3\nset k1 = 1e3\nset k2 = 1\nset Dispersion kappa = "
                   "0.5\nend",
               "outside its allowed range [0, 0.333333]");
  expect_error("unknown preset", "set Preset = skn", "skn");
  expect_error("misspelled entry",
               "set Model = neo-Hookean\n" + vol +
                   "subsection neo-Hookean\nset Shear modulos = 1e4\nend",
               "Shear modulos");
  expect_error("material id without a material",
               "set Preset = skin",
               "configures materials only for ids {3}");
  deallog << "OK" << std::endl;
}
