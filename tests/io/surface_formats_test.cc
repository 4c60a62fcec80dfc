// The surface formats .obj .off .ply .stl: writers refuse what a format cannot hold and leave no
// file, check_writable says so beforehand, tmop's STL is strictly standard, and the readers keep
// what is in the file (common variants, full-precision coordinates, non-manifold surfaces).
#include <dirent.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d))
      if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0)
        names.push_back(e->d_name);
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

void spit(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A height field of nx x ny vertices, float32-exact coordinates (OpenMesh and binary STL hold
// float32), as triangles or quads. space_dim 2 gives a planar mesh.
Mesh height_field(int nx, int ny, bool quads, int space_dim = 3) {
  Mesh m;
  m.space_dim = space_dim;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x[3] = {0.25 * i + 0.0625, 0.125 * j, 0.03125 * ((i * j) % 5)};
      m.add_vertex(x);
    }
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const std::int32_t a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      if (quads) {
        const std::int32_t q[4] = {a, b, c, d};
        m.add_cell(CellType::kQuad4, q);
      } else {
        const std::int32_t t1[3] = {a, b, c}, t2[3] = {a, c, d};
        m.add_cell(CellType::kTri3, t1);
        m.add_cell(CellType::kTri3, t2);
      }
    }
  return m;
}

// STL has no vertex list: a reader numbers the corners in order of first appearance. The same
// mesh numbered that way, so that a read-back STL compares equal.
Mesh numbered_by_first_use(const Mesh& in) {
  std::vector<std::int32_t> map(in.num_vertices(), -1);
  Mesh out;
  out.space_dim = in.space_dim;
  for (int c = 0; c < in.num_cells(); ++c)
    for (int k = 0; k < in.cell_size(c); ++k) {
      std::int32_t& m = map[in.cell(c)[k]];
      if (m < 0) m = out.add_vertex(in.vertex(in.cell(c)[k]));
    }
  std::int32_t nodes[kMaxCellNodes];
  for (int c = 0; c < in.num_cells(); ++c) {
    for (int k = 0; k < in.cell_size(c); ++k) nodes[k] = map[in.cell(c)[k]];
    out.add_cell(in.cell_types[c], nodes, in.cell_region[c], in.cell_entity[c]);
  }
  return out;
}

TEST(SurfaceWrite, StlRefusesQuadrilateralsAndWritesNothing) {
  const std::string dir = test::temp_dir();
  const Mesh quads = height_field(4, 3, true);
  for (bool binary : {false, true}) {
    WriteOptions o;
    o.binary = binary;
    const std::string out = dir + "/quads.stl";
    const Status s = write_mesh(out, quads, o);
    ASSERT_FALSE(s.ok()) << "binary " << binary;
    EXPECT_EQ(s.message().rfind(out + ": cannot write quad4 cells to .stl", 0), 0u) << s.message();
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
    EXPECT_TRUE(list_dir(dir).empty()) << "binary " << binary;
  }
}

// What each surface format cannot hold: volume cells everywhere, quadratic cells (their mid-edge
// nodes would be lost), quadrilaterals in STL, and a mesh without faces (the file could not be
// read back).
TEST(SurfaceWrite, RefusesWhatEachFormatCannotHold) {
  const std::string dir = test::temp_dir();
  struct Case {
    const char* what;
    Mesh mesh;
    const char* accepted_by;  // extensions that hold it
  };
  Mesh lines;
  lines.space_dim = 3;
  for (int v = 0; v < 3; ++v) {
    const double x[3] = {1.0 * v, 0, 0};
    lines.add_vertex(x);
  }
  const std::int32_t l0[2] = {0, 1}, l1[2] = {1, 2};
  lines.add_cell(CellType::kLine2, l0);
  lines.add_cell(CellType::kLine2, l1);
  Mesh tris_with_lines = height_field(3, 3, false);
  tris_with_lines.add_cell(CellType::kLine2, l0, 7);
  const Case cases[] = {
      {"tet4", test::make_mesh({CellType::kTet4}), ""},
      {"hex8 + quad4", test::make_mesh({CellType::kHex8, CellType::kQuad4}), ""},
      {"tri6", test::make_mesh({CellType::kTri6}), ""},
      {"quad9", test::make_mesh({CellType::kQuad9}), ""},
      {"lines only", lines, ""},
      {"no cells", test::make_mesh({}), ""},
      {"quads", height_field(3, 3, true), "obj off ply"},
      {"triangles + boundary line", tris_with_lines, "obj off ply stl"},
  };
  for (const Case& c : cases)
    for (const char* ext : {"obj", "off", "ply", "stl"})
      for (bool binary : {false, true}) {
        WriteOptions o;
        o.binary = binary;
        const std::string out = dir + "/x." + ext;
        const Status s = write_mesh(out, c.mesh, o);
        const bool held = std::string(c.accepted_by).find(ext) != std::string::npos;
        EXPECT_EQ(s.ok(), held) << c.what << " ." << ext << ": " << s.message();
        if (held) {
          Mesh back;
          const Status r = read_mesh(out, &back);
          EXPECT_TRUE(r.ok()) << r.message();
          std::remove(out.c_str());
        } else {
          EXPECT_EQ(s.message().rfind(out + ": cannot write", 0), 0u) << s.message();
        }
        EXPECT_TRUE(list_dir(dir).empty()) << c.what << " ." << ext;
      }
}

TEST(SurfaceWrite, PlanarMeshesReadBackTwoDimensional) {
  const std::string dir = test::temp_dir();
  for (const char* ext : {"obj", "off", "ply", "stl"})
    for (bool binary : {false, true}) {
      const bool stl = std::string(ext) == "stl";
      const Mesh in =
          stl ? numbered_by_first_use(height_field(4, 3, false, 2)) : height_field(4, 3, true, 2);
      WriteOptions o;
      o.binary = binary;
      const std::string path = dir + "/flat." + ext;
      ASSERT_TRUE(write_mesh(path, in, o).ok()) << ext;
      Mesh out;
      const Status s = read_mesh(path, &out);
      ASSERT_TRUE(s.ok()) << s.message();
      EXPECT_EQ(out.space_dim, 2) << ext;
      EXPECT_EQ(test::diff_meshes(in, out), "") << ext << " binary " << binary;
    }
}

TEST(CheckWritable, AgreesWithWriteMeshAndCreatesNothing) {
  const std::string dir = test::temp_dir();
  const std::vector<Mesh> meshes = {
      test::make_mesh(test::all_types()), test::make_mesh({CellType::kTet4, CellType::kTri3}),
      test::make_mesh({CellType::kQuad9}), height_field(3, 3, true), height_field(3, 3, false)};
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (const char* ext : {"msh", "vtk", "vtu", "mesh", "obj", "off", "ply", "stl", "xyz"}) {
      const std::string out = dir + "/x." + ext;
      const Status check = check_writable(out, meshes[m]);
      EXPECT_TRUE(list_dir(dir).empty()) << "check_writable created a file";
      const Status write = write_mesh(out, meshes[m]);
      EXPECT_EQ(check.ok(), write.ok()) << "mesh " << m << " ." << ext << ": " << write.message();
      if (!write.ok()) {
        EXPECT_EQ(check.message(), write.message());
      }
      std::remove(out.c_str());
    }
  const Status s = check_writable("/nonexistent/dir/out.msh", meshes[1]);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(),
            "/nonexistent/dir/out.msh: cannot write: directory /nonexistent/dir/ does not exist");
  WriteOptions o;
  o.msh_version = 30;
  EXPECT_FALSE(check_writable(dir + "/x.msh", meshes[1], o).ok());
}

// OpenMesh 9's ASCII STL writer put a blank line before every "endloop": meshio rejected the
// file and Gmsh 4.8 read 205 of 380 triangles. tmop's STL follows the grammar line by line.
TEST(StlWrite, AsciiIsStrictlyStandard) {
  const std::string dir = test::temp_dir();
  const Mesh in = height_field(20, 11, false);
  ASSERT_EQ(in.num_cells(), 380);
  ASSERT_TRUE(write_mesh(dir + "/s.stl", in).ok());
  std::istringstream text(slurp(dir + "/s.stl"));
  std::vector<std::string> lines;
  for (std::string l; std::getline(text, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 2u + 7u * 380u);
  EXPECT_EQ(lines.front(), "solid tmop");
  EXPECT_EQ(lines.back(), "endsolid tmop");
  const char* block[7] = {"facet normal ", "  outer loop", "    vertex ", "    vertex ",
                          "    vertex ",   "  endloop",    "endfacet"};
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    const std::string want = block[(i - 1) % 7];
    ASSERT_EQ(lines[i].compare(0, want.size(), want), 0) << "line " << i + 1 << ": " << lines[i];
    if (want.back() == ' ') {
      std::istringstream nums(lines[i].substr(want.size()));
      double a, b, c;
      std::string rest;
      EXPECT_TRUE(nums >> a >> b >> c) << lines[i];
      EXPECT_FALSE(nums >> rest) << lines[i];
    } else {
      EXPECT_EQ(lines[i], want);
    }
  }
}

TEST(StlRead, AsciiKeepsDoublesAndMergesCorners) {
  const std::string dir = test::temp_dir();
  Mesh in = numbered_by_first_use(height_field(4, 3, false));
  in.coords[0] = 0.1;  // not a float: ASCII STL keeps it exactly
  ASSERT_TRUE(write_mesh(dir + "/a.stl", in).ok());
  Mesh out;
  ASSERT_TRUE(read_mesh(dir + "/a.stl", &out).ok());
  EXPECT_EQ(test::diff_meshes(in, out), "");
}

TEST(StlRead, BinaryWithASolidHeaderIsBinary) {
  const std::string dir = test::temp_dir();
  const Mesh in = numbered_by_first_use(height_field(3, 2, false));
  WriteOptions o;
  o.binary = true;
  ASSERT_TRUE(write_mesh(dir + "/b.stl", in, o).ok());
  std::string bytes = slurp(dir + "/b.stl");
  ASSERT_EQ(bytes.size(), 84u + 50u * 4u);
  EXPECT_NE(bytes.compare(0, 5, "solid"), 0);  // tmop's own header is unambiguous
  bytes.replace(0, 11, "solid thing");         // as some writers do
  spit(dir + "/c.stl", bytes);
  Mesh out;
  const Status s = read_mesh(dir + "/c.stl", &out);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(test::diff_meshes(in, out), "");
}

// OpenMesh read every coordinate through float32; tmop keeps the file's digits.
TEST(SurfaceRead, AsciiCoordinatesAreReadAsDoubles) {
  const std::string dir = test::temp_dir();
  const std::string body[] = {"v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                              "OFF\n3 1 0\n0.1 0.2 0.3\n1 0 0\n0 1 0\n3 0 1 2\n",
                              "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                              "property double y\nproperty double z\nelement face 1\n"
                              "property list uchar int vertex_indices\nend_header\n"
                              "0.1 0.2 0.3\n1 0 0\n0 1 0\n3 0 1 2\n"};
  const char* ext[] = {"obj", "off", "ply"};
  for (int i = 0; i < 3; ++i) {
    const std::string path = dir + "/d." + ext[i];
    spit(path, body[i]);
    Mesh m;
    const Status s = read_mesh(path, &m);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(m.vertex(0)[0], 0.1) << ext[i];
    EXPECT_EQ(m.vertex(0)[2], 0.3) << ext[i];
  }
}

// Three triangles on one edge: OpenMesh's reader added copies of vertices to keep its mesh
// manifold; tmop keeps the file's connectivity.
TEST(SurfaceRead, NonManifoldSurfaceReadsAsInTheFile) {
  const std::string dir = test::temp_dir();
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0\nv 0.5 0 1\n"
      "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
  spit(dir + "/fin.obj", obj);
  Mesh m;
  const Status s = read_mesh(dir + "/fin.obj", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.num_vertices(), 5);
  ASSERT_EQ(m.num_cells(), 3);
  EXPECT_EQ(std::vector<std::int32_t>(m.cell(2), m.cell(2) + 3),
            (std::vector<std::int32_t>{0, 1, 4}));
}

// The validation must not be stricter than the formats: the common variants are read.
TEST(SurfaceRead, CommonVariantsAreAccepted) {
  const std::string dir = test::temp_dir();
  struct Case {
    const char* name;
    std::string text;
    int cells;
  };
  const Case cases[] = {
      {"v.obj",
       "# comment\nmtllib m.mtl\no thing\nv 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n"
       "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\ng group\nusemtl red\ns off\n"
       "f 1/1/1 2/2/1 3/3/1\nf -4//1 -2//1 -1//1\nl 1 2\n\nf 1 2 3 4\n",
       3},
      {"c.off",
       "COFF\n# comment\n4 2 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n"
       "1 1 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n3 0 2 3 1 0 0\n",
       2},
      {"same_line.off", "OFF 4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 3 2\n", 1},
      // A face colour index of -1: OpenMesh's OFF reader allocated 16 GB on this.
      {"colour_index.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 -1\n", 1},
      {"meshio.off",
       "OFF\n# Created by meshio\n\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n", 2},
      {"n.ply",
       "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 4\nproperty float x\n"
       "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
       "property float nz\nelement face 2\nproperty list uchar int vertex_indices\n"
       "property uchar red\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
       "end_header\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2 9\n"
       "4 0 1 2 3 9\n0 1\n",
       2},
  };
  for (const Case& c : cases) {
    spit(dir + "/" + c.name, c.text);
    Mesh m;
    const Status s = read_mesh(dir + "/" + c.name, &m);
    ASSERT_TRUE(s.ok()) << c.name << ": " << s.message();
    EXPECT_EQ(m.num_cells(), c.cells) << c.name;
    EXPECT_EQ(m.num_vertices(), 4) << c.name;
  }
  // Binary big-endian PLY.
  auto be32 = [](std::uint32_t v) {
    std::string s(4, '\0');
    for (int i = 0; i < 4; ++i) s[i] = static_cast<char>(v >> (24 - 8 * i));
    return s;
  };
  auto bef = [&](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return be32(u);
  };
  std::string ply =
      "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) ply += bef(f);
  ply += std::string(1, '\3') + be32(0) + be32(1) + be32(2);
  spit(dir + "/be.ply", ply);
  Mesh m;
  const Status s = read_mesh(dir + "/be.ply", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.num_cells(), 1);
  EXPECT_EQ(m.vertex(1)[0], 1.0);
}

}  // namespace
}  // namespace tmop
