// Whatever tmop writes, tmop reads (issue 19): meshes a format cannot hold readably are refused
// by check_writable (and write_mesh) before anything is written, the others round-trip.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

Mesh two_triangles(double eps) {
  Mesh m;
  m.space_dim = 3;
  const double x[5][3] = {{1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1 + eps, 1, 1}, {2, 2, 1}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t a[3] = {0, 1, 2}, b[3] = {3, 4, 2};
  m.add_cell(CellType::kTri3, a);
  m.add_cell(CellType::kTri3, b);
  m.cell_region.assign(2, 0);
  m.cell_entity.assign(2, 0);
  return m;
}

TEST(WriteReadback, VtkArraysWithoutANameAreRefusedOthersRoundTrip) {
  const std::string dir = test::temp_dir();
  Mesh m = test::make_mesh({CellType::kTri3, CellType::kTet4});
  DataArray a;
  a.values.assign(m.num_vertices(), 1.5);
  m.point_data.push_back(a);  // name ""
  for (bool binary : {false, true}) {
    WriteOptions o;
    o.binary = binary;
    const std::string out = dir + "/a.vtk";
    Status s = check_writable(out, m, o);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.message(), out +
                               ": cannot write an unnamed point-data array to .vtk (legacy VTK "
                               "arrays need a name; .vtu takes it)");
    s = write_mesh(out, m, o);
    EXPECT_FALSE(s.ok());
    EXPECT_FALSE(exists(out));
  }
  // .vtu keeps the empty name.
  ASSERT_TRUE(write_mesh(dir + "/a.vtu", m).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/a.vtu", &back).ok());
  ASSERT_EQ(back.point_data.size(), 1u);
  EXPECT_EQ(back.point_data[0].name, "");
  // Names with spaces, tabs, newlines, quotes and '%' are encoded as VTK does (%XX).
  m.point_data[0].name = "a b\tc\nd\"e%20f";
  for (bool binary : {false, true}) {
    WriteOptions o;
    o.binary = binary;
    ASSERT_TRUE(write_mesh(dir + "/b.vtk", m, o).ok());
    ASSERT_TRUE(read_mesh(dir + "/b.vtk", &back).ok());
    ASSERT_EQ(back.point_data.size(), 1u);
    EXPECT_EQ(back.point_data[0].name, m.point_data[0].name);
  }
}

TEST(WriteReadback, StlTrianglesWithTwoCornersAtOnePointAreRefused) {
  const std::string dir = test::temp_dir();
  // Vertex 3 is 1e-9 from vertex 0: distinct in doubles, one point in float32.
  Mesh m = two_triangles(1e-9);
  m.cell_nodes[3 + 1] = 0;  // triangle 1 = (3, 0, 2): corners 3 and 0 collapse in float32
  WriteOptions bin;
  bin.binary = true;
  Status s = check_writable(dir + "/b.stl", m, bin);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), dir +
                             "/b.stl: cannot write triangle 1 to binary .stl: its vertices 3 "
                             "and 0 are one point in float32 (STL keeps corners by "
                             "coordinates: the file would not read back)");
  EXPECT_FALSE(write_mesh(dir + "/b.stl", m, bin).ok());
  EXPECT_FALSE(exists(dir + "/b.stl"));
  // ASCII STL holds the doubles exactly: written and read back.
  ASSERT_TRUE(write_mesh(dir + "/a.stl", m).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/a.stl", &back).ok());
  EXPECT_EQ(back.num_cells(), 2);
  // Two distinct vertices at exactly one point in one triangle: refused in ASCII too.
  Mesh same = two_triangles(0);
  same.cell_nodes[3 + 1] = 0;
  s = check_writable(dir + "/s.stl", same);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("its vertices 3 and 0 are one point"), std::string::npos);
}

// Equal vertices in different triangles: STL has no other way to say "shared", so they are
// written and read back merged, every triangle intact.
TEST(WriteReadback, StlCoincidentVerticesInDifferentTrianglesReadBackMerged) {
  const std::string dir = test::temp_dir();
  const Mesh m = two_triangles(0);  // vertex 3 = vertex 0, in different triangles
  for (bool binary : {false, true}) {
    WriteOptions o;
    o.binary = binary;
    ASSERT_TRUE(write_mesh(dir + "/m.stl", m, o).ok());
    Mesh back;
    ASSERT_TRUE(read_mesh(dir + "/m.stl", &back).ok());
    EXPECT_EQ(back.num_cells(), 2);
    EXPECT_EQ(back.num_vertices(), 4);
  }
}

// Fuzz finding (tests/fuzz/regressions/stl/flat_z_1e-38.stl): two STL corners differing only by
// a z of 1e-38 made the mesh "planar up to round-off", the flattened mesh held two vertices at
// one point, and its STL read back with one vertex fewer. Such a mesh now stays 3D.
TEST(WriteReadback, FlatteningNeverPutsTwoVerticesOnOnePoint) {
  const std::string dir = test::temp_dir();
  Mesh m;
  m.space_dim = 3;
  const double x[6][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 1e-38}, {2, 0, 0}, {2, 1, 0}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t a[3] = {0, 1, 2}, b[3] = {3, 4, 5};
  m.add_cell(CellType::kTri3, a);
  m.add_cell(CellType::kTri3, b);
  m.cell_region.assign(2, 0);
  m.cell_entity.assign(2, 0);
  ASSERT_TRUE(write_mesh(dir + "/z.stl", m).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/z.stl", &back).ok());
  EXPECT_EQ(back.space_dim, 3);
  EXPECT_EQ(back.num_vertices(), 6);
  ASSERT_TRUE(write_mesh(dir + "/z2.stl", back).ok());
  Mesh again;
  ASSERT_TRUE(read_mesh(dir + "/z2.stl", &again).ok());
  EXPECT_EQ(again.num_vertices(), 6);
}

}  // namespace
}  // namespace tmop
