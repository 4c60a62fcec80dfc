// Quadratic tets: a tet10 grid whose interior nodes (corner and mid-edge) were moved randomly so
// that elements fold, untangled and certified valid everywhere by the Bernstein bound.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <random>

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

}  // namespace
}  // namespace tmop
