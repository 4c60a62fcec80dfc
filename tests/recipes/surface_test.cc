// A lat-long triangulation of the unit sphere with needles near one pole, tiny triangles near
// the other and a valence-64 vertex at each pole, smoothed on the exact sphere: every vertex
// stays on the sphere, nothing folds, and the shapes improve.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tmop/quality/quality_report.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

Mesh latlong_sphere(int nlat, int nlon, double grading) {
  Mesh m;
  m.space_dim = 3;
  const double north[3] = {0, 0, 1}, south[3] = {0, 0, -1};
  m.add_vertex(north);
  for (int i = 1; i < nlat; ++i) {
    const double th = M_PI * std::pow(double(i) / nlat, grading);
    for (int j = 0; j < nlon; ++j) {
      const double ph = 2 * M_PI * j / nlon;
      const double x[3] = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      m.add_vertex(x);
    }
  }
  const int s = m.add_vertex(south);
  auto id = [&](int i, int j) { return 1 + (i - 1) * nlon + (j % nlon); };
  for (int j = 0; j < nlon; ++j) {
    const std::int32_t t[3] = {0, id(1, j), id(1, j + 1)};
    m.add_cell(CellType::kTri3, t);
  }
  for (int i = 1; i < nlat - 1; ++i)
    for (int j = 0; j < nlon; ++j) {
      const std::int32_t a[3] = {id(i, j), id(i + 1, j), id(i + 1, j + 1)};
      const std::int32_t b[3] = {id(i, j), id(i + 1, j + 1), id(i, j + 1)};
      m.add_cell(CellType::kTri3, a);
      m.add_cell(CellType::kTri3, b);
    }
  for (int j = 0; j < nlon; ++j) {
    const std::int32_t t[3] = {s, id(nlat - 1, j + 1), id(nlat - 1, j)};
    m.add_cell(CellType::kTri3, t);
  }
  return m;
}

TEST(SurfaceRecipe, LatLongSphereOnTheExactSphere) {
  Mesh mesh = latlong_sphere(32, 64, 1.6);
  ASSERT_EQ(mesh.num_elements(), 3968);
  const QualityReport before = compute_quality(mesh);
  UntangleOptions opt;  // the surface recipe: untangle if folded, then shape, on the geometry
  opt.slide = true;
  opt.boundary.geometry = "sphere:0,0,0,1";
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const QualityReport after = compute_quality(mesh);
  double off = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double* x = mesh.vertex(v);
    off = std::max(off, std::abs(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1));
  }
  EXPECT_LT(off, 1e-12);
  EXPECT_EQ(result.after.inverted, 0);  // measured in the sphere's tangent frames
  EXPECT_GE(after.mean_ratio.mean, 0.90);
  EXPECT_GT(after.mean_ratio.min, 1.4 * before.mean_ratio.min);
  std::printf("sphere: mean ratio min %.3f -> %.3f, mean %.3f -> %.3f; max |r - 1| %.1e\n",
              before.mean_ratio.min, after.mean_ratio.min, before.mean_ratio.mean,
              after.mean_ratio.mean, off);
}

}  // namespace
}  // namespace tmop
