#include "tmop/recipes/size_adapt.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "tests/recipes/recipe_test_meshes.h"
#include "tests/temp_dir.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/quality_report.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

// Per-element equivalent edge lengths (target.h), in cell order.
std::vector<double> cell_sizes(const Mesh& mesh) {
  std::vector<double> h;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c)) h.push_back(cell_equivalent_edge(mesh, c));
  return h;
}

// Fraction of ratios a[i] / b[i] inside [lo, hi], and their median.
void ratio_stats(const std::vector<double>& a, const std::vector<double>& b, double lo, double hi,
                 double* inside, double* median) {
  std::vector<double> r(a.size());
  int in = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    r[i] = a[i] / b[i];
    in += r[i] >= lo && r[i] <= hi;
  }
  std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
  *median = r[r.size() / 2];
  *inside = static_cast<double>(in) / a.size();
}

class SizeAdaptGraded : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!testing_recipes::have_gmsh()) GTEST_SKIP() << "gmsh not available";
    ASSERT_TRUE(testing_recipes::graded_mesh(testing_tmp::dir(), false, &graded_));
    fixed_ = boundary_vertex_mask(graded_);
    sizes_ = cell_sizes(graded_);
    // The size field of the unperturbed mesh: each vertex's mean incident edge length.
    DataArray h{"h", 1, std::vector<double>(graded_.num_vertices(), 0)};
    std::vector<int> count(graded_.num_vertices(), 0);
    for (const auto& e : mesh_edges(graded_)) {
      double l2 = 0;
      for (int a = 0; a < 2; ++a)
        l2 += std::pow(graded_.vertex(e[1])[a] - graded_.vertex(e[0])[a], 2);
      for (int v : e) h.values[v] += std::sqrt(l2), ++count[v];
    }
    // gmsh keeps the attractor point as a vertex of no element: give it a harmless size.
    for (int v = 0; v < graded_.num_vertices(); ++v)
      h.values[v] = count[v] > 0 ? h.values[v] / count[v] : 1.0;
    graded_.point_data.push_back(h);
    perturbed_ = graded_;
    std::mt19937 rng(11);
    testing_recipes::perturb_valid(&perturbed_, fixed_, 0.35, &rng);
  }
  Mesh graded_, perturbed_;
  std::vector<char> fixed_;
  std::vector<double> sizes_;  // of the unperturbed mesh
};

// With the size field of the graded mesh, a shape-perturbed copy gets its shapes back and every
// element's size comes back to the field: median size ratio within 10% of 1 and 90% of the
// elements within [0.75, 1.33], while the mean and the worst mean ratio improve.
TEST_F(SizeAdaptGraded, SizeFieldRestoresGradingAndShapes) {
  Mesh mesh = perturbed_;
  const QualityReport before = compute_quality(mesh);
  double in0, med0;
  ratio_stats(cell_sizes(mesh), sizes_, 0.75, 1.33, &in0, &med0);
  SizeAdaptOptions opt;
  opt.size_field = "h";
  opt.solver.threads = 1;
  RecipeResult result;
  const Status s = size_adapt(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const QualityReport after = compute_quality(mesh);
  // The target sizes are the field at the cell: compare with the field's cell means.
  const DataArray& h = mesh.point_data[0];
  std::vector<double> target;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) sum += h.values[mesh.cell(c)[i]];
    target.push_back(sum / 3);
  }
  double in_t0, med_t0, in_t1, med_t1;
  ratio_stats(cell_sizes(perturbed_), target, 0.75, 1.33, &in_t0, &med_t0);
  ratio_stats(cell_sizes(mesh), target, 0.75, 1.33, &in_t1, &med_t1);
  std::printf(
      "size_adapt (size field) %lld tris: size/target median %.3f -> %.3f, within [0.75,1.33] "
      "%.1f%% -> %.1f%%; mean ratio mean %.3f -> %.3f, min %.3f -> %.3f; %d iterations %.2f s\n",
      static_cast<long long>(after.num_elements), med_t0, med_t1, 100 * in_t0, 100 * in_t1,
      before.mean_ratio.mean, after.mean_ratio.mean, before.mean_ratio.min, after.mean_ratio.min,
      result.stages[0].iterations, result.seconds);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_NEAR(med_t1, 1.0, 0.1);
  EXPECT_GE(in_t1, 0.9);
  EXPECT_GT(after.mean_ratio.mean, before.mean_ratio.mean);
  EXPECT_GT(after.mean_ratio.min, before.mean_ratio.min);
}

// Default targets (each element's own initial size): the grading is kept, element by element,
// while the shapes improve.
TEST_F(SizeAdaptGraded, LocalSizeKeepsGradingImprovesShapes) {
  Mesh mesh = perturbed_;
  const std::vector<double> initial = cell_sizes(mesh);
  const QualityReport before = compute_quality(mesh);
  SizeAdaptOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  const Status s = size_adapt(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  if (const char* dir = std::getenv("TMOP_RECIPE_OUTPUT")) {
    EXPECT_TRUE(write_mesh(std::string(dir) + "/size_adapt_before.vtu", perturbed_).ok());
    EXPECT_TRUE(write_mesh(std::string(dir) + "/size_adapt_after.vtu", mesh).ok());
  }
  const QualityReport after = compute_quality(mesh);
  double inside, median;
  ratio_stats(cell_sizes(mesh), initial, 0.75, 1.33, &inside, &median);
  const std::vector<double> final_sizes = cell_sizes(mesh);
  const auto [lo0, hi0] = std::minmax_element(initial.begin(), initial.end());
  const auto [lo1, hi1] = std::minmax_element(final_sizes.begin(), final_sizes.end());
  std::printf(
      "size_adapt (local size) %lld tris: size/initial median %.3f, within [0.75,1.33] %.1f%%; "
      "size range %.1fx -> %.1fx; mean ratio mean %.3f -> %.3f, min %.3f -> %.3f; %d iterations "
      "%.2f s\n",
      static_cast<long long>(after.num_elements), median, 100 * inside, *hi0 / *lo0, *hi1 / *lo1,
      before.mean_ratio.mean, after.mean_ratio.mean, before.mean_ratio.min, after.mean_ratio.min,
      result.stages[0].iterations, result.seconds);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_NEAR(median, 1.0, 0.05);
  EXPECT_GE(inside, 0.9);
  EXPECT_GT(*hi1 / *lo1, 0.7 * (*hi0 / *lo0));  // the grading is not smoothed away
  EXPECT_GT(after.mean_ratio.mean, before.mean_ratio.mean);
  EXPECT_GT(after.mean_ratio.min, before.mean_ratio.min);
}

TEST(SizeAdapt, MissingSizeFieldFailsClearly) {
  Mesh mesh;
  mesh.space_dim = 2;
  const double x[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (const auto& p : x) mesh.add_vertex(p);
  const std::int32_t t[3] = {0, 1, 2};
  mesh.add_cell(CellType::kTri3, t);
  SizeAdaptOptions opt;
  opt.size_field = "nope";
  opt.fixed = {0, 0, 1};
  RecipeResult result;
  const Status s = size_adapt(&mesh, opt, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("nope"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace tmop
