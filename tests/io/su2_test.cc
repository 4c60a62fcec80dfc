// SU2 (io/su2.cc): round trips in 2D and 3D with markers as named regions, meshio reads tmop's
// files and tmop reads meshio's, and broken or hostile files fail with one located line.
#include <gtest/gtest.h>

#include <fstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using test::Dump;

const char* kPy = "/usr/bin/python3";

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

std::string read_error(const std::string& path) {
  Mesh m;
  const Status s = read_mesh(path, &m);
  return s.ok() ? "ok" : s.message();
}

// SU2's linear types; element cells untagged (SU2 has no volume tags), boundary cells tagged by
// marker: regions 3 (unnamed: the marker is "3") and 4 (named).
Mesh su2_mesh(int dim, bool named) {
  Mesh m = dim == 2
               ? test::make_mesh(
                     {CellType::kTri3, CellType::kQuad4, CellType::kLine2, CellType::kLine2}, 2)
               : test::make_mesh({CellType::kTet4, CellType::kHex8, CellType::kWedge6,
                                  CellType::kPyramid5, CellType::kTri3, CellType::kQuad4});
  int b = 0;
  for (int c = 0; c < m.num_cells(); ++c) {
    m.cell_entity[c] = 0;
    m.cell_region[c] = cell_dim(m.cell_types[c]) == dim ? 0 : 3 + (b++ % 2);
  }
  if (named) m.set_physical_name(dim - 1, 4, "far_field");
  return m;
}

TEST(Su2, RoundTripsTwoAndThreeDimensionalMeshesWithMarkerNames) {
  for (int dim : {2, 3}) {
    const Mesh mesh = su2_mesh(dim, true);
    EXPECT_EQ(test::round_trip(mesh, {"a.su2"}), "") << dim;
    const std::string dir = test::temp_dir();
    ASSERT_TRUE(write_mesh(dir + "/a.su2", mesh).ok());
    Mesh back;
    ASSERT_TRUE(read_mesh(dir + "/a.su2", &back).ok());
    ASSERT_EQ(back.physical_names.size(), 1u);
    EXPECT_EQ(back.physical_names[0].dim, dim - 1);
    EXPECT_EQ(back.physical_names[0].tag, 4);
    EXPECT_EQ(back.physical_names[0].name, "far_field");
  }
}

TEST(Su2, NamedMarkersGetTagsAboveNumberedOnes) {
  const std::string dir = test::temp_dir();
  write_text(dir + "/m.su2",
             "% comment\nNDIME= 2\nNELEM= 1\n5 0 1 2 0\nNPOIN= 3 3\n0 0 0\n1 0 1\n0 1 2\n"
             "NMARK= 3\nMARKER_TAG= wall\nMARKER_ELEMS= 1\n3 0 1\nMARKER_TAG= 7\n"
             "MARKER_ELEMS= 1\n3 1 2\nMARKER_TAG= inlet\nMARKER_ELEMS= 1\n3 2 0\n");
  Mesh m;
  const Status s = read_mesh(dir + "/m.su2", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.space_dim, 2);
  ASSERT_EQ(m.num_cells(), 4);
  EXPECT_EQ(m.cell_region, (std::vector<std::int32_t>{0, 8, 7, 9}));
  ASSERT_NE(m.physical_name(1, 8), nullptr);
  EXPECT_EQ(*m.physical_name(1, 8), "wall");
  EXPECT_EQ(*m.physical_name(1, 9), "inlet");
  EXPECT_EQ(m.physical_name(1, 7), nullptr);
}

TEST(Su2, RefusesWhatItCannotHold) {
  const std::string dir = test::temp_dir();
  Status s = write_mesh(dir + "/q.su2", test::make_mesh({CellType::kTet10}));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write tet10 cells to SU2"), std::string::npos) << s.message();
  s = write_mesh(dir + "/s.su2", test::make_mesh({CellType::kTri3}));  // a surface in 3D
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("SU2: it holds planar 2D meshes and 3D volume meshes"),
            std::string::npos)
      << s.message();
  Mesh m = su2_mesh(3, false);
  m.set_physical_name(2, 4, "far field");
  s = check_writable(dir + "/n.su2", m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write marker name 'far field' to SU2"), std::string::npos)
      << s.message();
}

TEST(Su2, MeshioReadsTmopFiles) {
  if (!test::have_python_module("meshio")) GTEST_SKIP() << "python3-meshio not installed";
  const std::string dir = test::temp_dir();
  std::string cmd = std::string(kPy) + " " + test::python_helper() + " meshio";
  for (int dim : {2, 3}) {
    const std::string path = dir + "/a" + std::to_string(dim) + ".su2";
    ASSERT_TRUE(write_mesh(path, su2_mesh(dim, false)).ok());
    cmd += " '" + path + "'";
  }
  std::string out;
  ASSERT_EQ(test::run(cmd, &out), 0) << cmd << "\n" << out;
  for (int dim : {2, 3}) {
    const std::string path = dir + "/a" + std::to_string(dim) + ".su2";
    Dump d;
    std::string err;
    ASSERT_TRUE(test::parse_dump_file(path + ".meshio.dump", &d, &err)) << err;
    EXPECT_EQ(test::diff_dumps(test::dump_of(su2_mesh(dim, false)), d), "") << path;
  }
}

TEST(Su2, TmopReadsMeshioFiles) {
  if (!test::have_python_module("meshio")) GTEST_SKIP() << "python3-meshio not installed";
  const std::string dir = test::temp_dir();
  std::string out;
  ASSERT_EQ(
      test::run(std::string(kPy) + " " + test::python_helper() + " meshio-write-su2 '" + dir + "'",
                &out),
      0)
      << out;
  for (const char* name : {"a2.su2", "a3.su2"}) {
    const std::string path = dir + "/" + name;
    Dump expected;
    std::string err;
    ASSERT_TRUE(test::parse_dump_file(path + ".expected", &expected, &err)) << err;
    Mesh m;
    const Status s = read_mesh(path, &m);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(test::diff_dumps(expected, test::dump_of(m)), "") << name;
  }
}

TEST(Su2, BrokenAndHostileFilesFailWithOneLocatedLine) {
  const std::string dir = test::temp_dir();
  const std::string pts = "NPOIN= 3\n0 0\n1 0\n0 1\n";
  const std::pair<std::string, std::string> cases[] = {
      {"NDIME= 4\n", "a.su2:1: NDIME 4 out of range 2..3"},
      {"NDIME= 2\nNELEM= 1000000000000\n", "a.su2:2: NELEM 1000000000000 out of range"},
      {"NDIME= 2\nNELEM= 2000000000\n5 0 1 2\n", "a.su2:3: declared element count 2000000000"},
      {"NDIME= 3\nNPOIN= 2000000000\n0 0 0\n", "a.su2:3: declared point count 2000000000"},
      {"NDIME= 2\nNELEM= 1\n7 0 1 2\n" + pts + "NMARK= 0\n",
       "a.su2:3: unsupported SU2 element type 7"},
      {"NDIME= 2\nNELEM= 1\n10 0 1 2 3\n" + pts, "a.su2:3: tet4 (dimension 3) in a section"},
      {"NDIME= 2\nNELEM= 1\n5 0 1 9\n" + pts, "a.su2:3: node index 9 out of range 0..2"},
      {"NDIME= 2\nNELEM= 1\n5 0 1\n" + pts, "a.su2:3: unexpected end of file, expected node"},
      {"NDIME= 2\nNELEM= 1\n5 0 1 2\n" + pts + "NMARK= 2\nMARKER_TAG= a\nMARKER_ELEMS= 1\n3 0 1\n" +
           "% room for a second marker\n",
       "a.su2:8: NMARK says 2 markers, the file has 1"},
      {"NDIME= 2\nNELEM= 1\n5 0 1 2\n" + pts + "MARKER_ELEMS= 1\n3 0 1\n",
       "a.su2:8: MARKER_ELEMS without a MARKER_TAG"},
      {"NDIME= 2\nNELEM= 1\n5 0 1 2\nNPOIN= 2\n0 0\n1 x\n", "a.su2:6: expected coordinate"},
      {"NDIME= 2\nNZONE= 2\n", "a.su2:2: multi-zone SU2 files are not supported"},
      {"NDIME= 2\nFOO= 1\n", "a.su2:2: unknown keyword 'FOO'"},
      {"NELEM= 1\n", "a.su2:1: NDIME must come before"},
  };
  for (const auto& [text, says] : cases) {
    write_text(dir + "/a.su2", text);
    const std::string m = read_error(dir + "/a.su2");
    EXPECT_NE(m.find(says), std::string::npos) << "got: " << m << "\nwant: " << says;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace tmop
