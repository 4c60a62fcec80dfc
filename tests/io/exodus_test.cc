// Exodus II (io/exodus.cc, through libexodusii): round trip, meshio both ways, broken files.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using test::Dump;

const char* kPy = "/usr/bin/python3";

// Every type Exodus holds here, one block each (make_mesh gives each type its own region).
Mesh exodus_mesh() {
  Mesh m =
      test::make_mesh({CellType::kLine2, CellType::kLine3, CellType::kTri3, CellType::kQuad4,
                       CellType::kTet4, CellType::kHex8, CellType::kWedge6, CellType::kPyramid5,
                       CellType::kTri6, CellType::kQuad9, CellType::kTet10});
  for (int c = 0; c < m.num_cells(); ++c) m.cell_entity[c] = 0;
  return m;
}

#ifdef TMOP_TEST_WITH_EXODUS

TEST(Exodus, RoundTripsBlocksAsRegions) {
  EXPECT_EQ(test::round_trip(exodus_mesh(), {"a.exo", "b.e"}), "");
}

// Quadratic cells in the format's own (PATRAN) node order, checked by reading the file without
// tmop or the format library: patran_order_check.py takes each mid-edge node of straight-sided
// cells to be the midpoint of the edge the format documents place there (io_test_util.h).
TEST(Exodus, QuadraticCellsFollowTheDocumentedNodeOrder) {
  if (!test::have_python_module("netCDF4")) GTEST_SKIP() << "python3 netCDF4 not installed";
  EXPECT_EQ(test::check_patran_node_order("q.exo", "exodus"), "");
}

TEST(Exodus, RegionSharedByTwoTypesGetsAFreshBlockId) {
  const std::string dir = test::temp_dir();
  Mesh mesh = test::make_mesh({CellType::kTet4, CellType::kHex8});
  mesh.cell_region = {5, 5};
  ASSERT_TRUE(write_mesh(dir + "/m.exo", mesh).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/m.exo", &back).ok());
  ASSERT_EQ(back.num_cells(), 2);
  EXPECT_EQ(back.cell_region[0], 5);
  EXPECT_EQ(back.cell_region[1], 6);
}

TEST(Exodus, RefusesVertexCells) {
  const std::string dir = test::temp_dir();
  const Status s =
      write_mesh(dir + "/q.exo", test::make_mesh({CellType::kTet4, CellType::kVertex}));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write vertex cells to Exodus II"), std::string::npos)
      << s.message();
}

TEST(Exodus, MeshioReadsTmopFile) {
  if (!test::have_python_module("meshio") || !test::have_python_module("netCDF4"))
    GTEST_SKIP() << "python3-meshio / python3-netcdf4 not installed";
  const std::string dir = test::temp_dir();
  const Mesh mesh = exodus_mesh();
  ASSERT_TRUE(write_mesh(dir + "/a.exo", mesh).ok());
  std::string out;
  const std::string cmd =
      std::string(kPy) + " " + test::python_helper() + " meshio '" + dir + "/a.exo'";
  ASSERT_EQ(test::run(cmd, &out), 0) << out;
  Dump d;
  std::string err;
  ASSERT_TRUE(test::parse_dump_file(dir + "/a.exo.meshio.dump", &d, &err)) << err;
  Dump want = test::dump_of(mesh);
  test::strip_regions(&want);  // meshio keeps no block ids
  EXPECT_EQ(test::diff_dumps(want, d), "");
}

TEST(Exodus, TmopReadsMeshioFile) {
  if (!test::have_python_module("meshio") || !test::have_python_module("netCDF4"))
    GTEST_SKIP() << "python3-meshio / python3-netcdf4 not installed";
  const std::string dir = test::temp_dir();
  std::string out;
  ASSERT_EQ(test::run(std::string(kPy) + " " + test::python_helper() + " meshio-write-exodus '" +
                          dir + "'",
                      &out),
            0)
      << out;
  Dump expected;
  std::string err;
  ASSERT_TRUE(test::parse_dump_file(dir + "/a.exo.expected", &expected, &err)) << err;
  Mesh m;
  const Status s = read_mesh(dir + "/a.exo", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  Dump got = test::dump_of(m);
  test::strip_regions(&got);
  EXPECT_EQ(test::diff_dumps(expected, got), "");
}

TEST(Exodus, BrokenFilesFailWithOneLine) {
  const std::string dir = test::temp_dir();
  ASSERT_TRUE(write_mesh(dir + "/ok.exo", exodus_mesh()).ok());
  std::ifstream in(dir + "/ok.exo", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string good = ss.str();
  const std::string cases[][2] = {
      {"empty.exo", ""},
      {"text.exo", "not a netCDF file\n"},
      {"cut.exo", good.substr(0, good.size() / 2)},
      {"head.exo", good.substr(0, 100)},
  };
  for (const auto& c : cases) {
    const std::string path = dir + "/" + c[0];
    std::ofstream(path, std::ios::binary) << c[1];
    Mesh m;
    const Status s = read_mesh(path, &m);
    ASSERT_FALSE(s.ok()) << c[0];
    EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
    EXPECT_EQ(s.message().rfind(path, 0), 0u) << s.message();
    EXPECT_EQ(m.num_cells(), 0);
  }
}

#else

TEST(Exodus, WithoutTheLibraryTheFormatSaysSo) {
  const std::string dir = test::temp_dir();
  const Status s = write_mesh(dir + "/a.exo", exodus_mesh());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("built without Exodus II support"), std::string::npos) << s.message();
}

#endif

}  // namespace
}  // namespace tmop
