// Geometry fidelity without and with a user geometry: the smooth shape of TriangleSurfaceManifold
// (a cubic patch per facet through the vertices) keeps the Ceres manifold invariants, reproduces
// a sphere to a fraction of the flat facets' error and keeps flat regions exactly flat;
// ProjectedCurveManifold keeps an open cap's rim on the sphere.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "tests/geometry/curved_test_meshes.h"
#include "tests/geometry/manifold_invariants.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/geometry/projected_curve_manifold.h"
#include "tmop/geometry/sphere_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"

namespace tmop {
namespace {

using Shape = TriangleSurfaceManifold::Shape;

TriangleSurfaceManifold surface_of(const Mesh& m, Shape shape) {
  std::vector<std::int32_t> t(m.cell_nodes.begin(), m.cell_nodes.end());
  return TriangleSurfaceManifold(m.coords, t, shape);
}

// The centroid of cell c pushed out radially by `lift` (an off-surface start point).
Eigen::Vector3d centroid(const Mesh& m, int c, double lift = 1) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) p += Eigen::Map<const Eigen::Vector3d>(m.vertex(m.cell(c)[k]));
  return lift * p / 3;
}

TEST(SmoothSurface, InvariantsAndIdempotenceOnASphere) {
  const double c[3] = {0, 0, 0};
  const Mesh m = curved_meshes::cube_sphere(4, 5.0, c, true, 0.25);
  const TriangleSurfaceManifold s = surface_of(m, Shape::kSmooth);
  ASSERT_TRUE(s.smooth());
  for (int cell : {0, 17, 60, 101, 150}) {
    Eigen::Vector3d x, y, back;
    const Eigen::Vector3d start = centroid(m, cell, 1.02);
    s.Project(start.data(), x.data());
    const Eigen::Vector3d near = x + 0.05 * (centroid(m, cell) - x).cross(x).normalized();
    s.Project(near.data(), y.data());
    // Projecting a point of the surface returns it (Plus(x, 0) = x rests on it).
    s.Project(x.data(), back.data());
    EXPECT_LE((back - x).norm(), 1e-13) << cell;
    Eigen::Vector2d d(0.03, -0.02);
    testing_util::ExpectManifoldInvariants(s, x, d, y, 1e-9);
    // Plus lands on the surface, and steps across facets too.
    Eigen::Vector2d big(0.9, 0.4);
    Eigen::Vector3d moved, again;
    ASSERT_TRUE(s.Plus(x.data(), big.data(), moved.data()));
    s.Project(moved.data(), again.data());
    EXPECT_LE((again - moved).norm(), 1e-12) << cell;
    // The normal is the cross product of the tangents, outward here.
    double n[3];
    ASSERT_TRUE(s.Normal(x.data(), n));
    EXPECT_GT(Eigen::Map<Eigen::Vector3d>(n).dot(x.normalized()), 0.99);
  }
}

TEST(SmoothSurface, FollowsTheSphereThroughTheVertices) {
  const double c[3] = {1, -2, 0.5};
  for (bool perturbed : {false, true}) {
    const Mesh m = curved_meshes::cube_sphere(4, 5.0, c, true, perturbed ? 0.25 : 0);
    const TriangleSurfaceManifold flat = surface_of(m, Shape::kFlat);
    const TriangleSurfaceManifold smooth = surface_of(m, Shape::kSmooth);
    const Eigen::Vector3d centre(c[0], c[1], c[2]);
    double flat_err = 0, smooth_err = 0, vertex_err = 0;
    for (int v = 0; v < m.num_vertices(); ++v) {  // through the vertices
      Eigen::Vector3d p;
      smooth.Project(m.vertex(v), p.data());
      vertex_err =
          std::max(vertex_err, (p - Eigen::Map<const Eigen::Vector3d>(m.vertex(v))).norm());
    }
    // Sample every facet at 6 interior points (radial rays through them).
    for (int cell = 0; cell < m.num_cells(); ++cell) {
      for (int k = 0; k < 6; ++k) {
        const double l0 = (1 + k % 3) / 6.0, l1 = (1 + k / 3) / 5.0;
        Eigen::Vector3d q = centre;
        const double lam[3] = {l0, l1, 1 - l0 - l1};
        for (int j = 0; j < 3; ++j)
          q += lam[j] * (Eigen::Map<const Eigen::Vector3d>(m.vertex(m.cell(cell)[j])) - centre);
        Eigen::Vector3d a, b;
        flat.Project(q.data(), a.data());
        smooth.Project(q.data(), b.data());
        flat_err = std::max(flat_err, std::abs((a - centre).norm() - 5));
        smooth_err = std::max(smooth_err, std::abs((b - centre).norm() - 5));
      }
    }
    std::printf("radius-5 triangle sphere%s: off the sphere: flat %.4f, smooth %.5f\n",
                perturbed ? " (perturbed)" : "", flat_err, smooth_err);
    EXPECT_LE(vertex_err, 1e-12);
    EXPECT_GT(flat_err, 0.15);
    EXPECT_LT(smooth_err, 0.03);  // measured 0.0067 / 0.0189
    EXPECT_LT(smooth_err, flat_err / 10);
  }
}

// A plane z = 0 for x < 0 joined to a bend (z = x^2 for x > 0): points of the flat part stay
// at z = 0 exactly; the bend is curved.
TEST(SmoothSurface, FlatRegionsStayExactlyFlat) {
  Mesh m;
  m.space_dim = 3;
  const int n = 8;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = -1 + 2.0 * i / n, y = 2.0 * j / n;
      const double p[3] = {x, y, x > 0 ? x * x : 0};
      m.add_vertex(p);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      const std::int32_t t1[3] = {a, a + 1, a + n + 2}, t2[3] = {a, a + n + 2, a + n + 1};
      m.add_cell(CellType::kTri3, t1);
      m.add_cell(CellType::kTri3, t2);
    }
  }
  const TriangleSurfaceManifold s = surface_of(m, Shape::kSmooth);
  // Far from the bend (x <= -0.5: every vertex of the facets and of their 1-rings is at z = 0).
  const double starts[3][3] = {{-0.9, 0.3, 0.2}, {-0.7, 1.1, -0.1}, {-0.6, 1.7, 0}};
  for (const auto& start : starts) {
    double x[3], out[3];
    s.Project(start, x);
    EXPECT_EQ(x[2], 0.0);
    const double d[2] = {0.13, -0.07};
    ASSERT_TRUE(s.Plus(x, d, out));
    EXPECT_EQ(out[2], 0.0);
  }
  // The bend: a point between vertices is off the chord, towards the parabola.
  const double mid[3] = {0.375, 1.0, 0.15};
  double p[3];
  s.Project(mid, p);
  EXPECT_LT(std::abs(p[2] - p[0] * p[0]), 0.004);  // the chord is 0.0156 off at x = 0.375
}

TEST(ProjectedCurve, RimOnTheSphere) {
  const double c[3] = {0, 0, 0};
  const SphereManifold sphere(c, 10.0);
  const int around = 24;
  for (bool closed : {true, false}) {
    std::vector<double> points;
    const int count = closed ? around : around / 2 + 1;
    for (int i = 0; i < count; ++i) {
      const double t = 2 * M_PI * i / around, a = 0.6 + 0.05 * curved_meshes::jitter(i, 0);
      const double p[3] = {10 * std::sin(a) * std::cos(t), 10 * std::sin(a) * std::sin(t),
                           10 * std::cos(a)};
      points.insert(points.end(), p, p + 3);
    }
    const ProjectedCurveManifold curve(points, closed, &sphere);
    for (int i = 1; i + 1 < count; ++i) {  // through the vertices
      double out[3];
      const double zero = 0;
      ASSERT_TRUE(curve.Plus(&points[3 * i], &zero, out));
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[k], points[3 * i + k], 1e-12);
    }
    for (int i : {2, 5, 9}) {
      Eigen::Vector3d mid, x, y;
      for (int k = 0; k < 3; ++k) mid[k] = 0.6 * points[3 * i + k] + 0.4 * points[3 * i + 3 + k];
      curve.Project(mid.data(), x.data());
      EXPECT_NEAR(x.norm(), 10, 1e-12);
      const Eigen::Vector3d off = 0.3 * mid + 0.7 * Eigen::Map<Eigen::Vector3d>(&points[3 * i]);
      curve.Project(off.data(), y.data());
      Eigen::VectorXd d(1);
      d[0] = 0.2;
      testing_util::ExpectManifoldInvariants(curve, x, d, y, 1e-8);
      // Long steps cross vertices and stay on the sphere.
      double far[3];
      const double step = closed ? 25.0 : 3.0;
      ASSERT_TRUE(curve.Plus(x.data(), &step, far));
      EXPECT_NEAR(Eigen::Map<Eigen::Vector3d>(far).norm(), 10, 1e-12);
    }
  }
}

// BoundaryConstraints puts an open cap's rim on the analytic sphere and keeps polylines without
// one; the own-boundary patch is smooth.
TEST(ProjectedCurve, BoundaryConstraintsUseItForTheCapRim) {
  const Mesh cap = curved_meshes::spherical_cap(10, 0.6, 6, 24, 0.2);
  const int around = 24;
  for (const char* geometry : {"sphere:0,0,0,10", ""}) {
    BoundaryOptions o;
    o.geometry = geometry;
    std::unique_ptr<BoundaryConstraints> bc;
    ASSERT_TRUE(BoundaryConstraints::Build(cap, o, &bc).ok());
    int rim = -1, fixed = 0;
    for (int v = cap.num_vertices() - around; v < cap.num_vertices(); ++v) {
      if (rim < 0 && bc->kind(v) == VertexKind::kCurve) rim = v;
      fixed += bc->kind(v) == VertexKind::kFixed;
    }
    ASSERT_GE(rim, 0);
    const GeometryManifold* g = bc->geometry(rim);
    ASSERT_NE(g, nullptr);
    const bool projected = dynamic_cast<const ProjectedCurveManifold*>(g) != nullptr;
    EXPECT_EQ(projected, *geometry != 0) << geometry;
    double out[3];
    const double step = 0.4;
    ASSERT_TRUE(g->Plus(cap.vertex(rim), &step, out));
    const double r = Eigen::Map<Eigen::Vector3d>(out).norm();
    if (projected) {
      EXPECT_NEAR(r, 10, 1e-12);
    } else {
      EXPECT_GT(std::abs(r - 10), 1e-4);  // on a chord
    }
    EXPECT_EQ(bc->num_on_user_geometry(), *geometry ? cap.num_vertices() - fixed : 0);
  }
}

}  // namespace
}  // namespace tmop
