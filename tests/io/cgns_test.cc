// CGNS (io/cgns.cc, through libcgns): round trip, h5py reads tmop's file, broken files.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using test::Dump;

const char* kPy = "/usr/bin/python3";

// Every type CGNS holds here, one section each (make_mesh gives each type its own region).
Mesh cgns_mesh() {
  Mesh m =
      test::make_mesh({CellType::kLine2, CellType::kLine3, CellType::kTri3, CellType::kQuad4,
                       CellType::kTet4, CellType::kHex8, CellType::kWedge6, CellType::kPyramid5,
                       CellType::kTri6, CellType::kQuad9, CellType::kTet10});
  for (int c = 0; c < m.num_cells(); ++c) m.cell_entity[c] = 0;
  return m;
}

#ifdef TMOP_TEST_WITH_CGNS

TEST(Cgns, RoundTripsBlocksAsRegions) {
  EXPECT_EQ(test::round_trip(cgns_mesh(), {"a.cgns", "b.CGNS"}), "");
}

// Quadratic cells in the format's own (PATRAN) node order, checked by reading the file without
// tmop or the format library: patran_order_check.py takes each mid-edge node of straight-sided
// cells to be the midpoint of the edge the format documents place there (io_test_util.h).
TEST(Cgns, QuadraticCellsFollowTheDocumentedNodeOrder) {
  if (!test::have_python_module("h5py")) GTEST_SKIP() << "python3 h5py not installed";
  EXPECT_EQ(test::check_patran_node_order("q.cgns", "cgns"), "");
}

TEST(Cgns, RegionSharedByTwoTypesKeepsIt) {
  const std::string dir = test::temp_dir();
  Mesh mesh = test::make_mesh({CellType::kTet4, CellType::kHex8});
  mesh.cell_region = {5, 5};
  ASSERT_TRUE(write_mesh(dir + "/m.cgns", mesh).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/m.cgns", &back).ok());
  ASSERT_EQ(back.num_cells(), 2);
  EXPECT_EQ(back.cell_region[0], 5);
  EXPECT_EQ(back.cell_region[1], 5);
}

// meshio 5 cannot be the client: it reads only a section named GridElements holding tetrahedra,
// and libcgns refuses the files its writer makes (no node labels). h5py reads tmop's file node by
// node instead (mesh_dump.py cgns-h5, written from the SIDS layout, no libcgns).
TEST(Cgns, H5pyReadsTmopFileNodeByNode) {
  if (!test::have_python_module("h5py")) GTEST_SKIP() << "python3-h5py not installed";
  const std::string dir = test::temp_dir();
  const Mesh mesh = cgns_mesh();
  ASSERT_TRUE(write_mesh(dir + "/a.cgns", mesh).ok());
  std::string out;
  const std::string cmd =
      std::string(kPy) + " " + test::python_helper() + " cgns-h5 '" + dir + "/a.cgns'";
  ASSERT_EQ(test::run(cmd, &out), 0) << out;
  Dump d;
  std::string err;
  ASSERT_TRUE(test::parse_dump_file(dir + "/a.cgns.cgns-h5.dump", &d, &err)) << err;
  EXPECT_EQ(test::diff_dumps(test::dump_of(mesh), d), "");
}

TEST(Cgns, BrokenFilesFailWithOneLine) {
  const std::string dir = test::temp_dir();
  ASSERT_TRUE(write_mesh(dir + "/ok.cgns", cgns_mesh()).ok());
  std::ifstream in(dir + "/ok.cgns", std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string good = ss.str();
  const std::string cases[][2] = {
      {"empty.cgns", ""},
      {"text.cgns", "not an HDF5 file\n"},
      {"cut.cgns", good.substr(0, good.size() / 2)},
      {"head.cgns", good.substr(0, 100)},
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

TEST(Cgns, WithoutTheLibraryTheFormatSaysSo) {
  const std::string dir = test::temp_dir();
  const Status s = write_mesh(dir + "/a.cgns", cgns_mesh());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("built without CGNS support"), std::string::npos) << s.message();
}

#endif

}  // namespace
}  // namespace tmop
