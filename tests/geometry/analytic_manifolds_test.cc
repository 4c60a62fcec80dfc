// Plane, sphere, cylinder and line manifolds: the Ceres manifold invariants at random points,
// and points produced by Plus lying on the geometry to 1e-12 relative.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "tests/geometry/manifold_invariants.h"
#include "tmop/geometry/cylinder_manifold.h"
#include "tmop/geometry/line_manifold.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/sphere_manifold.h"

namespace tmop {
namespace {

using testing_util::ExpectManifoldInvariants;

constexpr int kTrials = 20;

Eigen::VectorXd random_vector(std::mt19937* rng, int n, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(*rng);
  return v;
}

// Random x on the manifold (projection of a random point), a small delta, and y = a random
// nearby point of the manifold; checks the invariants and that Plus lands on the geometry.
void check_random(const GeometryManifold& m, std::mt19937* rng, double scale, double tolerance) {
  for (int trial = 0; trial < kTrials; ++trial) {
    Eigen::VectorXd x(m.AmbientSize()), y(m.AmbientSize()), xp(m.AmbientSize());
    const Eigen::VectorXd r = random_vector(rng, m.AmbientSize(), 3 * scale);
    m.Project(r.data(), x.data());
    const Eigen::VectorXd delta = random_vector(rng, m.TangentSize(), 0.1 * scale);
    const Eigen::VectorXd delta_y = random_vector(rng, m.TangentSize(), 0.1 * scale);
    ASSERT_TRUE(m.Plus(x.data(), delta_y.data(), y.data()));
    ExpectManifoldInvariants(m, x, delta, y, tolerance);
    const Eigen::VectorXd big = random_vector(rng, m.TangentSize(), 2 * scale);
    ASSERT_TRUE(m.Plus(x.data(), big.data(), xp.data()));
    EXPECT_LE(m.Distance(xp.data()), 1e-12 * scale * 10) << "Plus left the geometry";
  }
}

TEST(PlaneManifold, InvariantsAtRandomPoints) {
  std::mt19937 rng(1);
  const double p[3] = {1, -2, 0.5}, n[3] = {0.3, -1, 2};
  PlaneManifold plane(p, n);
  check_random(plane, &rng, 1.0, 1e-12);
}

TEST(PlaneManifold, PlusStaysOnThePlaneExactly) {
  const double p[3] = {0, 0, 1}, n[3] = {0, 0, 2};
  PlaneManifold plane(p, n);
  const double x[3] = {3, 4, 1}, d[2] = {0.25, -7};
  double y[3];
  ASSERT_TRUE(plane.Plus(x, d, y));
  EXPECT_EQ(y[2], 1.0);
  EXPECT_NEAR(std::hypot(y[0] - 3, y[1] - 4), std::hypot(0.25, 7), 1e-14);
}

TEST(SphereManifold, InvariantsAtRandomPoints) {
  std::mt19937 rng(2);
  const double c[3] = {0.5, 1, -1};
  SphereManifold sphere(c, 2.5);
  check_random(sphere, &rng, 2.5, 1e-10);
  SphereManifold small(c, 0.05);
  check_random(small, &rng, 0.05, 1e-10);
}

TEST(SphereManifold, MinusRejectsTheFarHemisphere) {
  const double c[3] = {0, 0, 0};
  SphereManifold sphere(c, 1);
  const double x[3] = {1, 0, 0}, y[3] = {-1, 0, 0};
  double d[2];
  EXPECT_FALSE(sphere.Minus(y, x, d));
}

TEST(CylinderManifold, InvariantsAtRandomPoints) {
  std::mt19937 rng(3);
  const double p[3] = {0.6, 0.5, -0.1}, a[3] = {0, 0, 1.2};
  CylinderManifold cylinder(p, a, 0.25);
  check_random(cylinder, &rng, 0.25, 1e-10);
  const double a2[3] = {1, 2, -0.5};
  CylinderManifold oblique(p, a2, 3.0);
  check_random(oblique, &rng, 3.0, 1e-10);
}

TEST(LineManifold, InvariantsIn2DAnd3D) {
  std::mt19937 rng(4);
  const double p2[2] = {1, 2}, d2[2] = {3, -1};
  LineManifold line2(2, p2, d2);
  check_random(line2, &rng, 1.0, 1e-12);
  const double p3[3] = {1, 2, 3}, d3[3] = {0, 1, 1};
  LineManifold line3(3, p3, d3);
  check_random(line3, &rng, 1.0, 1e-12);
}

}  // namespace
}  // namespace tmop
