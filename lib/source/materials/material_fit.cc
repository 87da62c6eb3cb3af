#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/scoped_subsection.h>
#include <softgrasp/materials/homogeneous_loading.h>
#include <softgrasp/materials/material_fit.h>
#include <softgrasp/materials/material_library.h>
#include <sstream>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// A finite number in @p text, or nullopt-like false.
    bool parse_number(const std::string &text, double &value)
    {
      const std::string trimmed = Utilities::trim(text);
      if (trimmed.empty())
        return false;
      char *end = nullptr;
      value     = std::strtod(trimmed.c_str(), &end);
      return end == trimmed.c_str() + trimmed.size() && std::isfinite(value);
    }

    /// The parts of "a/b/c": {"a", "b", "c"}.
    std::vector<std::string> path_parts(const std::string &path)
    {
      std::vector<std::string> parts;
      std::stringstream        in(path);
      std::string              part;
      while (std::getline(in, part, '/'))
        parts.push_back(Utilities::trim(part));
      return parts;
    }

    /// Numbers as an entry's text, to round-trip exactly.
    std::string joined(const std::vector<double> &values)
    {
      std::ostringstream out;
      out << std::setprecision(17);
      for (std::size_t k = 0; k < values.size(); ++k)
        out << (k > 0 ? ", " : "") << values[k];
      return out.str();
    }

    /// The residuals of a fit for Eigen's Levenberg-Marquardt: unknowns are
    /// the parameters divided by their start values.
    struct Residuals : Eigen::DenseFunctor<double>
    {
      Residuals(MaterialFit                            &fit,
                const std::vector<StressStretchPoint>  &data,
                const std::vector<std::vector<double>> &start,
                const double                            floor)
          : Eigen::DenseFunctor<double>(count(start), data.size())
          , fit(fit)
          , data(data)
          , start(start)
          , floor(floor)
      {
      }

      static int count(const std::vector<std::vector<double>> &values)
      {
        int n = 0;
        for (const auto &v : values)
          n += v.size();
        return n;
      }

      /// The parameters of the scaled unknowns @p x.
      std::vector<std::vector<double>> parameters(const InputType &x) const
      {
        auto values = start;
        int  k      = 0;
        for (auto &entry : values)
          for (auto &v : entry)
            v *= x[k++];
        return values;
      }

      /// Residual of point @p i for a model stress @p p.
      double residual(const std::size_t i, const double p) const
      {
        const double measured = data[i].nominal_stress;
        return (p - measured) / std::max(std::abs(measured), floor);
      }

      int operator()(const InputType &x, ValueType &r) const
      {
        ++evaluations;
        try
        {
          const auto material = fit.material(parameters(x));
          for (std::size_t i = 0; i < data.size(); ++i)
            r[i] = residual(i,
                            MaterialFit::nominal_stress(
                                *material, data[i].test, data[i].stretch));
        }
        catch (const InputError &)
        {
          // refused parameters or no homogeneous state: far from any fit
          r.setConstant(1e3);
        }
        catch (const InvertedMaterialState &)
        {
          r.setConstant(1e3);
        }
        return 0;
      }

      MaterialFit                            &fit;
      const std::vector<StressStretchPoint>  &data;
      const std::vector<std::vector<double>> &start;
      const double                            floor;
      mutable unsigned int                    evaluations = 0;
    };

    std::string status_text(const Eigen::LevenbergMarquardtSpace::Status s)
    {
      using namespace Eigen::LevenbergMarquardtSpace;
      switch (s)
      {
      case RelativeReductionTooSmall:
        return "the sum of squares no longer decreases (converged)";
      case RelativeErrorTooSmall:
        return "the parameters no longer change (converged)";
      case RelativeErrorAndReductionTooSmall:
        return "parameters and sum of squares settled (converged)";
      case CosinusTooSmall:
        return "the residuals are orthogonal to the Jacobian (converged)";
      case TooManyFunctionEvaluation:
        return "stopped at the evaluation limit";
      case FtolTooSmall:
      case XtolTooSmall:
      case GtolTooSmall:
        return "no further reduction possible at machine precision";
      default:
        return "stopped (improper input)";
      }
    }
  } // namespace

  std::vector<StressStretchPoint>
  read_stress_stretch_table(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(
          "Cannot read the stress-stretch table '" + filename + "'" +
          (std::filesystem::exists(filename) ? " (no permission)."
                                             : " (no such file).") +
          " Fix: give the path of an existing CSV file with the header "
          "'test,stretch,nominal_stress_Pa' (a program's 'Data file' is "
          "relative to its parameter file).");
    std::vector<StressStretchPoint> points;
    std::string                     line;
    bool                            header = false;
    for (unsigned int number = 1; std::getline(in, line); ++number)
    {
      const std::string trimmed = Utilities::trim(line);
      if (trimmed.empty() || trimmed[0] == '#')
        continue;
      const std::string where =
          "In '" + filename + "', line " + std::to_string(number) + ": ";
      if (!header)
      {
        if (trimmed != "test,stretch,nominal_stress_Pa")
          throw InputError(where + "the header is '" + trimmed +
                           "'. Fix: make the first line that is not a "
                           "comment 'test,stretch,nominal_stress_Pa'.");
        header = true;
        continue;
      }
      const auto fields = Utilities::split_string_list(trimmed, ',');
      if (fields.size() != 3)
        throw InputError(where +
                         "expected 3 fields (test, stretch, nominal "
                         "stress in Pa), found " +
                         std::to_string(fields.size()) + ".");
      StressStretchPoint point;
      if (fields[0] == "uniaxial")
        point.test = HomogeneousTest::uniaxial;
      else if (fields[0] == "equibiaxial")
        point.test = HomogeneousTest::equibiaxial;
      else
        throw InputError(where + "unknown test '" + fields[0] +
                         "'. Fix: use 'uniaxial' or 'equibiaxial'.");
      if (!parse_number(fields[1], point.stretch) || point.stretch <= 0)
        throw InputError(where + "the stretch '" + fields[1] +
                         "' is not a positive number. Fix: give the stretch "
                         "l (1), not the strain.");
      if (!parse_number(fields[2], point.nominal_stress))
        throw InputError(where + "the nominal stress '" + fields[2] +
                         "' is not a finite number (Pa).");
      points.push_back(point);
    }
    if (points.empty())
      throw InputError("The stress-stretch table '" + filename +
                       "' holds no data rows. Fix: add rows 'test,stretch,"
                       "nominal_stress_Pa' after the header.");
    return points;
  }

  MaterialFit::MaterialFit(ParameterHandler               &prm,
                           const types::material_id        id,
                           const std::vector<std::string> &entries)
      : prm(prm)
      , section("Material " + std::to_string(static_cast<unsigned int>(id)))
      , entries(entries)
  {
    if (entries.empty())
      throw InputError("No entries to fit. Fix: name at least one numeric "
                       "entry of 'Materials/" +
                       section + "', such as 'Ogden/Moduli'.");
    for (const auto &entry : entries)
    {
      const auto parts = path_parts(entry);
      if (parts.empty() || parts.back().empty())
        throw InputError("An entry to fit is empty ('" + entry +
                         "'). Fix: name entries of 'Materials/" + section +
                         "' separated by commas, such as 'Ogden/Moduli'.");
      std::string text;
      try
      {
        const auto scope = enter({parts.begin(), parts.end() - 1});
        text             = prm.get(parts.back());
        // get() of an undeclared entry gives "" in release builds; set()
        // throws
        prm.set(parts.back(), text);
      }
      catch (const std::exception &)
      {
        throw InputError("'Materials/" + section + "/" + entry +
                         "' is not an entry of the material. Fix: name an "
                         "entry of its model's subsection, such as "
                         "'Ogden/Moduli' or 'neo-Hookean/Shear modulus'.");
      }
      std::vector<double> values;
      for (const auto &field : Utilities::split_string_list(text, ','))
      {
        double value = 0;
        if (!parse_number(field, value))
          throw InputError("'Materials/" + section + "/" + entry + "' = '" +
                           text +
                           "' is not a list of numbers. Fix: set it "
                           "to the start values of the fit.");
        if (value == 0)
          throw InputError("'Materials/" + section + "/" + entry +
                           "' has a start value 0, which gives the fit no "
                           "scale. Fix: start from a nonzero estimate.");
        values.push_back(value);
      }
      if (values.empty())
        throw InputError("'Materials/" + section + "/" + entry +
                         "' is empty. Fix: set it to the start values.");
      start.push_back(values);
    }
  }

  std::vector<std::unique_ptr<ScopedSubsection>>
  MaterialFit::enter(const std::vector<std::string> &subsections) const
  {
    std::vector<std::unique_ptr<ScopedSubsection>> scope;
    scope.push_back(std::make_unique<ScopedSubsection>(prm, "Materials"));
    scope.push_back(std::make_unique<ScopedSubsection>(prm, section));
    for (const auto &name : subsections)
      scope.push_back(std::make_unique<ScopedSubsection>(prm, name));
    return scope;
  }

  void MaterialFit::set_entries(const std::vector<std::vector<double>> &values)
  {
    for (std::size_t e = 0; e < entries.size(); ++e)
    {
      const auto parts = path_parts(entries[e]);
      const auto scope = enter({parts.begin(), parts.end() - 1});
      prm.set(parts.back(), joined(values[e]));
    }
  }

  std::shared_ptr<const Material>
  MaterialFit::material(const std::vector<std::vector<double>> &values)
  {
    set_entries(values);
    const auto scope = enter({});
    return MaterialLibrary::create_material(prm, "Materials/" + section, "fit");
  }

  double MaterialFit::nominal_stress(const Material       &material,
                                     const HomogeneousTest test,
                                     const double          stretch)
  {
    const StructuralDirections directions =
        material.structural_directions(Point<3>());
    return test == HomogeneousTest::uniaxial
               ? HomogeneousLoading::uniaxial(material, directions, stretch)
                     .nominal_stress
               : HomogeneousLoading::equibiaxial(material, directions, stretch)
                     .nominal_stress;
  }

  std::string MaterialFit::name(const HomogeneousTest test)
  {
    return test == HomogeneousTest::uniaxial ? "uniaxial" : "equibiaxial";
  }

  MaterialFit::Result
  MaterialFit::fit(const std::vector<StressStretchPoint> &data,
                   const Options                         &options)
  {
    const int n = Residuals::count(start);
    if (data.size() < static_cast<std::size_t>(n))
      throw InputError("The fit has " + std::to_string(n) +
                       " free parameters and needs at least as many points; "
                       "the table has " +
                       std::to_string(data.size()) +
                       ". Fix: fit fewer entries or add data.");
    double largest = 0;
    for (const auto &point : data)
      largest = std::max(largest, std::abs(point.nominal_stress));
    if (largest == 0)
      throw InputError("Every measured stress is zero: nothing to fit.");

    // the start must be a material the model accepts
    try
    {
      const auto first = material(start);
      for (const auto &point : data)
        nominal_stress(*first, point.test, point.stretch);
    }
    catch (const InputError &e)
    {
      throw InputError(std::string("The start values of the fit are "
                                   "refused: ") +
                       e.what());
    }

    Residuals residuals(*this, data, start, options.stress_floor * largest);
    Eigen::NumericalDiff<Residuals, Eigen::Central> functor(residuals);
    Eigen::LevenbergMarquardt<decltype(functor)>    lm(functor);
    lm.setMaxfev(options.max_evaluations);
    lm.setXtol(options.tolerance);
    lm.setFtol(options.tolerance);
    Eigen::VectorXd x      = Eigen::VectorXd::Ones(n);
    const auto      status = lm.minimize(x);

    Result result;
    result.entries     = entries;
    result.values      = residuals.parameters(x);
    result.evaluations = functor.evaluations;
    result.status      = status_text(status);
    result.converged   = status >= 1 && status <= 4;
    const auto fitted  = material(result.values);
    double     sum     = 0;
    for (std::size_t i = 0; i < data.size(); ++i)
    {
      const double p = nominal_stress(*fitted, data[i].test, data[i].stretch);
      result.model_stress.push_back(p);
      const double r = residuals.residual(i, p);
      sum += r * r;
      result.max_error = std::max(result.max_error, std::abs(r));
    }
    result.rms_error = std::sqrt(sum / data.size());
    return result;
  }

  std::string MaterialFit::Result::prm_lines() const
  {
    // entries in the same subsection share one block: close the
    // subsections the next entry is not in, open those it is in
    std::ostringstream       out;
    std::vector<std::string> open; // the subsections entered so far
    const auto               indent = [](const std::size_t depth)
    { return std::string(2 * depth, ' '); };
    for (std::size_t e = 0; e <= entries.size(); ++e)
    {
      std::vector<std::string>       parts = e < entries.size()
                                                 ? path_parts(entries[e])
                                                 : std::vector<std::string>{""};
      const std::vector<std::string> path(parts.begin(), parts.end() - 1);
      std::size_t                    common = 0;
      while (common < open.size() && common < path.size() &&
             open[common] == path[common])
        ++common;
      for (; open.size() > common; open.pop_back())
        out << indent(open.size() - 1) << "end\n";
      for (; open.size() < path.size(); open.push_back(path[open.size()]))
        out << indent(open.size()) << "subsection " << path[open.size()]
            << "\n";
      if (e == entries.size())
        break;
      out << indent(open.size()) << "set " << parts.back() << " = "
          << std::setprecision(8);
      for (std::size_t k = 0; k < values[e].size(); ++k)
        out << (k > 0 ? ", " : "") << values[e][k];
      out << "\n";
    }
    return out.str();
  }
} // namespace softgrasp
