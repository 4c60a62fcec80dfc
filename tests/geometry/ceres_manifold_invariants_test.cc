// Ceres's own manifold invariants (ceres/manifold_test_utils.h, EXPECT_THAT_MANIFOLD_INVARIANTS_
// HOLD: Plus, Minus, their Jacobians and their consistency) on tmop's analytic
// manifolds at random points, on the triangulated surface inside its faces and on 2D / 3D
// polylines inside their segments (the charts have kinks at edges and vertices, where the
// macro's numeric Jacobians are not defined; polyline_manifold_test.cc and
// triangle_surface_manifold_test.cc check the rest). The macro differentiates numerically with a
// fixed absolute step, so it is run at the unit scale at which the stages use the manifolds
// (normalised coordinates: docs/architecture.md).
#include <ceres/manifold_test_utils.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tmop/geometry/cylinder_manifold.h"
#include "tmop/geometry/line_manifold.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/polyline_manifold.h"
#include "tmop/geometry/sphere_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"

// The macro names Ceres's matchers unqualified, so it is used inside namespace ceres.
namespace ceres {
namespace {

using tmop::GeometryManifold;

// The macro at given points (for charts that hold only inside faces / segments).
void check_at(const GeometryManifold& m, const Eigen::VectorXd& x, const Eigen::VectorXd& delta,
              const Eigen::VectorXd& y) {
  EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(m, x, delta, y, 1e-6);
}

// A random point on the manifold, a small tangent step, and another nearby point on it.
void check(const GeometryManifold& m, std::mt19937* rng, double spread) {
  std::uniform_real_distribution<double> u(-1, 1);
  const int a = m.AmbientSize(), t = m.TangentSize();
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd guess(a), x(a), y(a), delta(t), step(t);
    for (int k = 0; k < a; ++k) guess[k] = spread * u(*rng);
    m.Project(guess.data(), x.data());
    for (int k = 0; k < t; ++k) delta[k] = 0.05 * u(*rng), step[k] = 0.05 * u(*rng);
    ASSERT_TRUE(m.Plus(x.data(), step.data(), y.data()));
    check_at(m, x, delta, y);
  }
}

}  // namespace
}  // namespace ceres

namespace tmop {
namespace {

using ceres::check;
using ceres::check_at;

TEST(CeresManifoldInvariants, AnalyticManifolds) {
  std::mt19937 rng(12);
  const double c[3] = {0.3, -0.2, 0.5}, n[3] = {0.2, 0.3, 1.0}, dir[3] = {1, 0.5, 0.2};
  check(PlaneManifold(c, n), &rng, 2);
  check(SphereManifold(c, 0.7), &rng, 2);
  check(CylinderManifold(c, dir, 0.4), &rng, 2);
  check(LineManifold(3, c, dir), &rng, 2);
}

// A height field z = 0.3 sin(x) cos(y) on a 7 x 7 grid of points, two triangles per square;
// points at face centroids, steps small enough to stay in the face.
TEST(CeresManifoldInvariants, TriangleSurfaceInsideFaces) {
  std::vector<double> v;
  std::vector<std::int32_t> t;
  const int n = 7;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      v.push_back(i * 0.3);
      v.push_back(j * 0.3);
      v.push_back(0.3 * std::sin(i * 0.3) * std::cos(j * 0.3));
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      t.insert(t.end(), {a, b, d, a, d, c});
    }
  const TriangleSurfaceManifold m(v, t);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> face(0, static_cast<int>(t.size() / 3) - 1);
  for (int trial = 0; trial < 30; ++trial) {
    const int f = face(rng);
    Eigen::VectorXd x(3), y(3), delta(2), step(2);
    for (int k = 0; k < 3; ++k)
      x[k] = (v[3 * t[3 * f] + k] + v[3 * t[3 * f + 1] + k] + v[3 * t[3 * f + 2] + k]) / 3;
    delta << 1e-3 * u(rng), 1e-3 * u(rng);
    step << 1e-3 * u(rng), 1e-3 * u(rng);
    ASSERT_TRUE(m.Plus(x.data(), step.data(), y.data()));
    check_at(m, x, delta, y);
  }
}

// A helix (3D, open) and a nonagon (2D, open and closed), at segment midpoints.
TEST(CeresManifoldInvariants, PolylinesInsideSegments) {
  for (int dim : {2, 3})
    for (bool closed : {false, true}) {
      std::vector<double> p;
      const int n = 9;
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        p.push_back(std::cos(a));
        p.push_back(std::sin(a));
        if (dim == 3) p.push_back(0.2 * i);
      }
      const PolylineManifold m(dim, p, closed);
      std::mt19937 rng(6);
      std::uniform_real_distribution<double> u(-1, 1);
      std::uniform_int_distribution<int> segment(0, n - 2);
      for (int trial = 0; trial < 20; ++trial) {
        const int s = segment(rng);
        Eigen::VectorXd x(dim), y(dim), delta(1), step(1);
        for (int k = 0; k < dim; ++k) x[k] = 0.5 * (p[dim * s + k] + p[dim * (s + 1) + k]);
        delta << 1e-3 * u(rng);
        step << 1e-3 * u(rng);
        ASSERT_TRUE(m.Plus(x.data(), step.data(), y.data()));
        check_at(m, x, delta, y);
      }
    }
}

}  // namespace
}  // namespace tmop
