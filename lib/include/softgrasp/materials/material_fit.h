#ifndef softgrasp_materials_material_fit_h
#define softgrasp_materials_material_fit_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <memory>
#include <softgrasp/base/scoped_subsection.h>
#include <softgrasp/materials/material.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /// A homogeneous test whose stress-stretch points a material is fitted to.
  enum class HomogeneousTest
  {
    uniaxial,   ///< uniaxial stress along x; stretch < 1 is unconfined
                ///< compression
    equibiaxial ///< equal stretch along x and y, no stress along z
  };

  /// One measured point of a homogeneous test: a row of a data table.
  struct StressStretchPoint
  {
    HomogeneousTest test           = HomogeneousTest::uniaxial;
    double          stretch        = 1; ///< l along x (1)
    double          nominal_stress = 0; ///< P_11 (Pa): force/reference area
  };

  /**
   * Read a table of measured points from the CSV file @p filename. Lines
   * starting with '#' are comments (the data's source belongs there); the
   * first other line is the header "test,stretch,nominal_stress_Pa"; each
   * further line is "uniaxial" or "equibiaxial", the stretch (1, > 0) and
   * the nominal stress (Pa). An InputError names the file, the line and
   * the fix for a missing file, a wrong header, an unknown test or a value
   * that is not a finite number.
   */
  std::vector<StressStretchPoint>
  read_stress_stretch_table(const std::string &filename);

  /**
   * Least-squares fit of the parameters of a material of the library to
   * measured homogeneous stress-stretch points. Any model, any numeric
   * entry: the material is the subsection 'Materials/Material <id>' of a
   * parsed parameter file (MaterialLibrary::parse_input(), presets
   * applied), and the fitted entries are named relative to it, e.g.
   * "Ogden/Moduli" or "Neo-Hookean/Shear modulus"; every number of a
   * listed entry is a free parameter, and the values in the file are the
   * start. Each trial material is built by MaterialLibrary::create_material()
   * and loaded by HomogeneousLoading, so the fit sees exactly the response
   * a simulation uses (compressible, with its volumetric energy).
   *
   * The residual of point i is (P_model - P_i) / max(|P_i|, f max_j |P_j|),
   * the relative error with a floor of the fraction f (`stress_floor`) of
   * the largest measured stress, so that points near zero stress do not
   * dominate. Levenberg-Marquardt (Eigen) minimises the sum of squares over
   * the unknowns scaled by their start values (so a start value must not
   * be zero), with a central-difference Jacobian. A trial whose parameters
   * the model refuses (say a negative modulus), or whose homogeneous state
   * does not converge, gets large residuals, so that the minimiser steps
   * back.
   */
  class MaterialFit
  {
  public:
    /// Settings of the least-squares solver.
    struct Options
    {
      double       stress_floor    = 0.05;  ///< f above (1)
      unsigned int max_evaluations = 4000;  ///< material evaluations (1)
      double       tolerance       = 1e-10; ///< relative, on x and the sum
    };

    /// The fitted parameters and how well they fit.
    struct Result
    {
      std::vector<std::string>         entries; ///< as given
      std::vector<std::vector<double>> values;  ///< per entry, its numbers
      std::vector<double> model_stress; ///< P_11 of the fit per point (Pa)
      double       rms_error   = 0; ///< root mean square of the residuals (1)
      double       max_error   = 0; ///< largest |residual| (1)
      unsigned int evaluations = 0; ///< of the set of residuals
      bool         converged   = false; ///< a tolerance was met
      std::string  status;              ///< the minimiser's own words

      /// The fitted entries as .prm lines, to paste into the material's
      /// subsection.
      std::string prm_lines() const;
    };

    /**
     * Prepare the fit of the entries @p entries of material @p id in @p prm
     * (which must outlive this object; fit() changes the entries to the
     * fitted values). Throws an InputError if an entry is not declared or
     * holds no numbers, or a start value is zero.
     */
    MaterialFit(dealii::ParameterHandler        &prm,
                const dealii::types::material_id id,
                const std::vector<std::string>  &entries);

    /// Fit to @p data; at least as many points as unknowns.
    Result fit(const std::vector<StressStretchPoint> &data,
               const Options                         &options);

    /// The material with the entries set to @p values (one list per entry).
    std::shared_ptr<const Material>
    material(const std::vector<std::vector<double>> &values);

    /// Nominal stress P_11 (Pa) of @p material in @p test at @p stretch.
    static double nominal_stress(const Material       &material,
                                 const HomogeneousTest test,
                                 const double          stretch);

    /// The name of @p test as in the data table.
    static std::string name(const HomogeneousTest test);

  private:
    dealii::ParameterHandler        &prm;
    const std::string                section; // "Material <id>"
    std::vector<std::string>         entries;
    std::vector<std::vector<double>> start; // per entry

    /// Enter Materials/Material <id> and then @p subsections (an entry's
    /// path without the entry), until the result is destroyed.
    std::vector<std::unique_ptr<ScopedSubsection>>
    enter(const std::vector<std::string> &subsections) const;

    /// Set the entries in prm to @p values.
    void set_entries(const std::vector<std::vector<double>> &values);
  };
} // namespace softgrasp

#endif
