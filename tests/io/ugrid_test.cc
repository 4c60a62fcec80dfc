// AFLR3 .ugrid (io/ugrid.cc): the hand-made fixture reads with valid cells, tmop round trips in
// every encoding, meshio reads tmop's files and tmop reads meshio's, and broken files fail with
// one line.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using test::Dump;

const char* kPy = "/usr/bin/python3";
const char* kEncodings[] = {"a.ugrid", "a.b8.ugrid", "a.lb8.ugrid", "a.r8.ugrid", "a.lr8.ugrid"};

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f << bytes;
}

// det [x1 - x0, x2 - x0, x3 - x0] of nodes a, b, c, d.
double corner_det(const Mesh& m, int a, int b, int c, int d) {
  const double* p = m.vertex(a);
  double e[3][3];
  const int o[3] = {b, c, d};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) e[i][k] = m.vertex(o[i])[k] - p[k];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

// The UGRID types in file order, tagged as UGRID can hold them: surface IDs on faces only.
Mesh ugrid_mesh() {
  Mesh m = test::make_mesh({CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kPyramid5,
                            CellType::kWedge6, CellType::kHex8});
  for (int c = 0; c < m.num_cells(); ++c) {
    if (cell_dim(m.cell_types[c]) == 3) m.cell_region[c] = 0;
    m.cell_entity[c] = 0;
  }
  return m;
}

TEST(Ugrid, HandMadeCellsReadValidInTmopOrder) {
  Mesh m;
  const Status s = read_mesh(std::string(TMOP_SOURCE_DIR) + "/tests/data/ugrid/cells.ugrid", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_EQ(m.num_cells(), 6);
  const CellType want[6] = {CellType::kTri3,     CellType::kQuad4,  CellType::kTet4,
                            CellType::kPyramid5, CellType::kWedge6, CellType::kHex8};
  for (int c = 0; c < 6; ++c) EXPECT_EQ(m.cell_types[c], want[c]) << c;
  EXPECT_EQ(m.cell_region[0], 3);
  EXPECT_EQ(m.cell_region[1], 7);
  // Gmsh order: the corner Jacobian at node 0 of each valid cell is positive.
  const std::int32_t* tet = m.cell(2);
  EXPECT_GT(corner_det(m, tet[0], tet[1], tet[2], tet[3]), 0);
  const std::int32_t* pyr = m.cell(3);
  EXPECT_GT(corner_det(m, pyr[0], pyr[1], pyr[3], pyr[4]), 0);
  EXPECT_DOUBLE_EQ(m.vertex(pyr[4])[2], 1.0);  // the apex is last
  const std::int32_t* wedge = m.cell(4);
  EXPECT_GT(corner_det(m, wedge[0], wedge[1], wedge[2], wedge[3]), 0);
  const std::int32_t* hex = m.cell(5);
  EXPECT_GT(corner_det(m, hex[0], hex[1], hex[3], hex[4]), 0);
}

TEST(Ugrid, RoundTripsInEveryEncoding) {
  const std::string dir = test::temp_dir();
  const Mesh mesh = ugrid_mesh();
  for (const char* name : kEncodings) {
    const std::string path = dir + "/" + name;
    ASSERT_TRUE(write_mesh(path, mesh).ok()) << name;
    Mesh back;
    const Status s = read_mesh(path, &back);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(test::diff_meshes(mesh, back), "") << name;
  }
  // The header's first count (60 nodes) in each byte order.
  EXPECT_EQ(slurp(dir + "/a.b8.ugrid").substr(0, 4), std::string("\0\0\0\x3c", 4));
  EXPECT_EQ(slurp(dir + "/a.lb8.ugrid").substr(0, 4), std::string("\x3c\0\0\0", 4));
  EXPECT_EQ(slurp(dir + "/a.r8.ugrid").substr(0, 8), std::string("\0\0\0\x1c\0\0\0\x3c", 8));
}

TEST(Ugrid, RefusesCellsItCannotHold) {
  const std::string dir = test::temp_dir();
  const Status s = write_mesh(dir + "/q.ugrid", test::make_mesh({CellType::kTet10}));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write tet10 cells to UGRID"), std::string::npos)
      << s.message();
  const Status v = write_mesh(dir + "/q.b4.ugrid", ugrid_mesh());
  ASSERT_FALSE(v.ok());
  EXPECT_NE(v.message().find("variant .b4.ugrid is not supported"), std::string::npos)
      << v.message();
}

TEST(Ugrid, MeshioReadsTmopFiles) {
  if (!test::have_python_module("meshio")) GTEST_SKIP() << "python3-meshio not installed";
  const std::string dir = test::temp_dir();
  const Mesh mesh = ugrid_mesh();
  std::string cmd = std::string(kPy) + " " + test::python_helper() + " meshio";
  for (const char* name : kEncodings) {
    ASSERT_TRUE(write_mesh(dir + "/" + name, mesh).ok()) << name;
    cmd += " '" + dir + "/" + name + "'";
  }
  std::string out;
  ASSERT_EQ(test::run(cmd, &out), 0) << cmd << "\n" << out;
  for (const char* name : kEncodings) {
    Dump d;
    std::string err;
    ASSERT_TRUE(test::parse_dump_file(dir + "/" + name + ".meshio.dump", &d, &err)) << err;
    // meshio 5 reads ASCII UGRID coordinates as float32.
    const double tol = std::string(name) == "a.ugrid" ? 1e-7 : 0.0;
    EXPECT_EQ(test::diff_dumps(test::dump_of(mesh), d, tol), "") << "meshio reading " << name;
  }
}

TEST(Ugrid, TmopReadsMeshioFiles) {
  if (!test::have_python_module("meshio")) GTEST_SKIP() << "python3-meshio not installed";
  const std::string dir = test::temp_dir();
  std::string out;
  ASSERT_EQ(test::run(std::string(kPy) + " " + test::python_helper() + " meshio-write-ugrid '" +
                          dir + "'",
                      &out),
            0)
      << out;
  for (const char* name : kEncodings) {
    const std::string path = dir + "/" + name;
    Dump expected;
    std::string err;
    ASSERT_TRUE(test::parse_dump_file(path + ".expected", &expected, &err)) << err;
    Mesh m;
    const Status s = read_mesh(path, &m);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(test::diff_dumps(expected, test::dump_of(m)), "") << "tmop reading " << name;
  }
}

// One line naming the file, never a crash or a huge allocation.
void expect_one_line_failure(const std::string& path, const std::string& bytes,
                             const std::string& says) {
  spit(path, bytes);
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_FALSE(s.ok()) << path;
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
  EXPECT_EQ(s.message().rfind(path, 0), 0u) << s.message();
  EXPECT_NE(s.message().find(says), std::string::npos) << s.message();
  EXPECT_EQ(m.num_cells(), 0);
  EXPECT_EQ(m.num_vertices(), 0);
}

TEST(Ugrid, BrokenFilesFailWithOneLine) {
  const std::string dir = test::temp_dir();
  const std::string good = slurp(std::string(TMOP_SOURCE_DIR) + "/tests/data/ugrid/cells.ugrid");
  ASSERT_FALSE(good.empty());
  expect_one_line_failure(dir + "/empty.ugrid", "", "empty file");
  expect_one_line_failure(dir + "/huge.ugrid", "2000000000 0 0 0 0 0 1\n0 0 0\n", "fit");
  expect_one_line_failure(dir + "/negative.ugrid", "-3 0 0 0 0 0 0\n", "number of nodes");
  expect_one_line_failure(dir + "/truncated.ugrid", good.substr(0, good.size() - 20), ":");
  expect_one_line_failure(dir + "/badnode.ugrid", "3 1 0 0 0 0 0\n0 0 0 1 0 0 0 1 0\n1 2 4\n1\n",
                          ":3: node index");
  expect_one_line_failure(dir + "/words.ugrid", "3 1 0 0 0 0 0\n0 0 zero 1 0 0 0 1 0\n1 2 3\n1\n",
                          ":2:");
  expect_one_line_failure(dir + "/x.b4.ugrid", good, "not supported");

  Mesh mesh = ugrid_mesh();
  ASSERT_TRUE(write_mesh(dir + "/ok.b8.ugrid", mesh).ok());
  const std::string bin = slurp(dir + "/ok.b8.ugrid");
  expect_one_line_failure(dir + "/cut.b8.ugrid", bin.substr(0, bin.size() - 3), "truncated");
  expect_one_line_failure(dir + "/short.b8.ugrid", bin.substr(0, 10), "byte");
  std::string hostile = bin;
  hostile[0] = '\x7f';  // ~2e9 nodes declared in a small file
  expect_one_line_failure(dir + "/hostile.b8.ugrid", hostile, "truncated");
  std::string bad_index = bin;
  // The first tria's first node index (after the header and 60 x 3 coordinates) -> 1000.
  bad_index.replace(28 + 60 * 24, 4, std::string("\0\0\x03\xe8", 4));
  expect_one_line_failure(dir + "/index.b8.ugrid", bad_index, "node index 1000 is out of range");
  ASSERT_TRUE(write_mesh(dir + "/ok.r8.ugrid", mesh).ok());
  std::string mark = slurp(dir + "/ok.r8.ugrid");
  mark[3] = '\x1d';
  expect_one_line_failure(dir + "/mark.r8.ugrid", mark, "record mark");
}

}  // namespace
}  // namespace tmop
