#include "tmop/mesh/mesh.h"

#include <gtest/gtest.h>

namespace tmop {
namespace {

TEST(Mesh, AddCellsAndCountTypes) {
  Mesh m;
  m.space_dim = 2;
  const double p[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t tri[3] = {0, 1, 2};
  const std::int32_t line[2] = {0, 1};
  m.add_cell(CellType::kTri3, tri, 7);
  m.add_cell(CellType::kLine2, line, 3);
  EXPECT_EQ(m.num_vertices(), 4);
  EXPECT_EQ(m.num_cells(), 2);
  EXPECT_EQ(m.dim(), 2);
  EXPECT_TRUE(m.is_element(0));
  EXPECT_FALSE(m.is_element(1));
  EXPECT_EQ(m.count_by_type()[static_cast<int>(CellType::kTri3)], 1);
  m.remove_lower_dimensional_cells();
  EXPECT_EQ(m.num_cells(), 1);
  EXPECT_EQ(m.cell_region[0], 7);
  EXPECT_EQ(m.cell(0)[2], 2);
}

TEST(CellType, TableIsConsistent) {
  for (int i = 0; i < kNumCellTypes; ++i) {
    const CellInfo& c = cell_info(static_cast<CellType>(i));
    CellType t;
    ASSERT_TRUE(cell_type_from_name(c.name, &t));
    EXPECT_EQ(static_cast<int>(t), i);
    ASSERT_TRUE(cell_type_from_gmsh(c.gmsh_type, &t));
    EXPECT_EQ(static_cast<int>(t), i);
    EXPECT_LE(c.num_nodes, kMaxCellNodes);
    const CellInfo& lin = cell_info(c.linear);
    EXPECT_EQ(lin.num_nodes, c.num_corners);
    for (int e = 0; e < c.num_edges; ++e) {
      EXPECT_LT(c.edges[e][0], c.num_corners);
      EXPECT_LT(c.edges[e][1], c.num_corners);
    }
  }
}

}  // namespace
}  // namespace tmop
