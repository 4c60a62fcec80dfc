// PolylineManifold: invariants inside segments, arc-length round trips across polyline vertices,
// clamping at the ends of open curves and wrapping on closed ones, in 2D and 3D.
#include "tmop/geometry/polyline_manifold.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "tests/geometry/manifold_invariants.h"

namespace tmop {
namespace {

// A zig-zag in 3D with unequal segments: 0 -> (1,0,0) -> (1,2,0) -> (1,2,0.5) -> (3,2,0.5).
// Lengths 1, 2, 0.5, 2: total 5.5.
std::vector<double> zigzag3() { return {0, 0, 0, 1, 0, 0, 1, 2, 0, 1, 2, 0.5, 3, 2, 0.5}; }

TEST(PolylineManifold, ArcLengthAndPointAt) {
  PolylineManifold curve(3, zigzag3(), false);
  EXPECT_DOUBLE_EQ(curve.length(), 5.5);
  const double x[3] = {1, 1.5, 0};
  EXPECT_DOUBLE_EQ(curve.ArcLength(x), 2.5);
  double p[3];
  curve.PointAt(3.25, p);
  EXPECT_DOUBLE_EQ(p[2], 0.25);
  EXPECT_DOUBLE_EQ(p[1], 2.0);
}

TEST(PolylineManifold, PlusMinusRoundTripAcrossVertices) {
  PolylineManifold curve(3, zigzag3(), false);
  const double x[3] = {0.3, 0, 0};  // s = 0.3
  for (double d : {2.7, 3.0, 4.9, -0.2, 1.25}) {
    double y[3], back;
    ASSERT_TRUE(curve.Plus(x, &d, y));
    EXPECT_NEAR(curve.ArcLength(y), 0.3 + d, 1e-14);
    EXPECT_LE(curve.Distance(y), 1e-15);
    ASSERT_TRUE(curve.Minus(y, x, &back));
    EXPECT_NEAR(back, d, 1e-14) << "d = " << d;
  }
  // d = 2.7 lands on the third vertex (1, 2, 0).
  double d = 2.7, y[3];
  curve.Plus(x, &d, y);
  EXPECT_NEAR(y[0], 1, 1e-15);
  EXPECT_NEAR(y[1], 2, 1e-15);
  EXPECT_NEAR(y[2], 0, 1e-15);
}

TEST(PolylineManifold, OpenCurveClampsAtItsEnds) {
  PolylineManifold curve(3, zigzag3(), false);
  const double x[3] = {1, 1, 0};
  double y[3], d = 100;
  curve.Plus(x, &d, y);
  EXPECT_EQ(y[0], 3.0);
  EXPECT_EQ(y[2], 0.5);
  d = -100;
  curve.Plus(x, &d, y);
  EXPECT_EQ(y[0], 0.0);
  EXPECT_EQ(y[1], 0.0);
}

TEST(PolylineManifold, ClosedCurveWraps) {
  // Unit square in 2D, perimeter 4, closing segment (0,1) -> (0,0).
  PolylineManifold square(2, {0, 0, 1, 0, 1, 1, 0, 1}, true);
  EXPECT_DOUBLE_EQ(square.length(), 4.0);
  const double x[2] = {0, 0.5};  // s = 3.5
  double d = 1.0, y[2], back;
  square.Plus(x, &d, y);
  EXPECT_NEAR(y[0], 0.5, 1e-15);
  EXPECT_NEAR(y[1], 0.0, 1e-15);
  square.Minus(y, x, &back);
  EXPECT_NEAR(back, 1.0, 1e-14);  // the short way round, not -3
  d = -5.25;
  square.Plus(x, &d, y);
  EXPECT_NEAR(square.ArcLength(y), 2.25, 1e-14);
}

TEST(PolylineManifold, InvariantsInsideSegments) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  // A closed polygonal circle in 2D (40 equal segments) and the open zig-zag in 3D.
  std::vector<double> circle;
  for (int i = 0; i < 40; ++i) {
    circle.push_back(std::cos(2 * M_PI * i / 40));
    circle.push_back(std::sin(2 * M_PI * i / 40));
  }
  PolylineManifold closed(2, circle, true);
  PolylineManifold open(3, zigzag3(), false);
  std::vector<double> closed_vertices;
  for (int i = 0; i <= 40; ++i) closed_vertices.push_back(closed.length() * i / 40);
  const std::vector<double> open_vertices = {0, 1, 3, 3.5, 5.5};
  for (int which = 0; which < 2; ++which) {
    const PolylineManifold& curve = which == 0 ? closed : open;
    const std::vector<double>& vertices = which == 0 ? closed_vertices : open_vertices;
    const int dim = curve.AmbientSize();
    int checked = 0;
    while (checked < 30) {
      // Central differences and small steps must not straddle a polyline vertex (a kink).
      const double s = curve.length() * u(rng);
      bool near_vertex = false;
      for (double v : vertices) near_vertex |= std::fabs(s - v) < 2e-3;
      if (near_vertex) continue;
      Eigen::VectorXd x(dim), y(dim), delta(1), dy(1);
      curve.PointAt(s, x.data());
      delta[0] = 1e-3 * (2 * u(rng) - 1);
      dy[0] = 1e-3 * (2 * u(rng) - 1);
      ASSERT_TRUE(curve.Plus(x.data(), dy.data(), y.data()));
      testing_util::ExpectManifoldInvariants(curve, x, delta, y, 1e-12);
      ++checked;
    }
  }
}

}  // namespace
}  // namespace tmop
