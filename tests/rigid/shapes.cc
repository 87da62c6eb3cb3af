// Rigid geom shapes (MuJoCo types and sizes): for 2000 random points around
// each shape the query is an exact signed distance field:
//   x = closest + distance * normal,  |normal| = 1,
//   the closest point lies on the surface (its distance is 0),
// to round-off; plus analytic values (inside, outside, caps, rims, the
// degenerate centre of an ellipsoid), the registry of shape types, every
// type's wire frame lying on its surface, and bad geom definitions.
#include "../tests.h"

#include <random>
#include <softgrasp/base/input_error.h>
#include <softgrasp/rigid/shape.h>

using namespace softgrasp;

void
check_value(const Shape           &shape,
            const Eigen::Vector3d &x,
            const double           distance,
            const Eigen::Vector3d &normal)
{
  const ShapeQuery q = shape.query(x);
  SG_CHECK(std::abs(q.distance - distance) < 1e-14,
           shape.type() + ": analytic distance");
  SG_CHECK((q.normal - normal).norm() < 1e-12, shape.type() + ": normal");
  dealii::deallog << shape.type() << " at (" << x.transpose()
                  << "): d = " << q.distance << ", n = ("
                  << q.normal.transpose() << ")" << std::endl;
}

int
main()
{
  softgrasp_tests::initlog(6);
  const std::vector<std::pair<std::string, Eigen::Vector3d>> geoms = {
      {"sphere", {0.02, 0, 0}},
      {"capsule", {0.01, 0.03, 0}},
      {"cylinder", {0.01, 0.02, 0}},
      {"box", {0.01, 0.02, 0.03}},
      {"ellipsoid", {0.03, 0.02, 0.01}},
      {"plane", {0, 0, 0}}};
  std::mt19937                           rng(42);
  std::uniform_real_distribution<double> uniform(-0.05, 0.05);
  for (const auto &[type, size] : geoms)
  {
    const auto shape = create_shape(type, size, "test " + type);
    double     worst = 0;
    for (unsigned int i = 0; i < 2000; ++i)
    {
      const Eigen::Vector3d x(uniform(rng), uniform(rng), uniform(rng));
      const ShapeQuery      q = shape->query(x);
      worst                   = std::max({worst,
                                          (x - (q.closest + q.distance * q.normal)).norm(),
                                          std::abs(q.normal.norm() - 1) * 0.05,
                                          std::abs(shape->query(q.closest).distance)});
    }
    SG_CHECK(worst < 1e-13, type + ": exact signed distance field");
    dealii::deallog << type << ": signed distance field exact on 2000 points"
                    << std::endl;
  }

  // Every shape type is registered under its MuJoCo name, and its wire
  // frame (what the pictures draw) lies on its surface.
  SG_CHECK(ShapeRegistry::names_separated_by(", ") ==
               "box, capsule, cylinder, ellipsoid, mesh, plane, sphere",
           "the registered shape types");
  for (const auto &[type, size] : geoms)
  {
    const auto   shape = create_shape(type, size, "drawn " + type);
    double       worst = 0;
    unsigned int n     = 0;
    for (const auto &line : shape->wireframe())
      for (const auto &x : line)
      {
        worst = std::max(worst, std::abs(shape->query(x).distance));
        ++n;
      }
    SG_CHECK(n > 0 && worst < 1e-15, type + ": wire frame on the surface");
    dealii::deallog << type << ": " << n << " wire frame points on the surface"
                    << std::endl;
  }

  using V = Eigen::Vector3d;
  check_value(*create_shape("sphere", {0.02, 0, 0}, "s"),
              {0, 0, 0.05},
              0.03,
              V::UnitZ());
  const auto capsule = create_shape("capsule", {0.01, 0.03, 0}, "c");
  check_value(*capsule, {0, 0.02, 0.01}, 0.01, V::UnitY());
  check_value(*capsule, {0, 0, 0.05}, 0.01, V::UnitZ());
  check_value(*capsule, {0.005, 0, -0.02}, -0.005, V::UnitX());
  const auto cylinder = create_shape("cylinder", {0.01, 0.02, 0}, "y");
  check_value(
      *cylinder, {0.02, 0, 0.03}, std::sqrt(2) * 0.01, V(1, 0, 1).normalized());
  check_value(*cylinder, {0, 0.005, -0.019}, -0.001, -V::UnitZ());
  const auto box = create_shape("box", {0.01, 0.02, 0.03}, "b");
  check_value(*box, {0.009, 0, 0}, -0.001, V::UnitX());
  check_value(*box, {0.0, -0.025, 0}, 0.005, -V::UnitY());
  const auto ellipsoid = create_shape("ellipsoid", {0.03, 0.02, 0.01}, "e");
  check_value(*ellipsoid, {0, 0, 0.02}, 0.01, V::UnitZ());
  check_value(*ellipsoid, {0.04, 0, 0}, 0.01, V::UnitX());
  check_value(*ellipsoid, {0, 0, 0}, -0.01, V::UnitZ());
  check_value(*create_shape("plane", {1, 1, 0.1}, "p"),
              {3, -2, -0.005},
              -0.005,
              V::UnitZ());

  for (const auto &[type, size] :
       std::vector<std::pair<std::string, Eigen::Vector3d>>{
           {"capsule", {0.01, -0.02, 0}},
           {"torus", {0.01, 0.01, 0}},
           {"box", {0.01, 0.01, NAN}}})
  {
    try
    {
      create_shape(type, size, "finger link");
      SG_CHECK(false, "a bad geom must be rejected");
    }
    catch (const InputError &e)
    {
      const std::string message = e.what();
      SG_CHECK(message.find("finger link") != std::string::npos &&
                   message.find("Fix:") != std::string::npos,
               "the message names the geom and the fix");
      dealii::deallog << "rejected: "
                      << message.substr(0, message.find(". Fix")) << std::endl;
    }
  }
}
