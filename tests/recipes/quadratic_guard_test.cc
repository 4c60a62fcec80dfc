// The step-back repair of the quadratic shape guard (recipes/quadratic_guard.h): a result whose
// cells break a guarantee is blended back towards its start over rings of neighbours until none
// does, and the moves away from the violators are kept.
#include "tmop/recipes/quadratic_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tmop/element/cell_type.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/guarantees.h"

namespace tmop {
namespace {

// An n x n x n block of straight tet10 (6 Kuhn tets per cube, mid nodes at the midpoints).
Mesh tet10_block(int n) {
  Mesh m;
  m.space_dim = 3;
  auto id = [&](int i, int j, int k) { return (k * (2 * n + 1) + j) * (2 * n + 1) + i; };
  for (int k = 0; k <= 2 * n; ++k)
    for (int j = 0; j <= 2 * n; ++j)
      for (int i = 0; i <= 2 * n; ++i) {
        const double x[3] = {0.5 * i, 0.5 * j, 0.5 * k};
        m.add_vertex(x);
      }
  const int cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int kuhn[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                          {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  const CellInfo& info = cell_info(CellType::kTet10);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& t : kuhn) {
          int g[4][3];
          for (int a = 0; a < 4; ++a)
            for (int b = 0; b < 3; ++b)
              g[a][b] = 2 * ((b == 0 ? i : b == 1 ? j : k) + cube[t[a]][b]);
          std::int32_t nodes[10];
          for (int a = 0; a < 4; ++a) nodes[a] = id(g[a][0], g[a][1], g[a][2]);
          for (int e = 0; e < 6; ++e) {
            const int* p = g[info.edges[e][0]];
            const int* q = g[info.edges[e][1]];
            nodes[4 + e] = id((p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2);
          }
          m.add_cell(CellType::kTet10, nodes);
        }
  return m;
}

// Mid nodes at their edges' midpoints (straight edges).
void place_mid_nodes(Mesh* m) {
  const CellInfo& info = cell_info(CellType::kTet10);
  for (int c = 0; c < m->num_cells(); ++c)
    for (int e = 0; e < 6; ++e) {
      const int a = m->cell(c)[info.edges[e][0]], b = m->cell(c)[info.edges[e][1]];
      for (int k = 0; k < 3; ++k)
        m->vertex(m->cell(c)[4 + e])[k] = 0.5 * (m->vertex(a)[k] + m->vertex(b)[k]);
    }
}

TEST(QuadraticGuard, StepBackHoldsTheViolatorsAndKeepsTheMovesAwayFromThem) {
  const Mesh grid = tet10_block(5);
  const std::vector<char> boundary = boundary_vertex_mask(grid);
  // The input: the interior corners jittered (a fixed pattern); the "solved" mesh: half way back
  // to the grid (every cell better), one corner also pushed far across its neighbours.
  Mesh input = grid;
  for (int v = 0; v < grid.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k)
      if (!boundary[v]) input.vertex(v)[k] += 0.08 * std::sin(1.7 * v + 2.3 * k);
  place_mid_nodes(&input);
  ShapeOptions options;
  options.solver.threads = 1;
  const QuadraticBaseline baseline = quadratic_baseline(input, 1);
  Mesh solved = input;
  std::vector<char> corner(input.num_vertices(), 0), unknown(input.num_vertices(), 0);
  for (int c = 0; c < input.num_cells(); ++c)
    for (int i = 0; i < 4; ++i) corner[input.cell(c)[i]] = 1;
  int pushed = -1;
  for (int v = 0; v < input.num_vertices(); ++v) {
    if (!corner[v] || boundary[v]) continue;
    unknown[v] = 1;
    for (int k = 0; k < 3; ++k)
      solved.vertex(v)[k] = 0.5 * (input.vertex(v)[k] + grid.vertex(v)[k]);
    if (pushed < 0 && std::abs(grid.vertex(v)[0] - 1) + std::abs(grid.vertex(v)[1] - 1) +
                              std::abs(grid.vertex(v)[2] - 1) <
                          1e-9)
      pushed = v;
  }
  ASSERT_GE(pushed, 0);
  solved.vertex(pushed)[0] += 0.8;  // beyond its neighbours: inverted cells
  place_mid_nodes(&solved);
  Mesh mesh = solved;
  std::vector<char> violates;
  std::string first;
  ASSERT_GT(quadratic_violators(mesh, baseline, options, &violates, &first), 0);
  auto apply = [&](const std::vector<double>& t) {
    for (int v = 0; v < mesh.num_vertices(); ++v)
      for (int k = 0; k < 3; ++k)
        mesh.vertex(v)[k] = input.vertex(v)[k] + t[v] * (solved.vertex(v)[k] - input.vertex(v)[k]);
    place_mid_nodes(&mesh);
  };
  std::vector<char> held;
  int passes = 0;
  ASSERT_TRUE(step_back_until_kept(&mesh, baseline, options, unknown, apply, 64, &violates, &passes,
                                   &first, &held))
      << first;
  EXPECT_LE(passes, 8);
  // Every guarantee holds, as tmop_optimize checks them.
  EXPECT_TRUE(
      check_guarantees(baseline.guarantees, guarantee_values(mesh, 1), GuaranteeOptions()).empty());
  EXPECT_TRUE(held[pushed]);
  EXPECT_DOUBLE_EQ(mesh.vertex(pushed)[0], input.vertex(pushed)[0]);
  // The held set stays near the pushed vertex; the other vertices keep (a share of) their moves.
  int kept = 0, held_count = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    held_count += held[v];
    if (unknown[v] && std::abs(mesh.vertex(v)[0] - input.vertex(v)[0]) > 1e-12) ++kept;
  }
  EXPECT_LT(held_count, 40);
  EXPECT_GT(kept, 10);
}

TEST(QuadraticGuard, StepBackEndsWhenOnlyTheStartKeepsTheGuarantees) {
  const Mesh input = tet10_block(2);
  ShapeOptions options;
  options.solver.threads = 1;
  const QuadraticBaseline baseline = quadratic_baseline(input, 1);
  // The one interior corner (1, 1, 1) pushed out: only its input position is valid.
  Mesh mesh = input;
  std::vector<char> unknown(input.num_vertices(), 0);
  int v0 = -1;
  for (int v = 0; v < input.num_vertices(); ++v)
    if (input.vertex(v)[0] == 1 && input.vertex(v)[1] == 1 && input.vertex(v)[2] == 1) v0 = v;
  ASSERT_GE(v0, 0);
  unknown[v0] = 1;
  const double x0 = input.vertex(v0)[0];
  auto apply = [&](const std::vector<double>& t) { mesh.vertex(v0)[0] = x0 + t[v0] * 0.9; };
  apply(std::vector<double>(input.num_vertices(), 1.0));
  std::vector<char> violates, held;
  std::string first;
  ASSERT_GT(quadratic_violators(mesh, baseline, options, &violates, &first), 0);
  int passes = 0;
  // The vertex goes back to its start in one pass (ring 0); nothing is left to step back.
  const bool kept = step_back_until_kept(&mesh, baseline, options, unknown, apply, 64, &violates,
                                         &passes, &first, &held);
  EXPECT_TRUE(kept);
  EXPECT_EQ(mesh.vertex(v0)[0], x0) << "the caller sees the start and keeps its input";
  EXPECT_LE(passes, 2);
}

}  // namespace
}  // namespace tmop
