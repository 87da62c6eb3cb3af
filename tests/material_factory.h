// Test helper: build a material from a .prm fragment of one material
// subsection, through the same parser users go through.
#ifndef softgrasp_tests_material_factory_h
#define softgrasp_tests_material_factory_h

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <memory>
#include <softgrasp/materials/material_library.h>
#include <string>
#include <vector>

namespace softgrasp_tests
{
  /// The right stretch U = C^{1/2}, a deformation gradient with C (stress
  /// depends on C only).
  inline dealii::Tensor<2, 3>
  stretch_from_C(const dealii::SymmetricTensor<2, 3> &C)
  {
    const auto                    eig = dealii::eigenvectors(C);
    dealii::SymmetricTensor<2, 3> U;
    for (const auto &p : eig)
      U += std::sqrt(p.first) *
           dealii::symmetrize(dealii::outer_product(p.second, p.second));
    return dealii::Tensor<2, 3>(U);
  }

  /// A random deformation gradient F = I + H, the entries of H drawn from
  /// @p u with @p random, redrawn until det F >= 0.5.
  template <typename Random, typename Distribution>
  dealii::Tensor<2, 3> random_deformation(Random &random, Distribution &u)
  {
    dealii::Tensor<2, 3> f;
    do
    {
      f = dealii::unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          f[i][j] += u(random);
    } while (determinant(f) < 0.5);
    return f;
  }

  inline std::shared_ptr<const softgrasp::Material>
  material_from_prm(const std::string &fragment)
  {
    dealii::ParameterHandler prm;
    softgrasp::MaterialLibrary::declare_parameters(prm);
    softgrasp::MaterialLibrary::parse_input_from_string(
        prm,
        "subsection Materials\n set Material ids = 0\n subsection Material "
        "0\n" +
            fragment + "\n end\nend\n");
    softgrasp::MaterialLibrary library;
    library.parse_parameters(prm);
    return library.get_shared(0);
  }

  /// A material library with material id i configured by @p fragments[i].
  inline softgrasp::MaterialLibrary
  library_from_prm(const std::vector<std::string> &fragments)
  {
    dealii::ParameterHandler prm;
    softgrasp::MaterialLibrary::declare_parameters(prm);
    std::string ids, sections;
    for (unsigned int i = 0; i < fragments.size(); ++i)
    {
      ids += (i ? ", " : "") + std::to_string(i);
      sections += " subsection Material " + std::to_string(i) + "\n" +
                  fragments[i] + "\n end\n";
    }
    softgrasp::MaterialLibrary::parse_input_from_string(
        prm,
        "subsection Materials\n set Material ids = " + ids + "\n" + sections +
            "end\n");
    softgrasp::MaterialLibrary library;
    library.parse_parameters(prm);
    return library;
  }

  /// One representative parameter set per registered model (and both HGO
  /// variants), with a given volumetric energy and Poisson's ratio.
  inline std::vector<std::pair<std::string, std::string>>
  model_fragments(const std::string &volumetric = "Simo-Taylor",
                  const std::string &poisson    = "0.45")
  {
    const std::string vol = "set Density = 1000\nsubsection Volumetric\nset "
                            "Energy = " +
                            volumetric + "\nset Poisson's ratio = " + poisson +
                            "\nend\n";
    return {
        {"neo-Hookean",
         "set Model = neo-Hookean\n" + vol +
             "subsection neo-Hookean\nset Shear modulus = 1e4\nend"},
        {"Mooney-Rivlin",
         "set Model = Mooney-Rivlin\n" + vol +
             "subsection Mooney-Rivlin\nset C10 = 4e3\nset C01 = 1e3\nend"},
        {"Ogden",
         "set Model = Ogden\n" + vol +
             "subsection Ogden\nset Moduli = 6.3e3, 0.012e3, -0.1e3\nset "
             "Exponents = 1.3, 5.0, -2.0\nend"},
        {"Yeoh",
         "set Model = Yeoh\n" + vol +
             "subsection Yeoh\nset Coefficients = 5e3, -1e2, 20\nend"},
        {"Veronda-Westmann",
         "set Model = Veronda-Westmann\n" + vol +
             "subsection Veronda-Westmann\nset C1 = 2e3\nset C2 = 5\nend"},
        {"Holzapfel-Gasser-Ogden (1 family)",
         "set Model = Holzapfel-Gasser-Ogden\n" + vol +
             "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = 1e4\nset "
             "k1 "
             "= 5e4\nset k2 = 2\nset Dispersion kappa = 0.1\nsubsection Fibre "
             "direction 1\nset Function expression = 1; 1; 0\nend\nend"},
        {"Holzapfel-Gasser-Ogden (2 families)",
         "set Model = Holzapfel-Gasser-Ogden\n" + vol +
             "subsection Holzapfel-Gasser-Ogden\nset Shear modulus = 1e4\nset "
             "k1 "
             "= 5e4\nset k2 = 2\nset Number of fibre families = 2\nsubsection "
             "Fibre direction 1\nset Function expression = 1; 0.5; 0\nend\n"
             "subsection Fibre direction 2\nset Function expression = 1; -0.5; "
             "0.2\nend\nend"}};
  }
} // namespace softgrasp_tests

#endif
