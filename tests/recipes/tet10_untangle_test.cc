// Quadratic tets: a tet10 grid whose interior nodes (corner and mid-edge) were moved randomly so
// that elements fold, untangled and certified valid everywhere by the Bernstein bound.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <random>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

// Adds straight mid-edge nodes to every tet4 (Gmsh tet10 edge order from the cell table).
Mesh to_tet10(const Mesh& in) {
  Mesh out;
  out.space_dim = 3;
  out.coords = in.coords;
  std::map<std::pair<int, int>, int> mid;
  const CellInfo& info = cell_info(CellType::kTet10);
  for (int c = 0; c < in.num_cells(); ++c) {
    std::int32_t nodes[10];
    for (int i = 0; i < 4; ++i) nodes[i] = in.cell(c)[i];
    for (int e = 0; e < 6; ++e) {
      int a = nodes[info.edges[e][0]], b = nodes[info.edges[e][1]];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it == mid.end()) {
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = (out.vertex(a)[k] + out.vertex(b)[k]) / 2;
        it = mid.emplace(key, out.add_vertex(x)).first;
      }
      nodes[4 + e] = it->second;
    }
    out.add_cell(CellType::kTet10, nodes);
  }
  return out;
}

TEST(QuadraticUntangle, Tet10GridIsCertifiedValid) {
  Mesh mesh = to_tet10(testing_grid::grid(CellType::kTet4, 3));
  const std::vector<char> boundary = boundary_vertex_mask(mesh);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-0.22, 0.22);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (boundary[v]) continue;
    for (int a = 0; a < 3; ++a) mesh.vertex(v)[a] += u(rng) / 3;
  }
  const QualityReport before = compute_quality(mesh);
  ASSERT_GT(before.inverted_cells, 5);
  UntangleOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const QualityReport after = compute_quality(mesh);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_EQ(result.certified, mesh.num_elements());
  std::printf("tet10: %lld of %d inverted (sample points or certificate) -> %lld; certified %d\n",
              static_cast<long long>(before.inverted_cells), mesh.num_elements(),
              static_cast<long long>(after.inverted_cells), result.certified);
}

// A mid-edge node of an edge in the cube's z = 0 face moved along its edge to 0.9 of the way: the
// cells around that edge fold at its end, and with the boundary fixed nothing can repair them.
// The failure counts them as tmop_quality does and suggests sliding, which repairs them.
TEST(QuadraticUntangle, FoldedBoundaryEdgeFailsFixedAndUntanglesSliding) {
  Mesh mesh = to_tet10(testing_grid::grid(CellType::kTet4, 3));
  const CellInfo& info = cell_info(CellType::kTet10);
  int moved = -1;
  for (int c = 0; c < mesh.num_cells() && moved < 0; ++c)
    for (int e = 0; e < 6 && moved < 0; ++e) {
      const double* a = mesh.vertex(mesh.cell(c)[info.edges[e][0]]);
      const double* b = mesh.vertex(mesh.cell(c)[info.edges[e][1]]);
      auto inside_face = [](const double* x) {
        return x[2] == 0 && x[0] > 0 && x[0] < 1 && x[1] > 0 && x[1] < 1;
      };
      if (!inside_face(a) || !inside_face(b)) continue;
      moved = mesh.cell(c)[4 + e];
      for (int k = 0; k < 3; ++k) mesh.vertex(moved)[k] = a[k] + 0.9 * (b[k] - a[k]);
    }
  ASSERT_GE(moved, 0);
  const long long before = compute_quality(mesh).inverted_cells;
  ASSERT_GT(before, 0);
  Mesh fixed_run = mesh;
  UntangleOptions opt;
  opt.solver.threads = 1;
  opt.max_rounds = 10;
  RecipeResult result;
  Status s = untangle(&fixed_run, opt, &result);
  ASSERT_FALSE(s.ok());
  const long long left = compute_quality(fixed_run).inverted_cells;
  EXPECT_LE(left, before);
  const std::string count = ": " + std::to_string(left) + (left == 1 ? " cell" : " cells");
  EXPECT_NE(s.message().find(count + " still inverted"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find(std::to_string(left) + " of them have nodes on the fixed boundary: "
                                                    "try --boundary=slide"),
            std::string::npos)
      << s.message();
  const std::string failure = s.message();
  opt.slide = true;
  s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(compute_quality(mesh).inverted_cells, 0);
  EXPECT_EQ(result.certified, mesh.num_elements());
  std::printf("folded boundary edge: %lld inverted; fixed: %lld left (%s); slide: 0\n", before,
              left, failure.c_str());
}

}  // namespace
}  // namespace tmop
