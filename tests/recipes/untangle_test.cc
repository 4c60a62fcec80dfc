#include "tmop/recipes/untangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/optimize/grid_meshes.h"
#include "tmop/mesh/fold_check.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/guarantees.h"

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

// Every cube of an n^3 grid split into 6 pyramids (its faces as bases, its centre as apex).
Mesh pyramid_grid(int n) {
  Mesh cubes = grid(CellType::kHex8, n);
  Mesh m;
  m.space_dim = 3;
  for (int v = 0; v < cubes.num_vertices(); ++v) m.add_vertex(cubes.vertex(v));
  static const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                  {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (int c = 0; c < cubes.num_cells(); ++c) {
    double centre[3] = {0, 0, 0};
    for (int i = 0; i < 8; ++i)
      for (int a = 0; a < 3; ++a) centre[a] += cubes.vertex(cubes.cell(c)[i])[a] / 8;
    const int apex = m.add_vertex(centre);
    for (const auto& f : faces) {
      std::int32_t p[5] = {cubes.cell(c)[f[0]], cubes.cell(c)[f[1]], cubes.cell(c)[f[2]],
                           cubes.cell(c)[f[3]], apex};
      m.add_cell(CellType::kPyramid5, p);
    }
  }
  // Orient: reverse the base of every pyramid measured negative.
  if (check_orientation(m).negative > 0) {
    for (int c = 0; c < m.num_cells(); ++c) {
      Mesh one;
      one.space_dim = 3;
      for (int i = 0; i < 5; ++i) one.add_vertex(m.vertex(m.cell(c)[i]));
      const std::int32_t q[5] = {0, 1, 2, 3, 4};
      one.add_cell(CellType::kPyramid5, q);
      if (check_orientation(one).negative > 0) std::swap(m.cell(c)[1], m.cell(c)[3]);
    }
  }
  return m;
}

TEST(Untangle, PyramidGrid) {
  std::mt19937 rng(43);
  Mesh mesh = pyramid_grid(4);
  ASSERT_EQ(check_orientation(mesh).positive, mesh.num_elements());
  tangle(&mesh, 4, 0.8, &rng);
  const int before = inverted(mesh);
  ASSERT_GT(before, 0.05 * mesh.num_elements());
  UntangleOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(inverted(mesh), 0);
  EXPECT_TRUE(folded_facets(mesh).empty());
  std::printf("pyramid5 n=4: %d of %d inverted -> 0, worst quality %.3f\n", before,
              mesh.num_elements(), result.after.min_quality);
}

// 500 random tangled small meshes in 2D and 3D, their vertices first moved to make them
// unstructured: all untangled, or a clear failure exactly where an inverted element has every
// node fixed (in a quarter of the meshes the nodes of one inverted element are fixed as well as
// the boundary: those must fail, naming that element).
TEST(Untangle, PropertyRandomSmallMeshes) {
  std::mt19937 rng(99);
  const CellType types[4] = {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8};
  int tangled = 0, untangled = 0, honest_failures = 0;
  for (int trial = 0; trial < 125; ++trial)
    for (CellType type : types) {
      const int n = cell_dim(type) == 2 ? 4 : 3;
      Mesh mesh = grid(type, n);
      testing_grid::perturb(&mesh, n, 0.3, &rng);
      tangle(&mesh, n, 0.9, &rng);
      if (inverted(mesh) == 0) continue;
      ++tangled;
      UntangleOptions opt;
      opt.solver.threads = 1;
      opt.improve_shape_after = false;
      int held = -1;  // an inverted cell whose nodes are all fixed
      if (trial % 4 == 3) {
        opt.fixed = boundary_vertex_mask(mesh);
        for (int c = 0; c < mesh.num_cells() && held < 0; ++c) {
          Mesh one;
          one.space_dim = mesh.space_dim;
          std::vector<std::int32_t> q;
          for (int i = 0; i < mesh.cell_size(c); ++i)
            q.push_back(one.add_vertex(mesh.vertex(mesh.cell(c)[i])));
          one.add_cell(mesh.cell_type(c), q.data());
          if (inverted(one) == 0) continue;
          held = c;
          for (int i = 0; i < mesh.cell_size(c); ++i) opt.fixed[mesh.cell(c)[i]] = 1;
        }
      }
      RecipeResult result;
      Status s = untangle(&mesh, opt, &result);
      if (s.ok()) {
        EXPECT_LT(held, 0) << cell_name(type) << " trial " << trial;
        if (inverted(mesh) == 0 && folded_facets(mesh).empty()) ++untangled;
      } else {
        EXPECT_GE(held, 0) << cell_name(type) << " trial " << trial << ": " << s.message();
        EXPECT_NE(s.message().find("every node fixed: " + std::to_string(held)), std::string::npos)
            << s.message();
        ++honest_failures;
      }
    }
  std::printf("property: %d tangled, %d untangled, %d refused (inverted with every node fixed)\n",
              tangled, untangled, honest_failures);
  EXPECT_GT(tangled, 300);
  EXPECT_GT(honest_failures, 50);
  EXPECT_EQ(untangled + honest_failures, tangled);
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

// The eps schedule's sigma floor must lie in (0, 1): sigma >= 1 would set eps to 0 (or NaN),
// a negative one would let eps grow. Refused up front, the mesh untouched.
TEST(Untangle, RefusesASigmaFloorOutsideZeroOne) {
  Mesh mesh = grid(CellType::kTri3, 4);
  mesh.vertex(6)[0] += 0.6;  // fold an interior vertex over its neighbours
  const std::vector<double> before = mesh.coords;
  for (double sigma : {0.0, 1.0, -0.5, 2.0, std::nan("")}) {
    UntangleOptions opt;
    opt.sigma_min = sigma;
    RecipeResult result;
    const Status s = untangle(&mesh, opt, &result);
    ASSERT_FALSE(s.ok()) << sigma;
    EXPECT_NE(s.message().find("sigma_min"), std::string::npos) << s.message();
    EXPECT_EQ(mesh.coords, before);
  }
  UntangleOptions opt;
  opt.sigma_min = 0.1;  // the published floor still works
  RecipeResult result;
  EXPECT_TRUE(untangle(&mesh, opt, &result).ok());
}

}  // namespace
// RecipeOptions / ShapeOptions::input_baseline: the caller's guarantee baseline of the input
// (tmop_optimize's) gives the shape guard exactly the result of computing it, when the input
// needs no untangling; after untangling moved vertices it is of another mesh and is not used.
// On these grids the shape guard holds nothing, so this checks that the hand-over changes no
// result; part_1m's output is byte-identical too (docs/benchmarks.md).
TEST(Untangle, TheCallersBaselineServesOnlyAnInputLeftAsItWas) {
  for (unsigned seed = 1; seed <= 12; ++seed)
    for (bool tangled : {false, true}) {
      SCOPED_TRACE(std::string(tangled ? "tangled" : "valid") + " input, seed " +
                   std::to_string(seed));
      std::mt19937 rng(seed);
      const CellType type = seed % 2 ? CellType::kTri3 : CellType::kQuad4;
      Mesh input = grid(type, 10);
      if (tangled)
        tangle(&input, 10, 0.7, &rng);
      else
        testing_grid::perturb(&input, 10, 0.3, &rng);
      if (tangled && inverted(input) == 0) continue;
      const GuaranteeBaseline baseline = guarantee_baseline(input, 1);
      Mesh own = input, given = input;
      UntangleOptions opt;
      opt.solver.threads = 1;
      opt.shape.solver.threads = 1;
      opt.improve_shape_after = true;
      RecipeResult a, b;
      if (!untangle(&own, opt, &a).ok()) continue;  // a tangle this grid cannot undo
      opt.shape.input_baseline = &baseline;
      ASSERT_TRUE(untangle(&given, opt, &b).ok());
      EXPECT_EQ(own.coords, given.coords);
      EXPECT_EQ(a.guard_held_cells, b.guard_held_cells);
    }
}

}  // namespace tmop
