// Ceres's own manifold invariants (ceres/manifold_test_utils.h, EXPECT_THAT_MANIFOLD_INVARIANTS_
// HOLD: Plus, Minus, their Jacobians and their consistency) on tmop's analytic
// manifolds, at random points. (The polyline's arc-length chart has kinks at its vertices,
// where the macro's numeric Jacobians are not defined: polyline_manifold_test.cc checks the same
// properties between vertices.)
#include <ceres/manifold_test_utils.h>
#include <gtest/gtest.h>

#include <random>

#include "tmop/geometry/cylinder_manifold.h"
#include "tmop/geometry/line_manifold.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/sphere_manifold.h"

// The macro names Ceres's matchers unqualified, so it is used inside namespace ceres.
namespace ceres {
namespace {

using tmop::GeometryManifold;

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
    EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(m, x, delta, y, 1e-6);
  }
}

}  // namespace
}  // namespace ceres

namespace tmop {
namespace {

using ceres::check;

TEST(CeresManifoldInvariants, AnalyticManifolds) {
  std::mt19937 rng(12);
  const double c[3] = {0.3, -0.2, 0.5}, n[3] = {0.2, 0.3, 1.0}, dir[3] = {1, 0.5, 0.2};
  check(PlaneManifold(c, n), &rng, 2);
  check(SphereManifold(c, 0.7), &rng, 2);
  check(CylinderManifold(c, dir, 0.4), &rng, 2);
  check(LineManifold(3, c, dir), &rng, 2);
}

}  // namespace
}  // namespace tmop
