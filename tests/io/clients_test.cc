// Real clients: files the gmsh program and meshio write are read by tmop, and files tmop writes
// are read by the Gmsh API and by meshio with identical points, cells, types and region tags.
// Each test skips only when the program / Python module is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using test::Dump;

const char* kPy = "/usr/bin/python3";

std::string geo(const std::string& name) {
  return std::string(TMOP_SOURCE_DIR) + "/tests/data/geo/" + name + ".geo";
}

// Signed measure of a cell from its corners (exact for the straight-sided cells Gmsh makes of
// boxes): tets, hexes and wedges split into tets, quads into triangles.
double tet_volume(const Mesh& m, int a, int b, int c, int d) {
  const double* p = m.vertex(a);
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = m.vertex(b)[k] - p[k];
    v[k] = m.vertex(c)[k] - p[k];
    w[k] = m.vertex(d)[k] - p[k];
  }
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6.0;
}
double tri_area(const Mesh& m, int a, int b, int c) {
  const double* p = m.vertex(a);
  const double* q = m.vertex(b);
  const double* r = m.vertex(c);
  return 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
}
double measure(const Mesh& m) {
  double sum = 0;
  for (int c = 0; c < m.num_cells(); ++c) {
    if (!m.is_element(c)) continue;
    const std::int32_t* n = m.cell(c);
    switch (cell_info(m.cell_types[c]).linear) {
      case CellType::kTet4:
        sum += tet_volume(m, n[0], n[1], n[2], n[3]);
        break;
      case CellType::kHex8: {
        const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                             {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
        for (auto& q : t) sum += tet_volume(m, n[q[0]], n[q[1]], n[q[2]], n[q[3]]);
        break;
      }
      case CellType::kWedge6:
        sum += tet_volume(m, n[0], n[1], n[2], n[3]) + tet_volume(m, n[1], n[2], n[3], n[4]) +
               tet_volume(m, n[2], n[3], n[4], n[5]);
        break;
      case CellType::kTri3:
        sum += tri_area(m, n[0], n[1], n[2]);
        break;
      case CellType::kQuad4:
        sum += tri_area(m, n[0], n[1], n[2]) + tri_area(m, n[0], n[2], n[3]);
        break;
      default:
        ADD_FAILURE() << "unexpected element " << cell_name(m.cell_types[c]);
    }
  }
  return sum;
}

// GTEST_SKIP returns from the function it is in, so this has to be a macro.
#define SKIP_UNLESS(have, what)                 \
  do {                                          \
    if (!(have)) {                              \
      GTEST_SKIP() << what << " not installed"; \
    }                                           \
  } while (0)

// Runs mesh_dump.py READER on the files and compares each dump with tmop's view of the mesh.
void compare_with_reader(const std::string& reader, const std::vector<std::string>& files,
                         const std::vector<Dump>& expected) {
  std::string cmd = std::string(kPy) + " " + test::python_helper() + " " + reader;
  for (const std::string& f : files) cmd += " '" + f + "'";
  std::string out;
  ASSERT_EQ(test::run(cmd, &out), 0) << cmd << "\n" << out;
  for (std::size_t i = 0; i < files.size(); ++i) {
    Dump d;
    std::string err;
    ASSERT_TRUE(test::parse_dump_file(files[i] + "." + reader + ".dump", &d, &err)) << err;
    EXPECT_EQ(test::diff_dumps(expected[i], d), "") << reader << " reading " << files[i];
  }
}

struct GmshCase {
  const char* geo;
  int order;
  int dim;          // space_dim tmop must find
  double measure;   // volume / area of the top-dimensional cells
  const char* top;  // element type expected
};

const GmshCase kGmshCases[] = {
    {"box", 2, 3, 2.0, "tet10"},
    {"square", 2, 2, 2.0, "tri6"},
    {"hexbox", 2, 3, 1.0, "hex27"},
    {"prism", 1, 3, 1.0, "wedge6"},
};

TEST(GmshWrites, TmopReadsMsh22And41AsciiAndBinary) {
  SKIP_UNLESS(test::have_program("gmsh"), "gmsh");
  const std::string dir = test::temp_dir();
  std::vector<std::string> files;
  std::vector<Dump> dumps;
  for (const GmshCase& g : kGmshCases) {
    for (const char* format : {"msh22", "msh41"}) {
      for (bool bin : {false, true}) {
        const std::string path = dir + "/" + g.geo + "_" + format + (bin ? "_bin" : "") + ".msh";
        std::string out;
        const std::string cmd = "gmsh -3 -order " + std::to_string(g.order) + " -format " + format +
                                (bin ? " -bin" : "") + " '" + geo(g.geo) + "' -o '" + path + "'";
        ASSERT_EQ(test::run(cmd, &out), 0) << out;
        Mesh m;
        const Status s = read_mesh(path, &m);
        ASSERT_TRUE(s.ok()) << s.message();
        EXPECT_EQ(m.space_dim, g.dim) << path;
        EXPECT_NEAR(measure(m), g.measure, 1e-9) << path;
        const std::vector<int> count = m.count_by_type();
        CellType top;
        ASSERT_TRUE(cell_type_from_name(g.top, &top));
        EXPECT_GT(count[static_cast<int>(top)], 0) << path;
        // Every element carries its physical tag.
        for (int c = 0; c < m.num_cells(); ++c) {
          if (m.is_element(c)) {
            ASSERT_NE(m.cell_region[c], 0) << path;
          }
        }
        files.push_back(path);
        dumps.push_back(test::dump_of(m));
      }
    }
  }
  // The Gmsh API reading the same files sees the same nodes, elements and physical tags.
  if (test::have_python_module("gmsh")) compare_with_reader("gmsh", files, dumps);
}

// Gmsh writes the same mesh as .msh, .vtk and .mesh: tmop must find identical cells in all three,
// which checks the VTK (tet10, hex27, wedge) and Medit (TetrahedraP2) node-order tables against
// Gmsh's own writers.
TEST(GmshWrites, VtkAndMeditNodeOrdersMatchMsh) {
  SKIP_UNLESS(test::have_program("gmsh"), "gmsh");
  const std::string dir = test::temp_dir();
  struct Job {
    const char* geo;
    int order;
    const char* ext;
  };
  // Gmsh's Medit writer (and reader) skip prisms and pyramids, so they cannot be checked here.
  const Job jobs[] = {{"box", 2, "vtk"},  {"hexbox", 2, "vtk"}, {"prism", 1, "vtk"},
                      {"box", 2, "mesh"}, {"box", 1, "mesh"},   {"hexbox", 1, "mesh"}};
  for (const Job& j : jobs) {
    std::string out;
    const std::string base = dir + "/" + j.geo + std::to_string(j.order);
    const std::string opts = "gmsh -3 -order " + std::to_string(j.order) + " '" + geo(j.geo) + "'";
    ASSERT_EQ(test::run(opts + " -format msh41 -o '" + base + ".msh'", &out), 0) << out;
    ASSERT_EQ(test::run(opts + " -format " + j.ext + " -o '" + base + "." + j.ext + "'", &out), 0)
        << out;
    Mesh a, b;
    Status s = read_mesh(base + ".msh", &a);
    ASSERT_TRUE(s.ok()) << s.message();
    s = read_mesh(base + "." + j.ext, &b);
    ASSERT_TRUE(s.ok()) << s.message();
    // Compare the elements (top dimension) only: the writers differ in which boundary cells
    // and tags they keep.
    auto elements = [](const Mesh& m) {
      Dump d = test::dump_of(m);
      Dump e;
      e.xyz = d.xyz;
      for (int c = 0; c < m.num_cells(); ++c)
        if (m.is_element(c)) {
          std::string line = d.cells[c];
          // Drop the region (second field): Gmsh's .vtk / .mesh writers put other tags there.
          const std::size_t s1 = line.find(' '), s2 = line.find(' ', s1 + 1);
          e.cells.push_back(line.substr(0, s1) + line.substr(s2));
        }
      return e;
    };
    const Dump da = elements(a), db = elements(b);
    EXPECT_GT(da.cells.size(), 0u);
    // Gmsh's .vtk / .mesh writers print fewer digits than its .msh writer.
    EXPECT_EQ(test::diff_dumps(da, db, 1e-13), "") << base << "." << j.ext;
    EXPECT_NEAR(measure(b), measure(a), 1e-12);
  }
}

TEST(TmopWrites, GmshReadsMsh) {
  SKIP_UNLESS(test::have_program("gmsh") && test::have_python_module("gmsh"), "python3-gmsh");
  const std::string dir = test::temp_dir();
  Mesh mesh = test::make_mesh(test::all_types());
  // Gmsh drops nodes no element uses: give every node a point element.
  for (std::int32_t v = 0; v < mesh.num_vertices(); ++v)
    mesh.add_cell(CellType::kVertex, &v, 10, 100);
  std::vector<std::string> files;
  std::vector<Dump> dumps;
  for (int version : {22, 41})
    for (bool bin : {false, true}) {
      const std::string path =
          dir + "/all" + std::to_string(version) + (bin ? "_bin" : "") + ".msh";
      WriteOptions o;
      o.binary = bin;
      o.msh_version = version;
      const Status s = write_mesh(path, mesh, o);
      ASSERT_TRUE(s.ok()) << s.message();
      files.push_back(path);
      dumps.push_back(test::dump_of(mesh));
    }
  compare_with_reader("gmsh", files, dumps);
}

TEST(TmopWrites, MeshioReadsEveryFormat) {
  SKIP_UNLESS(test::have_python_module("meshio"), "python3-meshio");
  const std::string dir = test::temp_dir();
  // meshio reads pyramid14 only from .msh; VTK has no 14-node pyramid.
  const Mesh msh_mesh = test::make_mesh(test::all_types());
  const Mesh mesh = test::make_mesh(test::vtk_types());
  const Mesh medit_mesh =
      test::make_mesh({CellType::kLine2, CellType::kTri3, CellType::kQuad4, CellType::kTet4,
                       CellType::kPyramid5, CellType::kWedge6, CellType::kHex8});
  struct Job {
    const char* name;
    bool bin;
    int version;
  };
  const Job jobs[] = {{"a22.msh", false, 22}, {"b22.msh", true, 22}, {"a41.msh", false, 41},
                      {"b41.msh", true, 41},  {"a.vtk", false, 0},   {"b.vtk", true, 0},
                      {"a.vtu", false, 0},    {"b.vtu", true, 0},    {"a.mesh", false, 0}};
  std::vector<std::string> files;
  std::vector<Dump> dumps;
  for (const Job& j : jobs) {
    const std::string path = dir + "/" + j.name;
    WriteOptions o;
    o.binary = j.bin;
    if (j.version) o.msh_version = j.version;
    const bool medit = std::string(j.name).find(".mesh") != std::string::npos;
    const bool msh = std::string(j.name).find(".msh") != std::string::npos;
    const Mesh& m = medit ? medit_mesh : (msh ? msh_mesh : mesh);
    const Status s = write_mesh(path, m, o);
    ASSERT_TRUE(s.ok()) << s.message();
    files.push_back(path);
    dumps.push_back(test::dump_of(m));
  }
  compare_with_reader("meshio", files, dumps);
}

#if defined(TMOP_TEST_WITH_EXODUS) && defined(TMOP_TEST_WITH_CGNS)
// VTK's own Exodus II and CGNS readers convert each cell to VTK's node order with tables of their
// own: every volume cell they return from tmop's .exo and .cgns must have the same points, in the
// same order, as in tmop's .vtu (vtk_readers_check.py). pyramid14 has no VTK type.
TEST(TmopWrites, VtkReadsExodusAndCgnsCellsInItsOwnNodeOrder) {
  SKIP_UNLESS(test::have_python_module("vtk"), "python3-vtk9");
  const std::vector<CellType> types = {CellType::kTet4,     CellType::kHex8,    CellType::kWedge6,
                                       CellType::kPyramid5, CellType::kTet10,   CellType::kHex20,
                                       CellType::kHex27,    CellType::kWedge15, CellType::kWedge18,
                                       CellType::kPyramid13};
  const Mesh mesh = test::straight_cells_mesh(types);
  const std::string dir = test::temp_dir();
  for (const char* name : {"a.vtu", "a.exo", "a.cgns"}) {
    const Status s = write_mesh(dir + "/" + name, mesh);
    ASSERT_TRUE(s.ok()) << s.message();
  }
  std::string out;
  const std::string cmd = std::string(kPy) + " " + TMOP_SOURCE_DIR +
                          "/tests/io/vtk_readers_check.py '" + dir + "/a.vtu' '" + dir +
                          "/a.exo' '" + dir + "/a.cgns'";
  ASSERT_EQ(test::run(cmd, &out), 0) << out;
  // VTK cell types: 10 tet4, 12 hex8, 13 wedge6, 14 pyramid5, 24 tet10, 25 hex20, 29 hex27,
  // 26 wedge15, 32 wedge18, 27 pyramid13.
  // VTK 9.1's CGNS reader has no PYRA_13 (the script says "skip cgns 27").
  for (const char* kind : {"exodus", "cgns"})
    for (int t : {10, 12, 13, 14, 24, 25, 29, 26, 32, 27}) {
      if (std::string(kind) == "cgns" && t == 27) continue;
      EXPECT_NE(out.find(std::string("agree ") + kind + " " + std::to_string(t) + " 1\n"),
                std::string::npos)
          << kind << " VTK type " << t << ":\n"
          << out;
    }
}
#endif

// The OpenMesh-backed surface formats, read back by meshio (an independent OBJ / OFF / PLY
// reader): same points in the same order, same faces.
TEST(TmopWrites, MeshioReadsSurfaceFormats) {
  SKIP_UNLESS(test::have_python_module("meshio"), "python3-meshio");
  const std::string dir = test::temp_dir();
  auto strip = [](bool quads) {
    Mesh mesh;
    mesh.space_dim = 3;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        // float32-exact: OpenMesh reads and writes coordinates as float (docs/formats.md).
        const double x[3] = {0.5 * i + 0.0625, 0.25 * j, 0.125 * (i * j % 3)};
        mesh.add_vertex(x);
      }
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const std::int32_t a = j * 4 + i;
        if (quads && (i + j) % 2 == 0) {
          const std::int32_t q[4] = {a, a + 1, a + 5, a + 4};
          mesh.add_cell(CellType::kQuad4, q);
        } else {
          const std::int32_t t1[3] = {a, a + 1, a + 5}, t2[3] = {a, a + 5, a + 4};
          mesh.add_cell(CellType::kTri3, t1);
          mesh.add_cell(CellType::kTri3, t2);
        }
      }
    return mesh;
  };
  std::vector<std::string> files;
  std::vector<Dump> dumps;
  // meshio's OFF reader takes triangles only.
  for (const char* name : {"s.obj", "s.off", "s.ply"}) {
    const Mesh mesh = strip(std::string(name) != "s.off");
    const std::string path = dir + "/" + name;
    const Status s = write_mesh(path, mesh);
    ASSERT_TRUE(s.ok()) << s.message();
    files.push_back(path);
    dumps.push_back(test::dump_of(mesh));
  }
  compare_with_reader("meshio", files, dumps);
}

// A planar 2D mesh (space_dim 2) whose vertices are all used (Gmsh keeps only used nodes):
// a strip of triangles and quadrilaterals with boundary edges, or their quadratic versions.
Mesh planar_mesh(bool quadratic) {
  Mesh m;
  m.space_dim = 2;
  const int nx = 5, ny = 3;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x[2] = {0.3 * i + 0.01 * j, 0.7 * j};
      m.add_vertex(x);
    }
  auto mid = [&](std::int32_t a, std::int32_t b) {
    const double x[2] = {0.5 * (m.vertex(a)[0] + m.vertex(b)[0]),
                         0.5 * (m.vertex(a)[1] + m.vertex(b)[1])};
    return m.add_vertex(x);
  };
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const std::int32_t a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      if ((i + j) % 2 == 0 && !quadratic) {
        const std::int32_t q[4] = {a, b, c, d};
        m.add_cell(CellType::kQuad4, q, 5);
      } else if (!quadratic) {
        const std::int32_t t1[3] = {a, b, c}, t2[3] = {a, c, d};
        m.add_cell(CellType::kTri3, t1, 6);
        m.add_cell(CellType::kTri3, t2, 6);
      } else {
        const std::int32_t t1[6] = {a, b, c, mid(a, b), mid(b, c), mid(c, a)};
        const std::int32_t t2[6] = {a, c, d, mid(a, c), mid(c, d), mid(d, a)};
        m.add_cell(CellType::kTri6, t1, 6);
        m.add_cell(CellType::kTri6, t2, 6);
      }
    }
  for (std::int32_t i = 0; i + 1 < nx; ++i) {
    if (quadratic) {
      const std::int32_t e[3] = {i, i + 1, mid(i, i + 1)};
      m.add_cell(CellType::kLine3, e, 7);
    } else {
      const std::int32_t e[2] = {i, i + 1};
      m.add_cell(CellType::kLine2, e, 7);
    }
  }
  return m;
}

// Gmsh 4.8 could not open tmop's 2D Medit files ("Wrong node index 0"): it takes the line after
// "Dimension" as the value, so the one-line "Dimension 2" hid the Vertices keyword. meshio 5
// reads linear Medit cells only (no EdgesP2 / TrianglesP2), Gmsh both.
TEST(TmopWrites, GmshAndMeshioReadTwoDimensionalMedit) {
  SKIP_UNLESS(test::have_python_module("gmsh") || test::have_python_module("meshio"),
              "python3-gmsh and python3-meshio");
  const std::string dir = test::temp_dir();
  const Mesh linear = planar_mesh(false), quadratic = planar_mesh(true);
  const std::string lin = dir + "/planar.mesh", quad = dir + "/planar_p2.mesh";
  ASSERT_TRUE(write_mesh(lin, linear).ok());
  ASSERT_TRUE(write_mesh(quad, quadratic).ok());
  Dump dl = test::dump_of(linear), dq = test::dump_of(quadratic);
  if (test::have_python_module("meshio")) compare_with_reader("meshio", {lin}, {dl});
  if (test::have_python_module("gmsh")) {
    // Gmsh keeps Medit references as elementary tags, not physical groups.
    test::strip_regions(&dl);
    test::strip_regions(&dq);
    compare_with_reader("gmsh", {lin, quad}, {dl, dq});
  }
}

// Each triangle as its three corner coordinates, starting at the smallest corner (orientation
// kept), so that readers that number STL vertices differently compare equal.
std::vector<std::string> triangles_by_coordinates(const std::vector<double>& xyz,
                                                  const std::vector<std::string>& cells) {
  std::vector<std::string> out;
  for (const std::string& c : cells) {
    std::istringstream in(c);
    std::string type;
    int region, n[3];
    in >> type >> region >> n[0] >> n[1] >> n[2];
    if (type != "tri3") continue;
    std::string corner[3];
    for (int k = 0; k < 3; ++k) {
      std::ostringstream p;
      p.precision(17);
      for (int j = 0; j < 3; ++j) p << xyz[3 * n[k] + j] << " ";
      corner[k] = p.str();
    }
    const int first = static_cast<int>(std::min_element(corner, corner + 3) - corner);
    out.push_back(corner[first] + "| " + corner[(first + 1) % 3] + "| " + corner[(first + 2) % 3]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// OpenMesh's ASCII STL (a blank line before every "endloop") made meshio reject the file and Gmsh
// 4.8 read 205 of 380 triangles. Both must read every triangle of tmop's ASCII and binary STL.
TEST(TmopWrites, GmshAndMeshioReadEveryStlTriangle) {
  SKIP_UNLESS(test::have_python_module("gmsh") || test::have_python_module("meshio"),
              "python3-gmsh and python3-meshio");
  const std::string dir = test::temp_dir();
  Mesh m;
  for (int j = 0; j < 11; ++j)
    for (int i = 0; i < 20; ++i) {
      // float32-exact, so that binary STL holds the same values.
      const double x[3] = {0.25 * i + 0.0625, 0.125 * j, 0.03125 * ((i * j) % 5)};
      m.add_vertex(x);
    }
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 19; ++i) {
      const std::int32_t a = j * 20 + i, t1[3] = {a, a + 1, a + 21}, t2[3] = {a, a + 21, a + 20};
      m.add_cell(CellType::kTri3, t1);
      m.add_cell(CellType::kTri3, t2);
    }
  ASSERT_EQ(m.num_cells(), 380);
  const Dump mine = test::dump_of(m);
  const std::vector<std::string> want = triangles_by_coordinates(mine.xyz, mine.cells);
  std::vector<std::string> files;
  for (bool binary : {false, true}) {
    WriteOptions o;
    o.binary = binary;
    files.push_back(dir + (binary ? "/b.stl" : "/a.stl"));
    ASSERT_TRUE(write_mesh(files.back(), m, o).ok());
  }
  for (const char* reader : {"gmsh", "meshio"}) {
    if (!test::have_python_module(reader)) continue;
    std::string cmd = std::string(kPy) + " " + test::python_helper() + " " + reader;
    for (const std::string& f : files) cmd += " '" + f + "'";
    std::string out;
    ASSERT_EQ(test::run(cmd, &out), 0) << cmd << "\n" << out;
    for (const std::string& f : files) {
      Dump d;
      std::string err;
      ASSERT_TRUE(test::parse_dump_file(f + "." + reader + ".dump", &d, &err)) << err;
      const std::vector<std::string> got = triangles_by_coordinates(d.xyz, d.cells);
      EXPECT_EQ(got.size(), 380u) << reader << " reading " << f;
      EXPECT_TRUE(got == want) << reader << " reading " << f;
    }
  }
}

TEST(MeshioWrites, TmopReadsEveryFormat) {
  SKIP_UNLESS(test::have_python_module("meshio"), "python3-meshio");
  const std::string dir = test::temp_dir();
  std::string out;
  ASSERT_EQ(
      test::run(std::string(kPy) + " " + test::python_helper() + " meshio-write '" + dir + "'",
                &out),
      0)
      << out;
  int checked = 0;
  for (const char* name : {"ascii.vtu", "zlib.vtu", "raw.vtu", "ascii.vtk", "binary.vtk",
                           "ascii42.vtk", "binary42.vtk", "ascii22.msh", "binary22.msh",
                           "ascii41.msh", "binary41.msh", "medit.mesh"}) {
    const std::string path = dir + "/" + name;
    Dump expected;
    std::string err;
    if (!test::parse_dump_file(path + ".expected", &expected, &err)) {
      ADD_FAILURE() << "meshio did not write " << name << ": " << out;
      continue;
    }
    Mesh m;
    const Status s = read_mesh(path, &m);
    ASSERT_TRUE(s.ok()) << s.message();
    Dump got = test::dump_of(m);
    const std::string n = name;
    if (n.find("41.msh") != std::string::npos) {
      // meshio's 4.1 writer lists only the entities named in gmsh:dim_tags (volume 100) in
      // $Entities, so only the cells of that entity carry their physical tag in the file.
      for (int c = 0; c < m.num_cells(); ++c)
        EXPECT_EQ(m.cell_region[c], m.cell_entity[c] == 100 ? 10 : 0) << name;
      test::strip_regions(&expected);
      test::strip_regions(&got);
    }
    // meshio's ASCII .vtu writer prints 11 significant digits.
    const double tol = n == "ascii.vtu" ? 1e-10 : 0.0;
    EXPECT_EQ(test::diff_dumps(expected, got, tol), "") << name;
    ++checked;
  }
  EXPECT_EQ(checked, 12);
}

}  // namespace
}  // namespace tmop
