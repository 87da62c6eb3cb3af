// Shared by the tests of the deep plane-strain drag (drag_potential on the
// nodes, drag_faces_2d on the faces): a rigid cylinder (R = 10 mm) pressed
// 10 mm into a 120 x 20 mm neo-Hookean block (E = 50 kPa, nu = 0.45, Q1
// u-p-J, bonded base) in 0.5 s and pulled 20 mm along it at 20 mm/s,
// mu = 0.5; one run and what every accepted step of it must satisfy.
#ifndef softgrasp_tests_contact_plane_drag_h
#define softgrasp_tests_contact_plane_drag_h

#include "../contact_factory.h"
#include "../solver_factory.h"
#include "../tests.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>

namespace softgrasp_tests
{
  namespace plane_drag
  {
    const double t_press = 0.5, speed = 0.02; // s, m/s

    /// The drag's parameters: @p cells ("40, 8"), the integrator, the time
    /// step @p dt (s; 0.025 s is 0.5 mm of pull), @p contact, lines of
    /// the Contact subsection (the enforcement, the integration, ...), and
    /// @p extra, whole subsections added at the end.
    inline std::string prm(const std::string &cells,
                           const std::string &contact,
                           const std::string &integrator,
                           const double       dt,
                           const std::string &extra = "")
    {
      std::ostringstream s;
      s << frictional_drag_prm(0.5)
        << "subsection Mesh\n subsection Block\n  set Subdivisions = " << cells
        << "\n end\nend\n"
        << "subsection Rigid bodies\n subsection Body finger\n"
        << "  set Trajectory = 0: -0.01, 0.0305, 0, 1, 0, 0, 0; 0.5: -0.01, "
        << "0.0205, 0, 1, 0, 0, 0; 1.5: 0.01, 0.0205, 0, 1, 0, 0, 0"
        << "\n end\nend\n"
        << "subsection Contact\n"
        << contact << "end\n"
        << "subsection Time\n set Integrator = " << integrator
        << "\n set End time = 1.5\n set Time step = " << dt
        << "\n set Maximum cut-backs = 4\nend\n"
        << "subsection Output\n set Directory = output-drag\n"
        << " set VTU interval = 0\n set Verbose = false\nend\n"
        << extra;
      return s.str();
    }

    /// What a run reached.
    struct Drag
    {
      double                pulled = 0; ///< mm, at the last converged step
      std::map<int, double> ratio;      ///< drag/normal at each mm
      std::map<int, double> normal;     ///< normal force at each mm (N/m)
      std::map<int, double> drag;       ///< drag at each mm (N/m)
      /// The explicit integrator's largest relative energy balance error
      /// after the first record.
      double       energy_balance = 0;
      double       first_event    = 1e9; ///< pull at the first stick-slip (mm)
      unsigned int events = 0, unsettled = 0;
      /// The largest Coulomb excess of a step, settled or not (history
      /// 'coulomb_excess': max (|f_t| - mu lambda) / (mu max lambda)).
      double largest_excess = 0;
    };

    /**
     * Run the drag of prm(@p cells, @p contact, @p integrator, @p dt,
     * @p extra). At every record: quasi-statically the support's reaction
     * balances the force on the cylinder; on the potential the potential
     * never rose along a Newton update and Coulomb's law holds against the
     * current normal forces (|f_t| <= mu lambda + 1e-3 mu max lambda)
     * unless the step is reported unsettled; the explicit energy balance
     * is recorded. A run that stops (the semi-smooth path) is kept up to
     * its last converged state.
     */
    inline Drag pull(const std::string &cells,
                     const std::string &contact,
                     const std::string &integrator,
                     const double       dt,
                     const std::string &extra = "")
    {
      const bool quasi_static = integrator == "quasi-static";
      auto run = make_solver<2>(prm(cells, contact, integrator, dt, extra));
      Drag drag;
      try
      {
        run->run();
      }
      catch (const std::exception &)
      {
        // the semi-smooth path stops: its last converged state is recorded
      }
      const auto &records   = run->contact_force_history();
      const auto &history   = run->history();
      const auto &table     = run->contact_history();
      const bool  potential = std::count(history.columns.begin(),
                                        history.columns.end(),
                                        "outer_iterations") > 0;
      for (std::size_t k = 0; k < records.size(); ++k)
      {
        const auto  &f    = records[k].forces[0][0];
        const double t    = records[k].time;
        const double mm   = (t - t_press) * speed * 1e3;
        const double near = std::round(mm);
        if (t > t_press + 1e-9 && std::abs(mm - near) < 1e-6)
        {
          drag.ratio[int(near)]  = std::abs(f.force[0]) / f.normal_force();
          drag.normal[int(near)] = f.normal_force();
          drag.drag[int(near)]   = std::abs(f.force[0]);
        }
        drag.pulled = std::max(drag.pulled, mm);
        if (table.value(k, "stick_slip_drop") > 0)
        {
          ++drag.events;
          drag.first_event = std::min(drag.first_event, mm);
        }
        if (quasi_static && k > 0)
          SG_CHECK((Eigen::Vector2d(history.value(k, "reaction_2_x"),
                                    history.value(k, "reaction_2_y")) -
                    f.force.head<2>())
                           .norm() <= 1e-6 * f.force.norm(),
                   "the support's reaction balances the contact force");
        if (integrator == "explicit dynamic" && t > 0.03)
          drag.energy_balance =
              std::max(drag.energy_balance,
                       std::abs(history.value(k, "energy_balance_error")));
        if (!potential || k == 0)
          continue;
        SG_CHECK(history.value(k, "energy_increases") == 0,
                 "the potential never rose along an update");
        const bool unsettled = history.value(k, "unsettled") > 0;
        drag.unsettled += unsettled;
        drag.largest_excess =
            std::max(drag.largest_excess, history.value(k, "coulomb_excess"));
        SG_CHECK(unsettled || history.value(k, "coulomb_excess") <= 1e-3,
                 "Coulomb's law against the current normal forces");
      }
      return drag;
    }

    /// The largest |a - b| of the values (the ratios by default) at the
    /// millimetres both have in [from, until]; @p agree: each within
    /// rtol |b| + atol.
    inline double
    largest_difference(const Drag           &a,
                       const Drag           &b,
                       const double          from,
                       const double          until,
                       const double          rtol,
                       const double          atol,
                       bool                 &agree,
                       std::map<int, double> Drag::*values = &Drag::ratio)
    {
      double      worst = 0;
      const auto &va = a.*values, &vb = b.*values;
      agree = true;
      for (const auto &[mm, value] : vb)
        if (mm >= from && mm <= until && va.count(mm))
        {
          worst = std::max(worst, std::abs(va.at(mm) - value));
          agree = agree && close(va.at(mm), value, rtol, atol);
        }
      return worst;
    }
  } // namespace plane_drag
} // namespace softgrasp_tests

#endif
