// TriangleSurfaceManifold: invariants inside faces, Plus stays on the triangle mesh to round-off,
// and a walk along one of two close parallel sheets never jumps to the other one.
#include "tmop/geometry/triangle_surface_manifold.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "tests/geometry/manifold_invariants.h"
#include "tmop/geometry/vec3.h"

namespace tmop {
namespace {

// A latitude-longitude triangulation of the sphere of radius r about the origin (poles
// included), appended to vertices / triangles. Edge length about pi r / rings.
void add_sphere(double r, int rings, std::vector<double>* vertices,
                std::vector<std::int32_t>* triangles) {
  const int base = static_cast<int>(vertices->size() / 3);
  const int sectors = 2 * rings;
  vertices->insert(vertices->end(), {0, 0, r});
  for (int i = 1; i < rings; ++i) {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2 * M_PI * j / sectors;
      vertices->insert(vertices->end(), {r * std::sin(theta) * std::cos(phi),
                                         r * std::sin(theta) * std::sin(phi), r * std::cos(theta)});
    }
  }
  vertices->insert(vertices->end(), {0, 0, -r});
  const int south = base + 1 + (rings - 1) * sectors;
  auto ring = [&](int i, int j) { return base + 1 + (i - 1) * sectors + (j % sectors); };
  for (int j = 0; j < sectors; ++j) {
    triangles->insert(triangles->end(), {base, ring(1, j), ring(1, j + 1)});
    triangles->insert(triangles->end(), {south, ring(rings - 1, j + 1), ring(rings - 1, j)});
  }
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < sectors; ++j) {
      triangles->insert(triangles->end(), {ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      triangles->insert(triangles->end(), {ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
}

// A grid of n x n squares of size h, each split into two triangles, in the plane z = 0, then
// folded along x = fold by the angle `bend` (radians): points with x > fold rise.
void add_folded_grid(int n, double h, double fold, double bend, std::vector<double>* vertices,
                     std::vector<std::int32_t>* triangles) {
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = i * h, y = j * h;
      const double beyond = std::max(0.0, x - fold);
      vertices->insert(vertices->end(),
                       {std::min(x, fold) + beyond * std::cos(bend), y, beyond * std::sin(bend)});
    }
  }
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      triangles->insert(triangles->end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles->insert(triangles->end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
}

TEST(TriangleSurfaceManifold, WalkOnAPlaneIsTheStraightStep) {
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_folded_grid(20, 0.2, 100, 0, &v, &t);  // flat 4 x 4 square
  TriangleSurfaceManifold surface(v, t);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    // Start at mesh vertices half of the time: every patch vertex starts at one.
    double x[3] = {1 + 2 * u(rng), 1 + 2 * u(rng), 0};
    if (trial % 2 == 0) {
      x[0] = std::round(x[0] / 0.2) * 0.2;
      x[1] = std::round(x[1] / 0.2) * 0.2;
    }
    const double d[2] = {1.8 * u(rng) - 0.9, 1.8 * u(rng) - 0.9};
    double jac[6], y[3], back[2];
    ASSERT_TRUE(surface.PlusJacobian(x, jac));
    ASSERT_TRUE(surface.Plus(x, d, y));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(y[i], x[i] + jac[2 * i] * d[0] + jac[2 * i + 1] * d[1], 1e-13) << trial;
    }
    ASSERT_TRUE(surface.Minus(y, x, back));
    EXPECT_NEAR(back[0], d[0], 1e-12);
    EXPECT_NEAR(back[1], d[1], 1e-12);
  }
}

TEST(TriangleSurfaceManifold, WalkAcrossAFoldKeepsLengthAndAngle) {
  // Folded by 60 degrees along x = 1: unfolding the walk must give the straight step.
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_folded_grid(20, 0.1, 1.0, M_PI / 3, &v, &t);
  TriangleSurfaceManifold surface(v, t);
  const double x[3] = {0.55, 1.05, 0};
  double jac[6];
  surface.PlusJacobian(x, jac);
  // Tangent coordinates of the step (0.8, 0.3) in the flat part's plane.
  const double step[3] = {0.8, 0.3, 0};
  const double d[2] = {jac[0] * step[0] + jac[2] * step[1], jac[1] * step[0] + jac[3] * step[1]};
  double y[3];
  ASSERT_TRUE(surface.Plus(x, d, y));
  // Unfolded end point (1.35, 1.35): 0.35 beyond the fold along the bent plane.
  EXPECT_NEAR(y[0], 1 + 0.35 * std::cos(M_PI / 3), 1e-12);
  EXPECT_NEAR(y[1], 1.35, 1e-12);
  EXPECT_NEAR(y[2], 0.35 * std::sin(M_PI / 3), 1e-12);
}

TEST(TriangleSurfaceManifold, MinusInvertsOneCrossingOfAFold) {
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_folded_grid(20, 0.1, 1.0, M_PI / 3, &v, &t);
  TriangleSurfaceManifold surface(v, t);
  const double x[3] = {0.97, 1.05, 0};
  double jac[6];
  surface.PlusJacobian(x, jac);
  const double step[2] = {0.05, 0.01};  // into the neighbouring triangle beyond the fold
  const double d[2] = {jac[0] * step[0] + jac[2] * step[1], jac[1] * step[0] + jac[3] * step[1]};
  double y[3], back[2];
  ASSERT_TRUE(surface.Plus(x, d, y));
  EXPECT_NEAR(y[2], 0.02 * std::sin(M_PI / 3), 1e-14);
  ASSERT_TRUE(surface.Minus(y, x, back));
  EXPECT_NEAR(back[0], d[0], 1e-14);
  EXPECT_NEAR(back[1], d[1], 1e-14);
}

TEST(TriangleSurfaceManifold, InvariantsInsideFaces) {
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_sphere(1.0, 12, &v, &t);
  TriangleSurfaceManifold surface(v, t);
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 30; ++trial) {
    // The centroid of a random face, moved a little: well inside the face.
    const int f =
        static_cast<int>(std::uniform_int_distribution<int>(0, surface.num_triangles() - 1)(rng));
    Eigen::VectorXd x(3), y(3), delta(2), dy(2);
    for (int i = 0; i < 3; ++i)
      x[i] = (v[3 * t[3 * f] + i] + v[3 * t[3 * f + 1] + i] + v[3 * t[3 * f + 2] + i]) / 3;
    delta << 1e-3 * u(rng), 1e-3 * u(rng);
    dy << 1e-3 * u(rng), 1e-3 * u(rng);
    ASSERT_TRUE(surface.Plus(x.data(), dy.data(), y.data()));
    testing_util::ExpectManifoldInvariants(surface, x, delta, y, 1e-12);
  }
}

TEST(TriangleSurfaceManifold, PlusStaysOnTheMesh) {
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_sphere(2.0, 10, &v, &t);
  TriangleSurfaceManifold surface(v, t);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  double x[3] = {2, 0, 0};
  for (int step = 0; step < 500; ++step) {
    const double d[2] = {0.3 * u(rng), 0.3 * u(rng)};
    double y[3];
    ASSERT_TRUE(surface.Plus(x, d, y));
    EXPECT_LE(surface.Distance(y), 1e-14);
    // On or inside the sphere the triangulation is inscribed in.
    EXPECT_LE(vec3::norm(y), 2.0 * (1 + 1e-14));
    std::copy(y, y + 3, x);
  }
}

TEST(TriangleSurfaceManifold, DoesNotJumpBetweenCloseSheets) {
  // Two concentric triangulated spheres 0.05 apart with edges of about 0.26: a plain
  // closest-point projection of a tangent step of 0.5 lands on the outer sheet.
  std::vector<double> v;
  std::vector<std::int32_t> t;
  add_sphere(1.0, 12, &v, &t);
  std::vector<double> inner_v = v;
  std::vector<std::int32_t> inner_t = t;
  add_sphere(1.05, 12, &v, &t);
  TriangleSurfaceManifold both(v, t);
  TriangleSurfaceManifold inner(inner_v, inner_t);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  int naive_jumps = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double r[3] = {u(rng), u(rng), u(rng)};
    vec3::normalize(r);
    double x[3];
    inner.Project(r, x);
    double d[2] = {0.5 * u(rng), 0.5 * u(rng)};
    double y[3];
    ASSERT_TRUE(both.Plus(x, d, y));
    EXPECT_LE(inner.Distance(y), 1e-14) << "jumped to the outer sheet";
    // What a global projection of the same tangent step would do.
    double jac[6], q[3], naive[3];
    both.PlusJacobian(x, jac);
    for (int i = 0; i < 3; ++i) q[i] = x[i] + jac[2 * i] * d[0] + jac[2 * i + 1] * d[1];
    both.Project(q, naive);
    if (inner.Distance(naive) > 1e-3) ++naive_jumps;
  }
  EXPECT_GT(naive_jumps, 0) << "the test geometry does not tempt a naive projection";
}

}  // namespace
}  // namespace tmop
