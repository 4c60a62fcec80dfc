#include "tmop/recipes/laplace.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>

#include "tests/optimize/grid_meshes.h"
#include "tests/recipes/recipe_test_meshes.h"
#include "tests/temp_dir.h"
#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

using testing_grid::grid;
using testing_grid::perturb;

// 200 random valid perturbed meshes of every linear type: Laplace never inverts anything and
// never lowers the worst quality; on average it improves the mean quality.
TEST(Laplace, PropertyNeverInvertsNeverLowersTheWorst) {
  std::mt19937 rng(7);
  const CellType types[4] = {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8};
  int runs = 0, improved_mean = 0;
  for (int trial = 0; trial < 50; ++trial)
    for (CellType type : types) {
      const int n = cell_dim(type) == 2 ? 6 : 3;
      Mesh mesh = grid(type, n);
      perturb(&mesh, n, 0.45, &rng);
      const QualityReport before = compute_quality(mesh);
      ASSERT_EQ(before.inverted_cells, 0);
      LaplaceOptions opt;
      RecipeResult result;
      Status s = laplace(&mesh, opt, &result);
      ASSERT_TRUE(s.ok()) << s.message();
      const QualityReport after = compute_quality(mesh);
      ++runs;
      EXPECT_EQ(after.inverted_cells, 0) << cell_name(type) << " trial " << trial;
      EXPECT_EQ(result.after.inverted, 0);
      EXPECT_GE(result.after.min_quality, result.before.min_quality - 1e-12);
      const bool simplex = type == CellType::kTri3 || type == CellType::kTet4;
      const double mean_before = simplex ? before.mean_ratio.mean : before.scaled_jacobian.mean;
      const double mean_after = simplex ? after.mean_ratio.mean : after.scaled_jacobian.mean;
      improved_mean += mean_after > mean_before;
    }
  std::printf("laplace: %d random meshes, 0 inverted after, mean quality improved in %d\n", runs,
              improved_mean);
  EXPECT_GE(improved_mean, runs * 9 / 10);
}

// A heavily perturbed quad grid: the untangled-by-construction mesh comes back close to the
// regular grid (Laplace's fixed point for a structured grid is the grid itself).
TEST(Laplace, RecoversTheRegularGrid) {
  std::mt19937 rng(3);
  const int n = 10;
  Mesh mesh = grid(CellType::kQuad4, n);
  const std::vector<double> regular = mesh.coords;
  perturb(&mesh, n, 0.4, &rng);
  LaplaceOptions opt;
  opt.max_sweeps = 500;
  RecipeResult result;
  ASSERT_TRUE(laplace(&mesh, opt, &result).ok());
  double max_dev = 0;
  for (std::size_t i = 0; i < regular.size(); ++i)
    max_dev = std::max(max_dev, std::abs(mesh.coords[i] - regular[i]));
  std::printf(
      "laplace quad grid n=%d: worst quality %.3f -> %.3f, %d sweeps, max deviation from "
      "the grid %.2e spacings\n",
      n, result.before.min_quality, result.after.min_quality, result.stages[0].iterations,
      max_dev * n);
  EXPECT_LT(max_dev * n, 1e-3);
  EXPECT_LT(result.stages[0].iterations, 500);  // stopped by the tolerance
}

// The gmsh graded triangle mesh of the size_adapt tests, shapes perturbed: Laplace restores
// shapes but, unlike size_adapt, pulls sizes toward uniform (recorded for docs/recipes/laplace.md).
TEST(Laplace, GradedTrianglesStayValid) {
  if (!testing_recipes::have_gmsh()) GTEST_SKIP() << "gmsh not available";
  Mesh mesh;
  ASSERT_TRUE(testing_recipes::graded_mesh(testing_tmp::dir(), false, &mesh));
  std::mt19937 rng(11);
  testing_recipes::perturb_valid(&mesh, boundary_vertex_mask(mesh), 0.35, &rng);
  const Mesh perturbed = mesh;
  const QualityReport before = compute_quality(mesh);
  RecipeResult result;
  ASSERT_TRUE(laplace(&mesh, LaplaceOptions(), &result).ok());
  const QualityReport after = compute_quality(mesh);
  if (const char* dir = std::getenv("TMOP_RECIPE_OUTPUT")) {
    EXPECT_TRUE(write_mesh(std::string(dir) + "/laplace_before.vtu", perturbed).ok());
    EXPECT_TRUE(write_mesh(std::string(dir) + "/laplace_after.vtu", mesh).ok());
  }
  std::printf(
      "laplace graded tris (%lld): mean ratio mean %.3f -> %.3f, min %.3f -> %.3f, "
      "unique edges min %.4f -> %.4f, max %.4f -> %.4f, %d sweeps, %.3f s\n",
      static_cast<long long>(after.num_elements), before.mean_ratio.mean, after.mean_ratio.mean,
      before.mean_ratio.min, after.mean_ratio.min, before.edge_length.min, after.edge_length.min,
      before.edge_length.max, after.edge_length.max, result.stages[0].iterations, result.seconds);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_GE(after.mean_ratio.min, before.mean_ratio.min);
  EXPECT_GT(after.mean_ratio.mean, before.mean_ratio.mean);
}

// A fan around a free vertex whose ring has a long thin spike: the centroid of the ring lies in
// the spike, outside the region from which the vertex sees every ring edge, so moving there
// would invert two triangles. The move is refused and the vertex stays exactly where it was.
TEST(Laplace, RefusesAMoveThatWouldInvert) {
  Mesh mesh;
  mesh.space_dim = 2;
  const double x[8][2] = {{0, 0},    {-0.5, -0.5}, {0.2, -0.05}, {3, -0.02},
                          {3.05, 0}, {3, 0.02},    {0.2, 0.05},  {-0.5, 0.5}};
  for (const auto& p : x) mesh.add_vertex(p);
  for (std::int32_t i = 1; i <= 7; ++i) {
    const std::int32_t t[3] = {0, i, i % 7 + 1};
    mesh.add_cell(CellType::kTri3, t);
  }
  ASSERT_EQ(compute_quality(mesh).inverted_cells, 0);
  LaplaceOptions opt;
  opt.fixed = {0, 1, 1, 1, 1, 1, 1, 1};
  RecipeResult result;
  ASSERT_TRUE(laplace(&mesh, opt, &result).ok());
  EXPECT_EQ(mesh.vertex(0)[0], 0.0);
  EXPECT_EQ(mesh.vertex(0)[1], 0.0);
  EXPECT_EQ(compute_quality(mesh).inverted_cells, 0);
  EXPECT_EQ(result.stages[0].iterations, 1);  // nothing moved: stops after the first sweep
}

TEST(Laplace, RefusesQuadraticElements) {
  Mesh mesh;
  mesh.space_dim = 2;
  const double x[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  for (const auto& p : x) mesh.add_vertex(p);
  const std::int32_t t[6] = {0, 1, 2, 3, 4, 5};
  mesh.add_cell(CellType::kTri6, t);
  RecipeResult result;
  const Status s = laplace(&mesh, LaplaceOptions(), &result);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("quadratic"), std::string::npos);
}

}  // namespace
}  // namespace tmop
