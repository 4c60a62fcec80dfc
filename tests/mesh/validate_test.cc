// Tests of tmop/mesh/validate.h: each defect is found and named with its cell / vertex.
#include "tmop/mesh/validate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/mesh/test_meshes.h"

namespace tmop {
namespace {

using testing_meshes::KuhnTets;
using testing_meshes::TwoTets;

TEST(Validate, AcceptsGoodMeshes) {
  EXPECT_TRUE(validate_mesh(TwoTets()).ok());
  EXPECT_TRUE(validate_mesh(KuhnTets(3, 3, 3)).ok());
  EXPECT_TRUE(validate_mesh(testing_meshes::QuadGrid2x2()).ok());
  EXPECT_TRUE(validate_mesh(testing_meshes::MixedMesh()).ok());
}

TEST(Validate, NonFiniteCoordinate) {
  Mesh m = TwoTets();
  m.vertex(3)[1] = std::numeric_limits<double>::quiet_NaN();
  const Status s = validate_mesh(m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "vertex 3: coordinate 1 is nan");
  m.vertex(3)[1] = INFINITY;
  EXPECT_FALSE(validate_mesh(m).ok());
}

TEST(Validate, NodeOutOfRange) {
  Mesh m = TwoTets();
  m.cell(1)[2] = 5;
  const Status s = validate_mesh(m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "cell 1: node 5 out of range 0..4");
  m.cell(1)[2] = -1;
  EXPECT_EQ(validate_mesh(m).message(), "cell 1: node -1 out of range 0..4");
}

TEST(Validate, RepeatedNode) {
  Mesh m = TwoTets();
  m.cell(1)[3] = 1;
  EXPECT_EQ(validate_mesh(m).message(), "cell 1: node 1 appears more than once");
}

TEST(Validate, DuplicateElement) {
  Mesh m = KuhnTets(2, 2, 2);
  const std::int32_t again[4] = {m.cell(17)[2], m.cell(17)[0], m.cell(17)[3], m.cell(17)[1]};
  m.add_cell(CellType::kTet4, again);
  const Status s = validate_mesh(m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "cell 48: same nodes as cell 17");
}

TEST(Validate, DuplicateBoundaryCellsAreAllowed) {
  Mesh m = TwoTets();
  const std::int32_t tri[3] = {0, 1, 2};
  m.add_cell(CellType::kTri3, tri, 1);
  m.add_cell(CellType::kTri3, tri, 2);
  EXPECT_TRUE(validate_mesh(m).ok());
}

TEST(Validate, CellDimensionAboveSpaceDimension) {
  Mesh m;
  m.space_dim = 2;
  const double p[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t tet[4] = {0, 1, 2, 3};
  m.add_cell(CellType::kTet4, tet);
  EXPECT_EQ(validate_mesh(m).message(),
            "cell 0: tet4 (dimension 3) in a mesh of space dimension 2");
}

TEST(Validate, WrongNodeCountAndBrokenArrays) {
  Mesh m = TwoTets();
  m.cell_types[1] = CellType::kTet10;  // 4 nodes stored for a 10-node type
  EXPECT_EQ(validate_mesh(m).message(), "cell 1: tet10 has 4 nodes, expected 10");
  Mesh b = TwoTets();
  b.cell_offsets.pop_back();
  EXPECT_FALSE(validate_mesh(b).ok());
  Mesh c = TwoTets();
  c.space_dim = 4;
  EXPECT_FALSE(validate_mesh(c).ok());
}

}  // namespace
}  // namespace tmop
