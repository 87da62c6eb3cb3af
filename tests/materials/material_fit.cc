// MaterialFit recovers the parameters of a model from stress-stretch
// points of the incompressible closed forms (not from the library):
// Mooney-Rivlin in uniaxial tension, unconfined compression and
// equibiaxial tension, and a two-term Ogden solid that stiffens in
// compression. The library's materials are nearly incompressible here
// (kappa = 10^5 mu_0), so the recovered values agree within 1e-3. Bad
// tables and entries stop with an error naming the cause.

#include "../tests.h"

#include <cmath>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/materials/material_fit.h>
#include <softgrasp/materials/material_library.h>

using namespace dealii;
using namespace softgrasp;

namespace
{
  /// A parameter handler with material 0 given by @p material_text.
  void parse(ParameterHandler &prm, const std::string &material_text)
  {
    MaterialLibrary::declare_parameters(prm);
    MaterialLibrary::parse_input_from_string(
        prm,
        "subsection Materials\n set Material ids = 0\n subsection Material "
        "0\n  set Density = 1000\n" +
            material_text + "\n end\nend\n");
  }

  /// Points of @p stress (closed form) at stretches from @p from to @p to.
  template <typename Stress>
  void add_points(std::vector<StressStretchPoint> &data,
                  const HomogeneousTest            test,
                  const double                     from,
                  const double                     to,
                  const unsigned int               n,
                  const Stress                    &stress)
  {
    for (unsigned int k = 0; k < n; ++k)
    {
      const double l = from + (to - from) * k / (n - 1);
      data.push_back({test, l, stress(l)});
    }
  }

  /// Fit, log and check the recovered values against @p exact.
  void check_fit(const std::string                      &label,
                 ParameterHandler                       &prm,
                 const std::vector<std::string>         &entries,
                 const std::vector<StressStretchPoint>  &data,
                 const std::vector<std::vector<double>> &exact)
  {
    MaterialFit fit(prm, 0, entries);
    const auto  result = fit.fit(data, MaterialFit::Options());
    deallog << label << ": " << result.status << std::endl;
    SG_CHECK(result.converged, label + ": the fit converged");
    double worst = 0;
    for (std::size_t e = 0; e < exact.size(); ++e)
      for (std::size_t k = 0; k < exact[e].size(); ++k)
      {
        const double relative = std::abs(result.values[e][k] / exact[e][k] - 1);
        worst                 = std::max(worst, relative);
        deallog << "  " << entries[e] << "[" << k
                << "] = " << std::setprecision(4) << result.values[e][k]
                << " (exact " << exact[e][k] << ")" << std::endl;
      }
    deallog << "  parameters within 1e-3: " << (worst < 1e-3 ? "yes" : "no")
            << "; largest residual below 1e-3: "
            << (result.max_error < 1e-3 ? "yes" : "no") << std::endl;
    SG_CHECK(worst < 1e-3, label + ": parameters within 1e-3");
    SG_CHECK(result.max_error < 1e-3, label + ": residuals within 1e-3");
  }

  void mooney_rivlin()
  {
    const double                    C10 = 2e3, C01 = 5e2; // Pa
    std::vector<StressStretchPoint> data;
    // incompressible: P = 2 (l - l^-2)(C10 + C01 / l) in uniaxial stress,
    // P = 2 (l - l^-5)(C10 + C01 l^2) in equibiaxial stress
    add_points(data,
               HomogeneousTest::uniaxial,
               0.6,
               1.8,
               13,
               [&](double l)
               { return 2 * (l - 1 / (l * l)) * (C10 + C01 / l); });
    add_points(data,
               HomogeneousTest::equibiaxial,
               1.05,
               1.5,
               10,
               [&](double l)
               { return 2 * (l - std::pow(l, -5)) * (C10 + C01 * l * l); });
    ParameterHandler prm;
    parse(prm,
          "set Model = Mooney-Rivlin\nsubsection Volumetric\n set Bulk "
          "modulus = 5e8\nend\nsubsection Mooney-Rivlin\n set C10 = 1e3\n "
          "set C01 = 1e3\nend");
    check_fit("Mooney-Rivlin",
              prm,
              {"Mooney-Rivlin/C10", "Mooney-Rivlin/C01"},
              data,
              {{C10}, {C01}});
  }

  void ogden()
  {
    // W = sum mu_p / alpha_p (sum_i l_i^alpha_p - 3); the second term
    // stiffens the solid in compression
    const std::vector<double> mu = {1500, -300}, alpha = {6, -4};
    const auto                uniaxial = [&](double l)
    {
      double P = 0;
      for (unsigned int p = 0; p < 2; ++p)
        P += mu[p] *
             (std::pow(l, alpha[p] - 1) - std::pow(l, -alpha[p] / 2 - 1));
      return P;
    };
    const auto equibiaxial = [&](double l)
    {
      double P = 0;
      for (unsigned int p = 0; p < 2; ++p)
        P += mu[p] *
             (std::pow(l, alpha[p] - 1) - std::pow(l, -2 * alpha[p] - 1));
      return P;
    };
    std::vector<StressStretchPoint> data;
    add_points(data, HomogeneousTest::uniaxial, 0.5, 1.5, 11, uniaxial);
    add_points(data, HomogeneousTest::equibiaxial, 1.05, 1.3, 6, equibiaxial);
    ParameterHandler prm;
    parse(prm,
          "set Model = Ogden\nsubsection Volumetric\n set Bulk modulus = "
          "6e8\nend\nsubsection Ogden\n set Moduli = 1000, -100\n set "
          "Exponents = 4, -2\nend");
    check_fit("Ogden, two terms",
              prm,
              {"Ogden/Moduli", "Ogden/Exponents"},
              data,
              {mu, alpha});
    deallog << "  compression at l = 0.5: P = " << std::setprecision(5)
            << uniaxial(0.5) << " Pa" << std::endl;
  }

  /// The error of @p action, which must contain @p must_contain.
  template <typename Action>
  void expect_error(const std::string &label,
                    const Action      &action,
                    const std::string &must_contain)
  {
    std::string message;
    try
    {
      action();
    }
    catch (const InputError &e)
    {
      message = e.what();
    }
    SG_CHECK(message.find(must_contain) != std::string::npos,
             label + ": message does not mention '" + must_contain +
                 "': " + message);
    deallog << label << ":" << std::endl << "  " << message << std::endl;
  }

  /// A table file with @p text.
  std::string table(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
    return name;
  }

  void bad_input()
  {
    const std::string header = "# source\ntest,stretch,nominal_stress_Pa\n";
    expect_error(
        "missing table",
        [] { read_stress_stretch_table("no_such_table.csv"); },
        "no such file");
    expect_error(
        "wrong header",
        [] { read_stress_stretch_table(table("h.csv", "l,P\n1.1,2\n")); },
        "the header is 'l,P'");
    expect_error(
        "unknown test",
        [&] {
          read_stress_stretch_table(table("t.csv", header + "shear,1.1,5\n"));
        },
        "line 3: unknown test 'shear'");
    expect_error(
        "strain for stretch",
        [&] {
          read_stress_stretch_table(
              table("s.csv", header + "uniaxial,-0.1,5\n"));
        },
        "is not a positive number");
    expect_error(
        "stress not a number",
        [&] {
          read_stress_stretch_table(
              table("n.csv", header + "uniaxial,1.1,5 kPa\n"));
        },
        "'5 kPa' is not a finite number");
    const std::string neo =
        "set Model = neo-Hookean\nsubsection Volumetric\n set Poisson's "
        "ratio = 0.45\nend\nsubsection neo-Hookean\n set Shear modulus = "
        "1e3\nend";
    expect_error(
        "unknown entry",
        [&]
        {
          ParameterHandler prm;
          parse(prm, neo);
          MaterialFit fit(prm, 0, {"neo-Hookean/Shear modulos"});
        },
        "is not an entry of the material");
    expect_error(
        "empty entry",
        [&]
        {
          ParameterHandler prm;
          parse(prm, neo);
          MaterialFit fit(prm, 0, {"neo-Hookean/Shear modulus", ""});
        },
        "An entry to fit is empty");
    expect_error(
        "too few points",
        [&]
        {
          ParameterHandler prm;
          parse(prm, neo);
          MaterialFit fit(prm, 0, {"neo-Hookean/Shear modulus"});
          fit.fit({}, MaterialFit::Options());
        },
        "needs at least as many points");
    expect_error(
        "refused start",
        [&]
        {
          ParameterHandler prm;
          parse(prm, neo);
          prm.enter_subsection("Materials");
          prm.enter_subsection("Material 0");
          prm.enter_subsection("neo-Hookean");
          prm.set("Shear modulus", "-1e3");
          for (unsigned int k = 0; k < 3; ++k)
            prm.leave_subsection();
          MaterialFit fit(prm, 0, {"neo-Hookean/Shear modulus"});
          fit.fit({{HomogeneousTest::uniaxial, 1.1, 100}},
                  MaterialFit::Options());
        },
        "The start values of the fit are refused");
  }
  /// A material the model refuses leaves the parameter handler where it
  /// was: the next trial of a fit reads its entries again.
  void usable_after_refusal()
  {
    ParameterHandler prm;
    parse(prm,
          "set Model = neo-Hookean\nsubsection Volumetric\n set Poisson's "
          "ratio = 0.45\nend\nsubsection neo-Hookean\n set Shear modulus = "
          "1e3\nend");
    MaterialFit fit(prm, 0, {"neo-Hookean/Shear modulus"});
    bool        refused = false;
    try
    {
      fit.material({{-1e3}});
    }
    catch (const InputError &)
    {
      refused = true;
    }
    SG_CHECK(refused, "a negative shear modulus is refused");
    const double mu = fit.material({{2e3}})->initial_shear_modulus();
    deallog << "after a refused modulus the next trial has mu_0 = " << mu
            << " Pa" << std::endl;
    SG_CHECK(std::abs(mu - 2e3) < 1e-9, "the next trial is read");
  }
} // namespace

int
main()
{
  softgrasp_tests::initlog();
  mooney_rivlin();
  ogden();
  bad_input();
  usable_after_refusal();
}
