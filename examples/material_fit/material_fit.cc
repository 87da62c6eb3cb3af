/* ---------------------------------------------------------------------
 * softgrasp example: material_fit
 *
 * Fit the parameters of a material of the softgrasp library to measured
 * stress-stretch points of homogeneous tests, and draw the fit over the
 * data.
 * --------------------------------------------------------------------- */

// @sect3{Introduction}
//
// A preset is only as good as the data behind it. This program takes a
// table of measured points (uniaxial tension or unconfined compression,
// equibiaxial tension: stretch and nominal stress in Pa) and a material
// of the parameter file, and fits the entries it names (for an Ogden
// solid 'Ogden/Moduli' and 'Ogden/Exponents') by least squares
// (softgrasp::MaterialFit). The material is the one a simulation would
// use, compressible with its volumetric energy, loaded homogeneously by
// softgrasp::HomogeneousLoading. It writes
//  - the fitted entries as .prm lines (fitted_material.prm), to paste
//    into a simulation's material subsection;
//  - every data point beside the fit's stress and the relative error
//    (material_fit.csv), and the fitted curve at many stretches;
//  - with gnuplot, a PNG of the curve over the data points;
//  - whether the fitted model is Drucker-stable over the data's stretches
//    (softgrasp::DruckerStability): a fit can be unstable between or
//    beyond its points.
//
// The shipped material_fit.prm fits a three-term Ogden solid to Treloar's
// uniaxial and equibiaxial data of natural rubber (treloar_1944.csv), the
// data of Ogden's classic fit that the library's 'natural rubber' preset
// uses; the fit lands near Ogden's parameters (doc/materials.md).
//
// Run it as
//   ./material_fit material_fit.prm

// @sect3{Include files}

#include <algorithm>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/gnuplot.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/program_arguments.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/materials/drucker_stability.h>
#include <softgrasp/materials/material_fit.h>
#include <softgrasp/materials/material_library.h>

using namespace dealii;
using namespace softgrasp;

// @sect3{Parameters}
//
// The program's own parameters, each with its unit; the material
// subsections are declared by the MaterialLibrary.
struct Parameters
{
  std::string              output_directory;
  std::string              data_file;
  unsigned int             material_id = 0;
  std::vector<std::string> entries;
  MaterialFit::Options     options;
  bool                     plot = true;

  static void declare(ParameterHandler &prm)
  {
    prm.declare_entry("Output directory",
                      "material_fit_output",
                      Patterns::DirectoryName(),
                      "Directory for the fitted entries, the CSV files and "
                      "the plot.");
    prm.declare_entry("Data file",
                      "",
                      Patterns::Anything(),
                      "CSV table of measured points, relative to this "
                      "file's directory: '#' comment lines "
                      "(the source), the header "
                      "'test,stretch,nominal_stress_Pa', then rows of "
                      "'uniaxial' or 'equibiaxial', the stretch (1) and the "
                      "nominal stress (Pa, force over reference area).");
    prm.declare_entry("Material id",
                      "0",
                      Patterns::Integer(0, 255),
                      "The material of 'Materials' to fit. Unit: 1.");
    prm.declare_entry("Fitted entries",
                      "",
                      Patterns::Anything(),
                      "Comma-separated entries of that material, relative "
                      "to its subsection (e.g. 'Ogden/Moduli, "
                      "Ogden/Exponents'); every number of each is a free "
                      "parameter and its value in this file the start.");
    prm.declare_entry("Stress floor",
                      "0.05",
                      Patterns::Double(0, 1),
                      "Each point's error is relative to its stress, but "
                      "to at least this fraction of the largest measured "
                      "stress (so that points near zero stress do not "
                      "dominate). Unit: 1.");
    prm.declare_entry("Maximum evaluations",
                      "4000",
                      Patterns::Integer(1),
                      "Largest number of evaluations of the residuals. "
                      "Unit: 1.");
    prm.declare_entry("Plot",
                      "true",
                      Patterns::Bool(),
                      "Run gnuplot to draw the fit over the data (PNG).");
    MaterialLibrary::declare_parameters(prm);
  }

  /// Read the entries; a relative 'Data file' is taken from the
  /// directory of the parameter file @p prm_file.
  void parse(ParameterHandler &prm, const std::string &prm_file)
  {
    output_directory     = prm.get("Output directory");
    data_file            = Utilities::trim(prm.get("Data file"));
    const auto directory = std::filesystem::path(prm_file).parent_path();
    if (!data_file.empty() && data_file[0] != '/' && !directory.empty())
      data_file = (directory / data_file).string();
    RunManifest::protect_input(data_file);
    material_id = prm.get_integer("Material id");
    entries     = Utilities::split_string_list(prm.get("Fitted entries"));
    options.stress_floor    = prm.get_double("Stress floor");
    options.max_evaluations = prm.get_integer("Maximum evaluations");
    plot                    = prm.get_bool("Plot");
    if (data_file.empty())
      throw InputError("'Data file' is not set. Fix: give the CSV table of "
                       "measured points to fit.");
  }
};

// @sect3{Output}
//
// The data beside the fit, and the fitted curve from the smallest to the
// largest measured stretch of each test.
void
write_results(const std::vector<StressStretchPoint> &data,
              const MaterialFit::Result             &result,
              MaterialFit                           &fit,
              const std::filesystem::path           &dir)
{
  {
    AtomicFile::TextFile out((dir / "material_fit.csv").string());
    out << "test,stretch,measured_nominal_stress_Pa,fitted_nominal_stress_"
           "Pa,relative_error\n"
        << std::setprecision(8);
    for (std::size_t i = 0; i < data.size(); ++i)
      out << MaterialFit::name(data[i].test) << "," << data[i].stretch << ","
          << data[i].nominal_stress << "," << result.model_stress[i] << ","
          << (result.model_stress[i] - data[i].nominal_stress) /
                 data[i].nominal_stress
          << "\n";
    out.commit();
  }
  const auto           material = fit.material(result.values);
  AtomicFile::TextFile out((dir / "fitted_curves.csv").string());
  out << "test,stretch,nominal_stress_Pa\n" << std::setprecision(8);
  for (const auto test :
       {HomogeneousTest::uniaxial, HomogeneousTest::equibiaxial})
  {
    double from = 1e300, to = -1e300;
    for (const auto &point : data)
      if (point.test == test)
      {
        from = std::min(from, point.stretch);
        to   = std::max(to, point.stretch);
      }
    for (unsigned int k = 0; from <= to && k <= 200; ++k)
    {
      const double l = from + (to - from) * k / 200.0;
      out << MaterialFit::name(test) << "," << l << ","
          << MaterialFit::nominal_stress(*material, test, l) << "\n";
    }
  }
  out.commit();
}

// A gnuplot script: the data as points, the fit as lines, one colour per
// test.
void
plot_fit(const std::filesystem::path           &dir,
         const std::vector<StressStretchPoint> &data,
         const MaterialFit::Result             &result)
{
  std::ofstream gp(dir / "material_fit.gnuplot");
  gp << "set datafile separator ','\nset key top left\nset grid\n"
     << "set xlabel 'stretch l'\nset ylabel 'nominal stress P (Pa)'\n"
     << "set terminal png size 900,650\nset output '"
     << AtomicFile::temporary_name("material_fit.png") << "'\n"
     << "set title sprintf('fit: rms error %.3g, largest %.3g', "
     << result.rms_error << ", " << result.max_error << ")\n"
     << "plot ";
  // one series of points and one line for each test in the data
  bool first  = true;
  int  colour = 1;
  for (const auto test :
       {HomogeneousTest::uniaxial, HomogeneousTest::equibiaxial})
  {
    if (std::none_of(data.begin(),
                     data.end(),
                     [&](const auto &point) { return point.test == test; }))
      continue;
    const std::string name = MaterialFit::name(test);
    const std::string x =
        "(strcol(1) eq '" + name + "' ? $2 : NaN):3 every ::1 with ";
    gp << (first ? "" : ", ") << "'material_fit.csv' using " << x
       << "points pt 7 lc " << colour << " title '" << name
       << ", data', 'fitted_curves.csv' using " << x << "lines lw 2 lc "
       << colour << " title '" << name << ", fit'";
    first = false;
    ++colour;
  }
  gp << "\n";
  gp.close();
  if (run_gnuplot(dir.string(),
                  "material_fit.gnuplot",
                  {"material_fit.png"},
                  std::cout))
    std::cout << "Plot: " << (dir / "material_fit.png").string() << "\n";
}

// @sect3{The main function}
int
main(int argc, char **argv)
{
  try
  {
    ParameterReader::set_program("material_fit", {});
    const auto arguments =
        ProgramArguments::parse(argc, argv, "material_fit.prm");
    const int exit_code = arguments.handle(
        argv[0],
        "Least-squares fit of a material's parameters to measured "
        "homogeneous stress-stretch points (no finite elements).",
        true);
    if (exit_code >= 0)
      return exit_code;
    ParameterHandler prm;
    Parameters       parameters;
    Parameters::declare(prm);
    if (arguments.print_parameters)
    {
      MaterialLibrary::print_parameters(prm, std::cout);
      return 0;
    }
    MaterialLibrary::parse_input(prm, arguments.parameter_file);
    parameters.parse(prm, arguments.parameter_file);
    const auto  data = read_stress_stretch_table(parameters.data_file);
    MaterialFit fit(prm, parameters.material_id, parameters.entries);
    if (arguments.dry_run)
    {
      ProgramArguments::report_dry_run(
          "material_fit", arguments.parameter_file, true);
      return 0;
    }

    std::cout << "Fitting " << parameters.entries.size() << " entries to "
              << data.size() << " points of '" << parameters.data_file << "'\n";
    const auto result = fit.fit(data, parameters.options);
    std::cout << "Result: " << result.status << " after " << result.evaluations
              << " evaluations\n"
              << "Error relative to each point's stress (floor "
              << parameters.options.stress_floor << " of the largest): rms "
              << std::setprecision(3) << result.rms_error << ", largest "
              << result.max_error << "\nFitted entries:\n"
              << result.prm_lines();
    // the fitted model may be unstable outside its data: check it over
    // the data's stretches (and l = 1)
    double from = 1, to = 1;
    for (const auto &point : data)
    {
      from = std::min(from, point.stretch);
      to   = std::max(to, point.stretch);
    }
    std::cout << "The fit is "
              << DruckerStability::check(*fit.material(result.values), from, to)
                     .summary(from, to)
              << "\n";
    if (!result.converged)
      std::cout << "Warning: the fit did not converge; the entries above "
                   "are its last iterate. Fix: start closer or raise "
                   "'Maximum evaluations'.\n";

    const std::filesystem::path dir(parameters.output_directory);
    std::filesystem::create_directories(dir);
    {
      AtomicFile::TextFile file((dir / "fitted_material.prm").string());
      file << "# Fitted by material_fit to '" << parameters.data_file
           << "': rms error " << result.rms_error << ", largest "
           << result.max_error << "\n"
           << result.prm_lines();
      file.commit();
    }
    write_results(data, result, fit, dir);
    std::cout << "Results: " << (dir / "material_fit.csv").string() << ", "
              << (dir / "fitted_material.prm").string() << "\n";
    if (parameters.plot)
      plot_fit(dir, data, result);
  }
  catch (const std::exception &e)
  {
    std::cerr << "Error: " << error_message(e) << std::endl;
    return 1;
  }
  return 0;
}
