#include <cmath>
#include <softgrasp/base/input_error.h>
#include <softgrasp/meshes/layered_limb.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  double LimbGeometry::mid_semi_axis() const
  {
    // Ramanujan: C = pi (3 (a + b) - sqrt((3a + b)(a + 3b))), b = k a.
    const double k = aspect_ratio;
    return circumference /
           (M_PI * (3 * (1 + k) - std::sqrt((3 + k) * (1 + 3 * k))));
  }

  std::array<double, 2> LimbGeometry::semi_axes(const unsigned int k,
                                                const double       x) const
  {
    if (k == 0)
      return {{bone_radius, bone_radius}};
    const double f = 2 / (1 + taper) * (1 + (taper - 1) * (x / length + 0.5));
    const double a = mid_semi_axis() * f;
    const double b = aspect_ratio * a;
    const double depth =
        (k <= 3 ? skin : 0) + (k <= 2 ? fat : 0) + (k <= 1 ? fascia : 0);
    return {{a - depth, b - depth}};
  }

  void LimbGeometry::check() const
  {
    const auto fail = [](const std::string &what, const std::string &fix)
    { throw InputError("Mesh 'layered limb': " + what + " Fix: " + fix); };
    if (!(length > 0) || !(circumference > 0) || !(aspect_ratio > 0) ||
        !(taper > 0) || !(skin > 0) || !(bone_radius > 0))
      fail("the length, circumference, aspect ratio, taper, skin thickness "
           "and bone radius must be positive.",
           "give positive values (m, or 1 for the ratios).");
    if (fat < 0 || fascia < 0)
      fail("a layer thickness is negative.",
           "give thicknesses >= 0 (m); 0 leaves the layer out.");
    for (const double x : {-length / 2, length / 2})
    {
      const auto   outer = semi_axes(1, x);
      const double room  = std::min(outer[0], outer[1]) - bone_radius;
      if (!(room > 0))
      {
        std::ostringstream what;
        what << "skin + fat + fascia (" << skin + fat + fascia
             << " m) and the bone radius (" << bone_radius
             << " m) leave no room for muscle at the "
             << (x < 0 ? "shoulder" : "elbow")
             << " end, whose smaller outer semi-axis is "
             << std::min(semi_axes(4, x)[0], semi_axes(4, x)[1]) << " m.";
        fail(what.str(),
             "make the layers thinner, the bone smaller, or the "
             "circumference, aspect ratio or taper larger.");
      }
    }
  }

  void LimbGeometry::check_human_size() const
  {
    // Ranges of human limb segments, from a newborn's forearm to an
    // adult's thigh (skin: epidermis and dermis; fat: subcutaneous).
    struct Range
    {
      const char *entry;
      double      value, lower, upper;
    };
    const Range ranges[] = {{"Length", length, 0.03, 1.2},
                            {"Circumference", circumference, 0.08, 1.0},
                            {"Skin thickness", skin, 0.0005, 0.005},
                            {"Fat thickness", fat, 0, 0.08},
                            {"Fascia thickness", fascia, 0, 0.003},
                            {"Bone radius", bone_radius, 0.002, 0.03}};
    for (const Range &r : ranges)
      if (r.value < r.lower || r.value > r.upper)
      {
        std::ostringstream what;
        what << "'Mesh/Layered limb/" << r.entry << "' = " << r.value
             << " m lies outside the range of human limbs (" << r.lower
             << " to " << r.upper
             << " m). Fix: give it in metres (a value in millimetres is "
                "1000 times too large), or set 'Mesh/Layered limb/Check "
                "human size = false' for a limb that is not human.";
        throw InputError(what.str());
      }
  }

  namespace
  {
    /// The interfaces present (a layer of thickness 0 has none).
    std::vector<unsigned int> present_interfaces(const LimbGeometry &g)
    {
      std::vector<unsigned int> k = {0, 1};
      if (g.fascia > 0)
        k.push_back(2);
      if (g.fat > 0)
        k.push_back(3);
      k.push_back(4);
      return k;
    }
  } // namespace

  LimbManifold::LimbManifold(const LimbGeometry &geometry,
                             const Placement<3> &placement)
      : ChartManifold<3, 3, 3>(Tensor<1, 3>({0., 2 * M_PI, 0.}))
      , geometry(geometry)
      , placement(placement)
      , inverse_rotation(transpose(placement.rotation))
  {
  }

  std::unique_ptr<Manifold<3, 3>> LimbManifold::clone() const
  {
    return std::make_unique<LimbManifold>(geometry, placement);
  }

  namespace
  {
    /// Semi-axes and their derivatives by xi and x at chart level xi.
    struct Axes
    {
      double a, b, a_xi, b_xi, a_x, b_x;
    };

    Axes axes_at(const LimbGeometry              &g,
                 const std::vector<unsigned int> &levels,
                 const double                     xi,
                 const double                     x)
    {
      const int    n   = static_cast<int>(levels.size()) - 1;
      const int    lo  = std::clamp(static_cast<int>(std::floor(xi)), 0, n - 1);
      const double t   = xi - lo;
      const auto   in  = g.semi_axes(levels[lo], x);
      const auto   out = g.semi_axes(levels[lo + 1], x);
      // d/dx of a skin-relative interface is a'(x); the bone is constant.
      const double da =
          2 / (1 + g.taper) * (g.taper - 1) / g.length * g.mid_semi_axis();
      const double din  = levels[lo] == 0 ? 0 : 1;
      const double dout = levels[lo + 1] == 0 ? 0 : 1;
      Axes         r;
      r.a    = (1 - t) * in[0] + t * out[0];
      r.b    = (1 - t) * in[1] + t * out[1];
      r.a_xi = out[0] - in[0];
      r.b_xi = out[1] - in[1];
      r.a_x  = ((1 - t) * din + t * dout) * da;
      r.b_x  = g.aspect_ratio * r.a_x;
      return r;
    }
  } // namespace

  Point<3> LimbManifold::local_point(const Point<3> &chart) const
  {
    const auto levels = present_interfaces(geometry);
    const Axes s      = axes_at(geometry, levels, chart[0], chart[2]);
    return Point<3>(
        chart[2], s.a * std::cos(chart[1]), s.b * std::sin(chart[1]));
  }

  Point<3> LimbManifold::local_chart(const Point<3> &p) const
  {
    const auto   levels = present_interfaces(geometry);
    const double x      = p[0];
    // F(xi) = (y / A)^2 + (z / B)^2 - 1 decreases with xi: bracket it on
    // the levels, then Newton (bisection as a safeguard).
    const auto F = [&](const double xi)
    {
      const Axes s = axes_at(geometry, levels, xi, x);
      return std::pow(p[1] / s.a, 2) + std::pow(p[2] / s.b, 2) - 1;
    };
    const double top = levels.size() - 1;
    double       lo = 0, hi = top;
    double       xi = 0;
    if (F(0) <= 0)
      xi = 0; // on or (by round-off) inside the bone surface
    else if (F(top) >= 0)
      xi = top; // on or (by round-off) outside the skin
    else
    {
      xi = 0.5 * (lo + hi);
      for (unsigned int it = 0; it < 100 && hi - lo > 1e-15 * top; ++it)
      {
        const double f    = F(xi);
        (f > 0 ? lo : hi) = xi;
        const Axes   s    = axes_at(geometry, levels, xi, x);
        const double df   = -2 * std::pow(p[1], 2) / std::pow(s.a, 3) * s.a_xi -
                          2 * std::pow(p[2], 2) / std::pow(s.b, 3) * s.b_xi;
        double next = df < 0 ? xi - f / df : 0.5 * (lo + hi);
        if (!(next > lo && next < hi))
          next = 0.5 * (lo + hi);
        if (std::abs(next - xi) < 1e-15 * top)
        {
          xi = next;
          break;
        }
        xi = next;
      }
    }
    const Axes s     = axes_at(geometry, levels, xi, x);
    double     theta = std::atan2(p[2] / s.b, p[1] / s.a);
    if (theta < 0)
      theta += 2 * M_PI;
    return Point<3>(xi, theta, x);
  }

  Point<3> LimbManifold::pull_back(const Point<3> &space) const
  {
    return local_chart(
        Point<3>(inverse_rotation * (space - Point<3>(placement.translation))));
  }

  Point<3> LimbManifold::push_forward(const Point<3> &chart) const
  {
    return placement(local_point(chart));
  }

  DerivativeForm<1, 3, 3>
  LimbManifold::push_forward_gradient(const Point<3> &chart) const
  {
    const auto   levels = present_interfaces(geometry);
    const Axes   s      = axes_at(geometry, levels, chart[0], chart[2]);
    const double c = std::cos(chart[1]), d = std::sin(chart[1]);
    Tensor<2, 3> local; // local[i][j] = d x_i / d chart_j
    local[0][2] = 1;
    local[1][0] = s.a_xi * c;
    local[2][0] = s.b_xi * d;
    local[1][1] = -s.a * d;
    local[2][1] = s.b * c;
    local[1][2] = s.a_x * c;
    local[2][2] = s.b_x * d;
    return DerivativeForm<1, 3, 3>(placement.rotation * local);
  }
} // namespace softgrasp
