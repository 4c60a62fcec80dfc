// .pvtu (io/pvtu.cc): pieces of contiguous cell blocks plus an index that VTK's own parallel
// reader opens (pvtu_check.py: the same cells, nodes and data as the .vtu, in order).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

// Every type VTK holds, with a point array of 3 components and a cell array.
Mesh data_mesh() {
  Mesh m = test::make_mesh(test::vtk_types());
  DataArray p{"velocity", 3, {}}, c{"mean_ratio", 1, {}};
  for (int v = 0; v < m.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) p.values.push_back(0.25 * v + k);
  for (int i = 0; i < m.num_cells(); ++i) c.values.push_back(1.0 / (1 + i));
  m.point_data.push_back(p);
  m.cell_data.push_back(c);
  return m;
}

bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

TEST(Pvtu, VtkReadsThePiecesAsTheVtu) {
  if (!test::have_python_module("vtk")) GTEST_SKIP() << "python3-vtk9 not installed";
  const std::string dir = test::temp_dir();
  const Mesh mesh = data_mesh();
  ASSERT_TRUE(write_mesh(dir + "/a.vtu", mesh).ok());
  for (int pieces : {1, 3, 7}) {
    for (bool binary : {false, true}) {
      SCOPED_TRACE(std::to_string(pieces) + (binary ? " binary" : " ascii"));
      WriteOptions o;
      o.pieces = pieces;
      o.binary = binary;
      const std::string pvtu = dir + "/p" + std::to_string(pieces) + (binary ? "b" : "a") + ".pvtu";
      const Status s = write_mesh(pvtu, mesh, o);
      ASSERT_TRUE(s.ok()) << s.message();
      const std::string stem = pvtu.substr(0, pvtu.size() - 5);
      EXPECT_TRUE(exists(stem + "_0.vtu"));
      EXPECT_TRUE(exists(stem + "_" + std::to_string(pieces - 1) + ".vtu"));
      EXPECT_FALSE(exists(stem + "_" + std::to_string(pieces) + ".vtu"));
      std::string out;
      const std::string cmd = std::string("/usr/bin/python3 ") + TMOP_SOURCE_DIR +
                              "/tests/io/pvtu_check.py '" + dir + "/a.vtu' '" + pvtu + "' " +
                              std::to_string(pieces);
      ASSERT_EQ(test::run(cmd, &out), 0) << out;
      EXPECT_NE(out.find("pvtu ok " + std::to_string(mesh.num_cells())), std::string::npos) << out;
    }
  }
}

TEST(Pvtu, EachPieceIsAVtuTmopReads) {
  const std::string dir = test::temp_dir();
  const Mesh mesh = data_mesh();
  WriteOptions o;
  o.pieces = 2;
  ASSERT_TRUE(write_mesh(dir + "/m.pvtu", mesh, o).ok());
  Mesh a, b;
  ASSERT_TRUE(read_mesh(dir + "/m_0.vtu", &a).ok());
  ASSERT_TRUE(read_mesh(dir + "/m_1.vtu", &b).ok());
  EXPECT_EQ(a.num_cells() + b.num_cells(), mesh.num_cells());
  EXPECT_EQ(a.num_cells(), mesh.num_cells() / 2);
  ASSERT_EQ(a.cell_data.size(), 1u);
  EXPECT_EQ(a.cell_data[0].values[0], 1.0);
}

TEST(Pvtu, RefusalsAreOneLine) {
  const std::string dir = test::temp_dir();
  WriteOptions o;
  o.pieces = 0;
  Status s = write_mesh(dir + "/z.pvtu", data_mesh(), o);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write 0 pieces"), std::string::npos) << s.message();
  s = write_mesh(dir + "/q.pvtu", test::make_mesh({CellType::kPyramid14}));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write pyramid14 cells to .pvtu"), std::string::npos)
      << s.message();
  EXPECT_FALSE(exists(dir + "/q_0.vtu"));
  ASSERT_TRUE(write_mesh(dir + "/r.pvtu", data_mesh()).ok());
  Mesh back;
  s = read_mesh(dir + "/r.pvtu", &back);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("writes .pvtu but does not read it"), std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace tmop
