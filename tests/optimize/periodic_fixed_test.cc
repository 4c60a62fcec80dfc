// Periodic vertices (Mesh::periodic, Gmsh's $Periodic) are fixed by every stage
// (stage_fixed_vertices): both sides of a link keep their coordinates bit for bit while the rest
// of the mesh moves.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "grid_meshes.h"
#include "tmop/optimize/stage.h"
#include "tmop/optimize/stage_spec.h"

namespace tmop {
namespace {

TEST(PeriodicVertices, AreFixedAndDoNotMove) {
  const int n = 6;
  const Mesh original = testing_grid::grid(CellType::kTri3, n);
  Mesh mesh = original;
  std::mt19937 rng(3);
  testing_grid::perturb(&mesh, n, 0.3, &rng);
  // Two interior vertex pairs linked (a stand-in for a periodic seam inside a sliding boundary).
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  PeriodicLink link;
  link.dim = 1;
  link.tag = 2;
  link.master_tag = 4;
  link.nodes = {{id(4, 2), id(2, 2)}, {id(4, 3), id(2, 3)}};
  mesh.periodic.push_back(link);
  const Mesh input = mesh;

  StageSpec spec;
  TermSpec term;
  term.metric = std::shared_ptr<const Metric>(make_metric("size_shape_orientation", 2).release());
  term.target.type = TargetType::kReference;
  term.target.reference = &original;
  spec.terms.push_back(term);
  spec.solver.threads = 1;
  std::vector<char> fixed;
  ASSERT_TRUE(stage_fixed_vertices(mesh, spec, &fixed).ok());
  for (const auto& p : link.nodes) {
    EXPECT_TRUE(fixed[p.first]);
    EXPECT_TRUE(fixed[p.second]);
  }
  EXPECT_FALSE(fixed[id(3, 3)]);

  StageResult result;
  ASSERT_TRUE(optimize_stage(&mesh, spec, &result).ok());
  for (const auto& p : link.nodes)
    for (int v : {p.first, p.second})
      EXPECT_EQ(std::memcmp(mesh.vertex(v), input.vertex(v), 2 * sizeof(double)), 0) << v;
  // The free interior moved towards the grid.
  double moved = 0;
  for (int k = 0; k < 2; ++k)
    moved += std::abs(mesh.vertex(id(3, 3))[k] - input.vertex(id(3, 3))[k]);
  EXPECT_GT(moved, 1e-3);
}

}  // namespace
}  // namespace tmop
