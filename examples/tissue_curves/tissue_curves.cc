/* ---------------------------------------------------------------------
 * softgrasp example: tissue_curves
 *
 * Stress-stretch curves of every tissue preset of the softgrasp material
 * library (and of any material defined in the parameter file), under
 * uniaxial and equibiaxial stress.
 * --------------------------------------------------------------------- */

// @sect3{Introduction}
//
// Before a robot hand squeezes an arm in a finite element model, it pays to
// look at how the tissues in that model respond to stretch. This program
// takes every preset of softgrasp's tissue library (skin, subcutaneous fat,
// skeletal muscle, fascia, ligament, natural rubber, cortical bone) plus
// the materials of the parameter file, and computes two homogeneous stress
// states for a range of stretches l:
//
//  - uniaxial stress: F = diag(l, l2, l3) with sigma_22 = sigma_33 = 0;
//  - equibiaxial stress: F = diag(l, l, l3) with sigma_33 = 0.
//
// The free stretches are found by Newton's method with the material's
// consistent tangent (softgrasp::HomogeneousLoading). Fibre-reinforced
// presets (muscle, fascia, ligament) have their fibres along x, the loading
// axis. The results go to a CSV file and, with gnuplot, to PNG plots.
//
// Run it as
//   ./tissue_curves tissue_curves.prm

// @sect3{Include files}

#include <cstdlib>
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
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/materials/tissue_presets.h>

using namespace dealii;
using namespace softgrasp;

// @sect3{Parameters}
//
// The program's own parameters, each with its unit. The material
// subsections are declared by the MaterialLibrary.
struct Parameters
{
  std::string              output_directory;
  double                   min_stretch = 0.7; // 1
  double                   max_stretch = 1.6; // 1
  unsigned int             n_points    = 19;
  std::vector<std::string> presets;
  bool                     plot = true;

  static void declare(ParameterHandler &prm)
  {
    prm.declare_entry("Output directory",
                      "tissue_curves_output",
                      Patterns::DirectoryName(),
                      "Directory for the CSV file and the plots.");
    prm.declare_entry("Minimum stretch",
                      "0.7",
                      Patterns::Double(0.05),
                      "Smallest stretch of each curve. Unit: 1.");
    prm.declare_entry("Maximum stretch",
                      "1.6",
                      Patterns::Double(0.05),
                      "Largest stretch of each curve. Unit: 1.");
    prm.declare_entry("Number of points",
                      "19",
                      Patterns::Integer(2, 100000),
                      "Points per curve (at most 1e5: a plot cannot show "
                      "more). Unit: 1.");
    prm.declare_entry("Presets",
                      "all",
                      Patterns::Anything(),
                      "'all' or a comma-separated list of tissue presets.");
    prm.declare_entry("Plot",
                      "true",
                      Patterns::Bool(),
                      "Run gnuplot to make PNG plots from the CSV file.");
    MaterialLibrary::declare_parameters(prm);
  }

  void parse(ParameterHandler &prm)
  {
    output_directory = prm.get("Output directory");
    min_stretch      = prm.get_double("Minimum stretch");
    max_stretch      = prm.get_double("Maximum stretch");
    n_points         = prm.get_integer("Number of points");
    plot             = prm.get_bool("Plot");
    if (!(min_stretch < max_stretch))
      throw InputError("'Minimum stretch' must be smaller than 'Maximum "
                       "stretch'. Fix: e.g. 0.7 and 1.6.");
    presets.clear();
    if (prm.get("Presets") == "all")
      for (const auto &preset : TissuePresets::all())
        presets.push_back(preset.name);
    else
      presets = Utilities::split_string_list(prm.get("Presets"), ',');
  }
};

// @sect3{Writing the curves}
//
// One row per material, loading mode and stretch. The file is written to a
// temporary name and renamed, so a crash never leaves half a file.
void
write_curves(const Parameters                                   &parameters,
             const std::vector<std::shared_ptr<const Material>> &materials,
             const std::filesystem::path                        &csv)
{
  const std::filesystem::path tmp = csv.string() + ".tmp";
  std::ofstream               out(tmp);
  // gnuplot blocks: one per material, separated by two blank lines
  std::ofstream blocks_uni(csv.parent_path() / "uniaxial.dat"),
      blocks_bi(csv.parent_path() / "equibiaxial.dat");
  out << "material,mode,stretch,nominal_stress_Pa,cauchy_stress_Pa,"
         "free_stretch,normalised_stress\n"
      << std::setprecision(8);

  std::cout << std::left << std::setw(34) << "material" << std::right
            << std::setw(12) << "mu_0 [Pa]" << std::setw(16)
            << "P(1.2) uni [Pa]" << std::setw(16) << "P(1.2) bi [Pa]"
            << std::setw(12) << "c_d [m/s]"
            << "\n";
  for (const auto &material : materials)
  {
    const StructuralDirections fibres =
        material->structural_directions(Point<3>());
    for (unsigned int i = 0; i < parameters.n_points; ++i)
    {
      const double l = parameters.min_stretch +
                       (parameters.max_stretch - parameters.min_stretch) * i /
                           (parameters.n_points - 1.0);
      const auto   uni = HomogeneousLoading::uniaxial(*material, fibres, l);
      const auto   bi  = HomogeneousLoading::equibiaxial(*material, fibres, l);
      const double mu  = material->initial_shear_modulus();
      out << '"' << material->name() << "\",uniaxial," << l << ","
          << uni.nominal_stress << "," << uni.cauchy_stress << ","
          << uni.stretches[1] << "," << uni.nominal_stress / mu << "\n";
      out << '"' << material->name() << "\",equibiaxial," << l << ","
          << bi.nominal_stress << "," << bi.cauchy_stress << ","
          << bi.stretches[2] << "," << bi.nominal_stress / mu << "\n";
      blocks_uni << l << " " << uni.nominal_stress / mu << "\n";
      blocks_bi << l << " " << bi.nominal_stress / mu << "\n";
    }
    blocks_uni << "\n\n";
    blocks_bi << "\n\n";
    const auto uni = HomogeneousLoading::uniaxial(*material, fibres, 1.2);
    const auto bi  = HomogeneousLoading::equibiaxial(*material, fibres, 1.2);
    std::cout << std::left << std::setw(34) << material->name() << std::right
              << std::setprecision(4) << std::setw(12)
              << material->initial_shear_modulus() << std::setw(16)
              << uni.nominal_stress << std::setw(16) << bi.nominal_stress
              << std::setw(12) << material->reference_wave_speed() << "\n";
  }
  out.close();
  std::filesystem::rename(tmp, csv);
}

// @sect3{Plotting}
//
// A gnuplot script: nominal stress normalised by each material's
// small-strain shear modulus mu_0, so that tissues whose moduli differ by
// seven orders of magnitude share one plot.
void
plot_curves(const std::vector<std::shared_ptr<const Material>> &materials,
            const std::filesystem::path                        &dir)
{
  std::ofstream gp(dir / "tissue_curves.gnuplot");
  gp << "set key top left font ',9'\n"
     << "set grid\nset xlabel 'stretch l'\n"
     << "set ylabel 'nominal stress P / mu_0'\nset yrange [-20:60]\n";
  for (const std::string mode : {"uniaxial", "equibiaxial"})
  {
    gp << "set terminal png size 1000,700\nset output '"
       << softgrasp::AtomicFile::temporary_name(mode + ".png")
       << "'\nset title '" << mode << " stress of the tissue presets'\n"
       << "plot ";
    for (unsigned int m = 0; m < materials.size(); ++m)
      gp << (m ? ", " : "") << "'" << mode << ".dat' index " << m
         << " using 1:2 with linespoints title '" << materials[m]->name()
         << "'";
    gp << "\n";
  }
  gp.close();
  if (softgrasp::run_gnuplot(dir.string(),
                             "tissue_curves.gnuplot",
                             {"uniaxial.png", "equibiaxial.png"},
                             std::cout))
    std::cout << "Plots: " << (dir / "uniaxial.png").string() << ", "
              << (dir / "equibiaxial.png").string() << "\n";
}

// @sect3{The main function}
int
main(int argc, char **argv)
{
  try
  {
    ParameterReader::set_program("tissue_curves", {});
    const auto arguments =
        ProgramArguments::parse(argc, argv, "tissue_curves.prm");
    const int exit_code = arguments.handle(
        argv[0],
        "Stress-stretch curves of the tissue models under uniaxial and "
        "equibiaxial loading (no finite elements).",
        true);
    if (exit_code >= 0)
      return exit_code;
    const std::string &prm_file = arguments.parameter_file;
    const bool         print    = arguments.print_parameters;
    const bool         dry_run  = arguments.dry_run;
    ParameterHandler   prm;
    Parameters         parameters;
    Parameters::declare(prm);
    // --print-parameters: every parameter with its documentation, as
    // generated from the code (one material subsection shown).
    if (print)
    {
      MaterialLibrary::print_parameters(prm, std::cout);
      return 0;
    }
    MaterialLibrary::parse_input(prm, prm_file);
    parameters.parse(prm);
    if (dry_run)
    {
      ProgramArguments::report_dry_run("tissue_curves", prm_file, true);
      return 0;
    }

    MaterialLibrary library;
    library.parse_parameters(prm);

    std::vector<std::shared_ptr<const Material>> materials;
    for (const std::string &name : parameters.presets)
      materials.push_back(MaterialLibrary::create_preset(name));
    for (const auto id : library.material_ids())
      materials.push_back(library.get_shared(id));

    const std::filesystem::path dir(parameters.output_directory);
    std::filesystem::create_directories(dir);
    write_curves(parameters, materials, dir / "tissue_curves.csv");
    std::cout << "Curves: " << (dir / "tissue_curves.csv").string() << "\n";
    if (parameters.plot)
      plot_curves(materials, dir);
  }
  catch (const std::exception &e)
  {
    std::cerr << "Error: " << softgrasp::error_message(e) << std::endl;
    return 1;
  }
  return 0;
}
