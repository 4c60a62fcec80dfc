// Every file under tests/data/bad/ is broken in one way (its name says how). Reading must fail
// without crashing, with one line "FILE:LINE: what" or "FILE:byte N: what".
#include <dirent.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

// "LINE: what" or "byte N: what" (std::regex trips GCC 12 warnings under sanitizers).
bool located(const std::string& rest) {
  std::size_t i = rest.rfind("byte ", 0) == 0 ? 5 : 0;
  const std::size_t digits = i;
  while (i < rest.size() && rest[i] >= '0' && rest[i] <= '9') ++i;
  return i > digits && rest.compare(i, 2, ": ") == 0 && i + 2 < rest.size() && rest[i + 2] != ' ';
}

std::vector<std::string> corpus() {
  const std::string dir = std::string(TMOP_SOURCE_DIR) + "/tests/data/bad";
  std::vector<std::string> files;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name[0] == '.' || name.size() < 3 || name.substr(name.size() - 3) == ".py") continue;
      files.push_back(dir + "/" + name);
    }
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(BadInput, EveryCorpusFileFailsWithALocatedOneLineMessage) {
  const std::vector<std::string> files = corpus();
  ASSERT_GE(files.size(), 60u);
  for (const std::string& path : files) {
    Mesh mesh;
    mesh.space_dim = 3;
    const Status s = read_mesh(path, &mesh);
    ASSERT_FALSE(s.ok()) << path << " was accepted";
    const std::string& m = s.message();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    ASSERT_EQ(m.compare(0, path.size() + 1, path + ":"), 0) << m;
    const std::string rest = m.substr(path.size() + 1);
    if (path.find("unknown_extension") != std::string::npos) {
      EXPECT_NE(rest.find("unknown mesh file extension"), std::string::npos) << m;
    } else {
      EXPECT_TRUE(located(rest)) << m;
    }
    // A failed read leaves an empty mesh.
    EXPECT_EQ(mesh.num_vertices(), 0) << path;
    EXPECT_EQ(mesh.num_cells(), 0) << path;
  }
}

// Spot checks that the location and the diagnosis are the right ones.
TEST(BadInput, MessagesNameTheProblemAndItsPlace) {
  const std::string dir = std::string(TMOP_SOURCE_DIR) + "/tests/data/bad/";
  struct Expect {
    const char* file;
    const char* text;
  };
  const Expect expects[] = {
      {"nan_coordinate.msh", "nan_coordinate.msh:7: coordinate is not finite"},
      {"inf_coordinate.msh", "inf_coordinate.msh:8: coordinate out of range"},
      {"unknown_element_type.msh", "unknown_element_type.msh:12: unsupported Gmsh element type 99"},
      {"node_out_of_range.msh", "node_out_of_range.msh:12: node tag 9 is not defined"},
      {"huge_node_count.msh", "huge_node_count.msh:5: declared node count 2000000000"},
      {"wrong_endianness22.msh", "wrong_endianness22.msh:byte 20: endianness marker"},
      {"wrong_datasize22.msh", "wrong_datasize22.msh:2: binary data size 4"},
      {"mixed_dimensions41.msh", "mixed_dimensions41.msh:18: element type tet4 (dimension 3)"},
      {"mixed_dimensions.mesh", "mixed_dimensions.mesh:9: Tetrahedra (3D cells) in a Dimension 2"},
      {"repeated_vertices.mesh", "repeated_vertices.mesh:8: repeated Vertices section"},
      {"index_out_of_range.mesh", "index_out_of_range.mesh:10: vertex index 4 out of range 1..3"},
      {"unknown_cell_type.vtk", "unknown_cell_type.vtk:10: cell 0: unsupported VTK cell type 42"},
      {"huge_point_count.vtk", "huge_point_count.vtk:5: declared value count 2999999997"},
      {"wrong_byte_count.vtu", "declares 1000 bytes"},
      {"truncated_binary22.msh", "truncated_binary22.msh:byte "},
      // Surface formats: OpenMesh accepted these silently (garbage skipped, faces dropped, NaN
      // read as a coordinate, empty meshes).
      {"garbage_line.obj", "garbage_line.obj:4: unknown OBJ statement 'this'"},
      {"index_out_of_range.obj", "index_out_of_range.obj:5: vertex index 9 out of range"},
      {"nan_coordinate.obj", "nan_coordinate.obj:4: coordinate is not finite"},
      {"short_face.obj", "short_face.obj:5: face has 2 vertices"},
      {"repeated_vertex.obj", "repeated_vertex.obj:4: face uses vertex 2 twice"},
      {"inf_coordinate.off", "inf_coordinate.off:4: coordinate is not finite"},
      {"index_out_of_range.off", "index_out_of_range.off:6: vertex index 3 out of range 0..2"},
      {"truncated.off", "truncated.off:8: unexpected end of file after 1 of 2 faces"},
      {"data_after_faces.off", "data_after_faces.off:7: unexpected data after the last face"},
      {"pentagon.off", "pentagon.off:8: face has 5 vertices"},
      {"index_out_of_range_binary.off", "index_out_of_range_binary.off:byte 71: vertex index 5"},
      {"nan_coordinate.ply", "nan_coordinate.ply:11: coordinate is not finite"},
      {"index_out_of_range.ply", "index_out_of_range.ply:13: vertex index 7 out of range 0..2"},
      {"truncated.ply", "truncated.ply:14: unexpected end of file"},
      {"nan_binary.ply", "nan_binary.ply:byte 185: coordinate is not finite"},
      {"index_out_of_range_binary.ply", "index_out_of_range_binary.ply:byte 214: vertex index 3"},
      {"truncated_binary.ply", "truncated_binary.ply:byte 205: list length 3 runs past the end"},
      {"nan_coordinate.stl", "nan_coordinate.stl:6: coordinate is not finite"},
      {"two_vertex_facet.stl", "two_vertex_facet.stl:2: facet has 2 vertices, expected 3"},
      {"degenerate_facet.stl", "degenerate_facet.stl:2: facet has two equal corners"},
      {"truncated.stl", "truncated.stl:12: unexpected end of file, expected 'endloop'"},
      {"empty_facets.stl", "empty_facets.stl:3: expected 'facet' or 'endsolid', got 'endloop'"},
      {"nan_binary.stl", "nan_binary.stl:byte 174: coordinate of triangle 1 is not finite"},
      {"no_triangles_binary.stl", "no_triangles_binary.stl:byte 80: no triangles"},
      // Said "offsets give 3 nodes, expected 3".
      {"short_connectivity.vtu",
       "short_connectivity.vtu:11: cell 1 (tri3) ends at offset 6, but the connectivity array has "
       "only 5 values"},
  };
  for (const Expect& e : expects) {
    Mesh mesh;
    const Status s = read_mesh(dir + e.file, &mesh);
    ASSERT_FALSE(s.ok()) << e.file;
    EXPECT_NE(s.message().find(e.text), std::string::npos) << s.message();
  }
}

TEST(BadInput, MissingFileAndDirectory) {
  Mesh mesh;
  Status s = read_mesh("/nonexistent/dir/mesh.msh", &mesh);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(),
            "/nonexistent/dir/mesh.msh: cannot open for reading (No such file or directory)");
  s = read_mesh(std::string(TMOP_SOURCE_DIR) + "/tests/data/bad", &mesh);
  EXPECT_FALSE(s.ok());
}

// Every prefix of a valid binary and ASCII file must be rejected cleanly (or, for prefixes that
// happen to be complete files, read); never crash.
TEST(BadInput, EveryTruncationOfValidFilesIsHandled) {
  const std::string dir = test::temp_dir();
  const Mesh m = test::make_mesh({CellType::kTet4, CellType::kHex8, CellType::kTri3});
  struct Case {
    const char* name;
    bool binary;
    int version;
  };
  for (const Case& c : {Case{"a.msh", false, 22}, Case{"b.msh", true, 22}, Case{"c.msh", true, 41},
                        Case{"d.msh", false, 41}, Case{"e.vtk", true, 0}, Case{"f.vtu", true, 0},
                        Case{"g.mesh", false, 0}}) {
    WriteOptions o;
    o.binary = c.binary;
    if (c.version) o.msh_version = c.version;
    const std::string full = dir + "/" + c.name;
    ASSERT_TRUE(write_mesh(full, m, o).ok());
    std::FILE* f = std::fopen(full.c_str(), "rb");
    std::string bytes(1 << 16, '\0');
    bytes.resize(std::fread(&bytes[0], 1, bytes.size(), f));
    std::fclose(f);
    const std::string cut = dir + "/cut_" + c.name;
    int failures = 0;
    for (std::size_t n = 0; n < bytes.size(); n += 7) {
      f = std::fopen(cut.c_str(), "wb");
      std::fwrite(bytes.data(), 1, n, f);
      std::fclose(f);
      Mesh out;
      const Status s = read_mesh(cut, &out);
      if (!s.ok()) {
        ++failures;
        EXPECT_EQ(s.message().compare(0, cut.size() + 1, cut + ":"), 0) << s.message();
      }
    }
    EXPECT_GT(failures, static_cast<int>(bytes.size() / 7 * 9 / 10)) << c.name;
  }
}

// The surface formats: OFF, PLY and STL declare what follows (or close it with endsolid), so
// nearly every prefix must be rejected; an OBJ cut at a line end is a shorter valid file. Every
// message is located, on one line.
TEST(BadInput, EveryTruncationOfSurfaceFilesIsHandled) {
  const std::string dir = test::temp_dir();
  struct Case {
    const char* name;
    bool binary;
    int min_failures_percent;
  };
  for (const Case& c : {Case{"a.off", false, 90}, Case{"b.off", true, 99}, Case{"c.ply", false, 90},
                        Case{"d.ply", true, 99}, Case{"e.stl", false, 99}, Case{"f.stl", true, 99},
                        Case{"g.obj", false, 0}}) {
    WriteOptions o;
    o.binary = c.binary;
    const std::string full = dir + "/" + c.name;
    const bool stl = std::string(c.name).find(".stl") != std::string::npos;
    const Mesh src =
        test::make_mesh(stl ? std::vector<CellType>{CellType::kTri3, CellType::kTri3}
                            : std::vector<CellType>{CellType::kTri3, CellType::kQuad4});
    ASSERT_TRUE(write_mesh(full, src, o).ok()) << c.name;
    std::FILE* f = std::fopen(full.c_str(), "rb");
    std::string bytes(1 << 16, '\0');
    bytes.resize(std::fread(&bytes[0], 1, bytes.size(), f));
    std::fclose(f);
    const std::string cut = dir + "/cut_" + c.name;
    int failures = 0, tries = 0;
    for (std::size_t n = 0; n < bytes.size(); n += 3, ++tries) {
      f = std::fopen(cut.c_str(), "wb");
      std::fwrite(bytes.data(), 1, n, f);
      std::fclose(f);
      Mesh out;
      const Status s = read_mesh(cut, &out);
      if (!s.ok()) {
        ++failures;
        EXPECT_EQ(s.message().compare(0, cut.size() + 1, cut + ":"), 0) << s.message();
        EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
      }
    }
    EXPECT_GE(failures * 100, tries * c.min_failures_percent) << c.name;
  }
}

// Random byte corruptions of valid files: never a crash, and failures are located messages.
TEST(BadInput, RandomByteCorruptionsAreHandled) {
  const std::string dir = test::temp_dir();
  const Mesh m = test::make_mesh({CellType::kTet10, CellType::kWedge6, CellType::kQuad4});
  std::uint64_t state = 12345;
  auto rnd = [&state]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<std::uint32_t>(state >> 33);
  };
  struct Case {
    const char* name;
    bool binary;
    int version;
  };
  for (const Case& c : {Case{"a.msh", false, 22}, Case{"b.msh", true, 22}, Case{"c.msh", true, 41},
                        Case{"d.msh", false, 41}, Case{"e.vtk", true, 0}, Case{"f.vtk", false, 0},
                        Case{"g.vtu", true, 0}, Case{"h.vtu", false, 0}, Case{"i.mesh", false, 0},
                        Case{"j.off", false, 0}, Case{"k.off", true, 0}, Case{"l.obj", false, 0},
                        Case{"m.ply", false, 0}, Case{"n.ply", true, 0}, Case{"o.stl", false, 0},
                        Case{"p.stl", true, 0}}) {
    WriteOptions o;
    o.binary = c.binary;
    if (c.version) o.msh_version = c.version;
    const std::string full = dir + "/" + c.name;
    const std::string ext = std::string(c.name).substr(2);
    const Mesh src = ext == "stl" ? test::make_mesh({CellType::kTri3, CellType::kTri3})
                     : ext == "off" || ext == "obj" || ext == "ply"
                         ? test::make_mesh({CellType::kTri3, CellType::kQuad4})
                         : m;
    ASSERT_TRUE(write_mesh(full, src, o).ok());
    std::FILE* f = std::fopen(full.c_str(), "rb");
    std::string bytes(1 << 16, '\0');
    bytes.resize(std::fread(&bytes[0], 1, bytes.size(), f));
    std::fclose(f);
    const std::string bad = dir + "/bad_" + c.name;
    for (int trial = 0; trial < 150; ++trial) {
      std::string b = bytes;
      const int flips = 1 + rnd() % 4;
      for (int k = 0; k < flips; ++k) b[rnd() % b.size()] = static_cast<char>(rnd() % 256);
      f = std::fopen(bad.c_str(), "wb");
      std::fwrite(b.data(), 1, b.size(), f);
      std::fclose(f);
      Mesh out;
      const Status s = read_mesh(bad, &out);
      if (!s.ok()) {
        EXPECT_EQ(s.message().compare(0, bad.size() + 1, bad + ":"), 0) << s.message();
        EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
      }
    }
  }
}

}  // namespace
}  // namespace tmop
