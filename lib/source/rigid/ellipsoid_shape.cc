#include <cmath>
#include <softgrasp/rigid/ellipsoid_shape.h>

namespace softgrasp
{
  EllipsoidShape::EllipsoidShape(const Eigen::Vector3d &radii)
      : radii(radii)
  {
  }

  ShapeQuery EllipsoidShape::query(const Eigen::Vector3d &x) const
  {
    // Work with y = |x| in the first octant; the closest point c satisfies
    // c_i = r_i^2 y_i / (t + r_i^2) with F(t) = sum (r_i y_i / (t + r_i^2))^2
    // - 1 = 0, F decreasing on t > -r_min^2.
    const Eigen::Vector3d y  = x.cwiseAbs();
    const Eigen::Vector3d r2 = radii.cwiseProduct(radii);
    Eigen::Index          k;
    const double          r_min = radii.minCoeff(&k);
    const double          level = y.cwiseQuotient(radii).squaredNorm() - 1;

    auto F = [&](const double t)
    {
      double sum = 0;
      for (unsigned int i = 0; i < 3; ++i)
      {
        const double term = radii[i] * y[i] / (t + r2[i]);
        sum += term * term;
      }
      return sum - 1;
    };

    // Does F blow up at t -> -r_min^2? Only if a shortest-axis coordinate
    // is non-zero; otherwise the closest point may be the degenerate one.
    const double tiny   = 1e-14 * radii.maxCoeff();
    bool         blowup = false;
    for (unsigned int i = 0; i < 3; ++i)
      if (radii[i] <= r_min * (1 + 1e-12) && y[i] > tiny)
        blowup = true;

    Eigen::Vector3d c          = Eigen::Vector3d::Zero();
    bool            degenerate = false;
    if (!blowup)
    {
      double limit = -1;
      for (unsigned int i = 0; i < 3; ++i)
        if (radii[i] > r_min * (1 + 1e-12))
        {
          const double term = radii[i] * y[i] / (r2[i] - r_min * r_min);
          limit += term * term;
        }
      if (limit < 0)
      {
        degenerate  = true;
        double rest = 1;
        for (unsigned int i = 0; i < 3; ++i)
          if (radii[i] > r_min * (1 + 1e-12))
          {
            c[i] = r2[i] * y[i] / (r2[i] - r_min * r_min);
            rest -= (c[i] / radii[i]) * (c[i] / radii[i]);
          }
        c[k] = r_min * std::sqrt(std::max(0.0, rest));
      }
    }
    if (!degenerate)
    {
      double lo = -r_min * r_min;
      double hi = radii.maxCoeff() * y.norm();
      for (unsigned int it = 0; it < 200 && hi - lo > 0; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi)
          break;
        (F(mid) > 0 ? lo : hi) = mid;
      }
      const double t = 0.5 * (lo + hi);
      for (unsigned int i = 0; i < 3; ++i)
        c[i] = r2[i] * y[i] / (t + r2[i]);
    }

    ShapeQuery q;
    for (unsigned int i = 0; i < 3; ++i)
      q.closest[i] = x[i] < 0 ? -c[i] : c[i];
    const Eigen::Vector3d gradient = q.closest.cwiseQuotient(r2);
    q.normal                       = gradient.normalized();
    q.distance = (level < 0 ? -1.0 : 1.0) * (x - q.closest).norm();
    return q;
  }

  double EllipsoidShape::bounding_radius() const
  {
    return radii.maxCoeff();
  }

  std::string EllipsoidShape::type() const
  {
    return type_name;
  }

  std::unique_ptr<EllipsoidShape> EllipsoidShape::create(const ShapeSpec &spec)
  {
    spec.require_positive(3, "three radii");
    return std::make_unique<EllipsoidShape>(spec.size);
  }

  std::vector<std::vector<Eigen::Vector3d>> EllipsoidShape::wireframe() const
  {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    const Eigen::Vector3d x = radii[0] * Eigen::Vector3d::UnitX(),
                          y = radii[1] * Eigen::Vector3d::UnitY(),
                          z = radii[2] * Eigen::Vector3d::UnitZ();
    return {arc(o, x, y), arc(o, y, z), arc(o, z, x)};
  }

  SOFTGRASP_REGISTER_SHAPE(
      EllipsoidShape, "an ellipsoid with radii size[0..2] along the local axes")
} // namespace softgrasp
