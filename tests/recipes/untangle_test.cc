#include "tmop/recipes/untangle.h"

#include <gtest/gtest.h>

#include <random>

#include "tests/optimize/grid_meshes.h"
#include "tmop/mesh/fold_check.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

using testing_grid::grid;

// Moves every interior vertex by a random vector of up to `amount` grid spacings (no validity
// check), so a fraction of the elements inverts.
void tangle(Mesh* m, int n, double amount, std::mt19937* rng) {
  const std::vector<char> boundary = boundary_vertex_mask(*m);
  std::uniform_real_distribution<double> u(-amount / n, amount / n);
  for (int v = 0; v < m->num_vertices(); ++v)
    if (!boundary[v])
      for (int a = 0; a < m->space_dim; ++a) m->vertex(v)[a] += u(*rng);
}

int inverted(const Mesh& m) {
  return std::max(measure_mesh(m, SampleRule::kDefault).inverted,
                  measure_mesh(m, SampleRule::kCorners).inverted);
}

struct Case {
  CellType type;
  int n;
  double amount;
};

class Untangle : public ::testing::TestWithParam<Case> {};

TEST_P(Untangle, LeavesNothingInvertedBySignAndByFolds) {
  const Case c = GetParam();
  std::mt19937 rng(42);
  Mesh mesh = grid(c.type, c.n);
  tangle(&mesh, c.n, c.amount, &rng);
  const int before = inverted(mesh);
  ASSERT_GT(before, 0);
  UntangleOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(inverted(mesh), 0);
  EXPECT_TRUE(folded_facets(mesh).empty());
  EXPECT_GT(result.after.min_quality, 0);
  std::printf("%s n=%d: %d of %d inverted -> 0 (%d solves, %.3f s), worst quality %.3f\n",
              cell_name(c.type), c.n, before, mesh.num_elements(), result.stages[0].solves,
              result.seconds, result.after.min_quality);
}

INSTANTIATE_TEST_SUITE_P(
    Grids, Untangle,
    ::testing::Values(Case{CellType::kTri3, 12, 0.6}, Case{CellType::kTri3, 12, 1.2},
                      Case{CellType::kQuad4, 12, 0.8}, Case{CellType::kTet4, 5, 0.6},
                      Case{CellType::kTet4, 5, 1.0}, Case{CellType::kHex8, 5, 0.8}),
    [](const auto& info) {
      return std::string(cell_name(info.param.type)) + "_" +
             std::to_string(static_cast<int>(info.param.amount * 10));
    });

// 500 random tangled small meshes in 2D and 3D: all untangled (their boundaries are valid, so a
// valid position exists for every interior vertex).
TEST(Untangle, PropertyRandomSmallMeshes) {
  std::mt19937 rng(99);
  const CellType types[4] = {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8};
  int tangled = 0, untangled = 0;
  for (int trial = 0; trial < 125; ++trial)
    for (CellType type : types) {
      const int n = cell_dim(type) == 2 ? 4 : 3;
      Mesh mesh = grid(type, n);
      tangle(&mesh, n, 0.9, &rng);
      if (inverted(mesh) == 0) continue;
      ++tangled;
      UntangleOptions opt;
      opt.solver.threads = 1;
      opt.improve_shape_after = false;
      RecipeResult result;
      Status s = untangle(&mesh, opt, &result);
      EXPECT_TRUE(s.ok()) << cell_name(type) << " trial " << trial << ": " << s.message();
      if (s.ok() && inverted(mesh) == 0 && folded_facets(mesh).empty()) ++untangled;
    }
  EXPECT_GT(tangled, 300);
  EXPECT_EQ(untangled, tangled);
}

TEST(Untangle, FailsClearlyWhenAnInvertedElementHasEveryNodeFixed) {
  Mesh mesh = grid(CellType::kTri3, 2);
  // fold a boundary triangle: all of its nodes are boundary (fixed) vertices
  mesh.vertex(1)[1] = 0.9;  // bottom middle vertex pushed up through its neighbours
  std::vector<char> fixed(mesh.num_vertices(), 1);
  UntangleOptions opt;
  opt.fixed = fixed;
  RecipeResult result;
  const std::vector<double> before = mesh.coords;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("every node fixed"), std::string::npos) << s.message();
  EXPECT_EQ(mesh.coords, before);
}

}  // namespace
}  // namespace tmop
