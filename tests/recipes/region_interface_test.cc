// Region interfaces (facets between cells of different cell_region / cell_entity tags) are
// boundaries of their regions: a fixed boundary keeps their vertices, a sliding one moves them
// on the interface only, so each region keeps its exact shape and volume.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/optimize/grid_meshes.h"
#include "tmop/mesh/topology.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

// Region 1 left of x = 0.5, region 2 right of it.
void split_regions(Mesh* m) {
  m->cell_region.assign(m->num_cells(), 0);
  for (int c = 0; c < m->num_cells(); ++c) {
    double x = 0;
    for (int i = 0; i < m->cell_size(c); ++i) x += m->vertex(m->cell(c)[i])[0] / m->cell_size(c);
    m->cell_region[c] = x < 0.5 ? 1 : 2;
  }
}

double region_measure(const Mesh& m, int region) {
  double sum = 0;
  for (int c = 0; c < m.num_cells(); ++c) {
    if (m.cell_region[c] != region) continue;
    const double* p[4];
    for (int i = 0; i < m.cell_size(c); ++i) p[i] = m.vertex(m.cell(c)[i]);
    if (m.cell_type(c) == CellType::kTri3) {
      sum += 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                    (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
    } else {
      double e[3][3];
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) e[r][s] = p[r + 1][s] - p[0][s];
      sum += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
              e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
              e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
             6;
    }
  }
  return sum;
}

class RegionInterface : public ::testing::TestWithParam<CellType> {};

TEST_P(RegionInterface, FixedKeepsItSlidingStaysOnIt) {
  const CellType type = GetParam();
  const int n = cell_dim(type) == 2 ? 8 : 4;
  Mesh input = testing_grid::grid(type, n);
  split_regions(&input);
  const std::vector<char> boundary = boundary_vertex_mask(input);
  std::vector<int> interface;
  for (int v = 0; v < input.num_vertices(); ++v) {
    const double* x = input.vertex(v);
    const bool on_outer = x[0] == 0 || x[0] == 1 || x[1] == 0 || x[1] == 1 ||
                          (input.space_dim == 3 && (x[2] == 0 || x[2] == 1));
    if (x[0] == 0.5 && !on_outer) interface.push_back(v);
  }
  ASSERT_FALSE(interface.empty());
  for (int v : interface) EXPECT_TRUE(boundary[v]) << "interface vertex " << v;
  std::mt19937 rng(5);
  testing_grid::perturb(&input, n, 0.3, &rng);  // moves interior vertices off the interface only
  const double v1 = region_measure(input, 1), v2 = region_measure(input, 2);

  for (bool slide : {false, true}) {
    Mesh mesh = input;
    ShapeOptions opt;
    opt.solver.threads = 1;
    opt.slide = slide;
    RecipeResult result;
    ASSERT_TRUE(improve_shape(&mesh, opt, &result).ok());
    int moved = 0;
    for (int v : interface) {
      if (slide) {
        EXPECT_NEAR(mesh.vertex(v)[0], 0.5, 1e-12);
        double d = 0;
        for (int a = 0; a < mesh.space_dim; ++a)
          d += std::abs(mesh.vertex(v)[a] - input.vertex(v)[a]);
        moved += d > 1e-9;
      } else {
        for (int a = 0; a < mesh.space_dim; ++a) EXPECT_EQ(mesh.vertex(v)[a], input.vertex(v)[a]);
      }
    }
    if (slide) {
      EXPECT_GT(moved, 0) << "interface vertices should slide";
    }
    EXPECT_NEAR(region_measure(mesh, 1), v1, 1e-12);
    EXPECT_NEAR(region_measure(mesh, 2), v2, 1e-12);
    EXPECT_LT(result.stages.back().final_objective, result.stages.front().initial_objective);
  }
}

INSTANTIATE_TEST_SUITE_P(Types, RegionInterface,
                         ::testing::Values(CellType::kTri3, CellType::kTet4),
                         [](const ::testing::TestParamInfo<CellType>& info) {
                           return std::string(cell_name(info.param));
                         });

}  // namespace
}  // namespace tmop
