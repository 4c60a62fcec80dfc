// Physical names and periodic links (Mesh::physical_names, Mesh::periodic): .msh 2.2 / 4.1 in
// ASCII and binary read what Gmsh writes and write what Gmsh reads; .vtu (field data), Exodus
// (block names) and CGNS (section names) keep the names; bad $PhysicalNames lines fail at their
// line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

const char* kPy = "/usr/bin/python3";

std::string names_helper() { return std::string(TMOP_SOURCE_DIR) + "/tests/io/names_check.py"; }

void write_text(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

// A tri mesh with a named domain and named boundary lines, one periodic link with an affine.
Mesh named_mesh() {
  Mesh m = test::make_mesh({CellType::kTri3, CellType::kTri3, CellType::kLine2, CellType::kLine2});
  m.cell_region[3] = m.cell_region[2] + 100;  // two boundary regions, each its own entity
  m.cell_entity[3] = m.cell_entity[2] + 100;
  m.set_physical_name(2, m.cell_region[0], "fluid domain");
  m.set_physical_name(1, m.cell_region[2], "top's lid");
  m.set_physical_name(1, m.cell_region[3], "wall");
  m.set_physical_name(3, 99, "unused volume");  // names of tags without cells are kept too
  PeriodicLink link;
  link.dim = 1;
  link.tag = m.cell_entity[2];
  link.master_tag = m.cell_entity[3];
  link.affine = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  link.nodes = {{m.cell(2)[0], m.cell(3)[0]}, {m.cell(2)[1], m.cell(3)[1]}};
  m.periodic.push_back(link);
  PeriodicLink point;  // a point entity without cells, as Gmsh links corners
  point.dim = 0;
  point.tag = 41;
  point.master_tag = 42;
  point.nodes = {{m.cell(2)[0], m.cell(3)[0]}};
  m.periodic.push_back(point);
  return m;
}

std::string names_of(const Mesh& m) {
  std::string s;
  for (const PhysicalName& p : m.physical_names)
    s += std::to_string(p.dim) + ":" + std::to_string(p.tag) + ":" + p.name + ";";
  return s;
}

// The mesh with its names in (dim, tag) order, as the writers put them.
Mesh sorted_names(Mesh m) {
  std::sort(m.physical_names.begin(), m.physical_names.end(),
            [](const PhysicalName& a, const PhysicalName& b) {
              return a.dim != b.dim ? a.dim < b.dim : a.tag < b.tag;
            });
  return m;
}

TEST(PhysicalNames, MshRoundTripsNamesAndPeriodicLinksInEveryVariant) {
  const std::string dir = test::temp_dir();
  const Mesh mesh = named_mesh();
  for (int version : {22, 41})
    for (bool binary : {false, true}) {
      WriteOptions o;
      o.msh_version = version;
      o.binary = binary;
      const std::string path = dir + "/m" + std::to_string(version) + (binary ? "b" : "a") + ".msh";
      ASSERT_TRUE(write_mesh(path, mesh, o).ok()) << path;
      Mesh back;
      const Status s = read_mesh(path, &back);
      ASSERT_TRUE(s.ok()) << s.message();
      EXPECT_EQ(test::diff_meshes(mesh, back), "") << path;
      EXPECT_EQ(names_of(back), names_of(sorted_names(mesh))) << path;
      ASSERT_EQ(back.periodic.size(), 2u) << path;
      for (int l = 0; l < 2; ++l) {
        EXPECT_EQ(back.periodic[l].dim, mesh.periodic[l].dim);
        EXPECT_EQ(back.periodic[l].tag, mesh.periodic[l].tag);
        EXPECT_EQ(back.periodic[l].master_tag, mesh.periodic[l].master_tag);
        EXPECT_EQ(back.periodic[l].affine, mesh.periodic[l].affine);
        EXPECT_EQ(back.periodic[l].nodes, mesh.periodic[l].nodes);
      }
    }
}

TEST(PhysicalNames, ReadsWhatGmshWritesAndGmshReadsTmopsFiles) {
  if (!test::have_python_module("gmsh")) GTEST_SKIP() << "python3-gmsh not installed";
  const std::string dir = test::temp_dir();
  std::string out;
  ASSERT_EQ(test::run(std::string(kPy) + " " + names_helper() + " make-gmsh '" + dir + "'", &out),
            0)
      << out;
  for (const char* name : {"named.msh", "named22.msh"}) {
    Mesh m;
    const Status s = read_mesh(dir + "/" + name, &m);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_NE(m.physical_name(2, 7), nullptr) << name;
    EXPECT_EQ(*m.physical_name(2, 7), "fluid domain");
    ASSERT_NE(m.physical_name(1, 5), nullptr);
    EXPECT_EQ(*m.physical_name(1, 5), "wall");
    // Right = left + (1, 0): every pair is a translation of its master.
    std::size_t pairs = 0;
    for (const PeriodicLink& l : m.periodic)
      for (const auto& p : l.nodes) {
        ++pairs;
        EXPECT_NEAR(m.vertex(p.first)[0], m.vertex(p.second)[0] + 1, 1e-12) << name;
        EXPECT_NEAR(m.vertex(p.first)[1], m.vertex(p.second)[1], 1e-12) << name;
      }
    EXPECT_GE(pairs, 11u) << name;  // the curve's 11 nodes (4.1 adds the corner points)
    for (bool binary : {false, true}) {
      WriteOptions o;
      o.binary = binary;
      const std::string again = dir + "/again" + (binary ? "b_" : "a_") + name;
      ASSERT_TRUE(write_mesh(again, m, o).ok());
      out.clear();
      ASSERT_EQ(test::run(std::string(kPy) + " " + names_helper() + " names '" + again + "'", &out),
                0)
          << out;
      EXPECT_NE(out.find("\tfluid domain|inlet|outlet|wall"), std::string::npos) << out;
      out.clear();
      ASSERT_EQ(
          test::run(std::string(kPy) + " " + names_helper() + " periodic '" + again + "'", &out), 0)
          << out;
      EXPECT_EQ(std::stoul(out), pairs) << again;  // Gmsh reads every pair tmop wrote
    }
  }
}

std::string read_error(const std::string& path) {
  Mesh m;
  const Status s = read_mesh(path, &m);
  return s.ok() ? "ok" : s.message();
}

TEST(PhysicalNames, BadNameLinesFailAtTheirLine) {
  const std::string dir = test::temp_dir();
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n";
  const std::string rest =
      "$EndPhysicalNames\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n1 15 2 0 1 1\n"
      "$EndElements\n";
  write_text(dir + "/a.msh", head + "1 3 \"ok\"\n1 4 wall\n" + rest);
  EXPECT_EQ(read_error(dir + "/a.msh"),
            dir + "/a.msh:7: expected a physical name in double quotes after the tag");
  write_text(dir + "/b.msh", head + "1 3 \"ok\"\n1 4 \"wall\n" + rest);
  EXPECT_EQ(read_error(dir + "/b.msh"),
            dir + "/b.msh:7: physical name has no closing double quote on its line");
  write_text(dir + "/c.msh", head + "1 3 \"a\"b\"\n1 4 \"w\"\n" + rest);
  EXPECT_NE(read_error(dir + "/c.msh").find("/c.msh:6: text after the closing quote"),
            std::string::npos);
  write_text(dir + "/d.msh", head + "1 3 \"a\"\n1 3 \"b\"\n" + rest);
  EXPECT_EQ(read_error(dir + "/d.msh"),
            dir + "/d.msh:7: second name for physical tag 3 of dimension 1");
  write_text(dir + "/e.msh", head + "7 3 \"a\"\n1 3 \"b\"\n" + rest);
  EXPECT_EQ(read_error(dir + "/e.msh"), dir + "/e.msh:6: physical dimension 7 out of range 0..3");
  // A huge count is refused before anything is allocated.
  write_text(dir + "/f.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2000000000\n");
  EXPECT_NE(read_error(dir + "/f.msh").find("declared physical name count 2000000000"),
            std::string::npos);
  // Periodic nodes must exist.
  write_text(dir + "/g.msh",
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Periodic\n1\n"
             "1 2 4\n1\n1 9\n$EndPeriodic\n");
  EXPECT_EQ(read_error(dir + "/g.msh"), dir + "/g.msh:12: master node tag 9 is not in $Nodes");
  write_text(dir + "/h.msh",
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Periodic\n1\n"
             "1 2 4\n2000000000\n1 1\n$EndPeriodic\n");
  EXPECT_NE(
      read_error(dir + "/h.msh").find("/h.msh:11: declared periodic node pair count 2000000000"),
      std::string::npos)
      << read_error(dir + "/h.msh");
  write_text(dir + "/i.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Periodic\n0\n$EndPeriodic\n");
  EXPECT_EQ(read_error(dir + "/i.msh"), dir + "/i.msh:4: $Periodic before $Nodes");
  write_text(dir + "/j.msh",
             "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n0 1 0 1\n1\n0 0 0\n"
             "$EndNodes\n$Periodic\n1\n0 1 2\n3 1 0 0\n1\n1 1\n$EndPeriodic\n");
  EXPECT_EQ(read_error(dir + "/j.msh"),
            dir + "/j.msh:13: a periodic link has 0 or 16 affine values, not 3");
}

TEST(PhysicalNames, NamesGmshCannotReadAreRefused) {
  const std::string dir = test::temp_dir();
  Mesh m = named_mesh();
  m.set_physical_name(1, 5, "say \"hi\"");
  const Status s = check_writable(dir + "/q.msh", m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cannot write physical name 'say \"hi\"' to .msh"), std::string::npos)
      << s.message();
  EXPECT_TRUE(write_mesh(dir + "/q.vtu", m).ok());  // XML escapes it
}

TEST(PhysicalNames, VtuAndVtkKeepNamesAsFieldDataMeshioAndVtkRead) {
  const std::string dir = test::temp_dir();
  const Mesh mesh = named_mesh();
  for (const std::string name : {"a.vtu", "b.vtu", "a.vtk", "b.vtk"}) {
    WriteOptions o;
    o.binary = name[0] == 'b';
    const std::string path = dir + "/" + name;
    ASSERT_TRUE(write_mesh(path, mesh, o).ok());
    Mesh back;
    ASSERT_TRUE(read_mesh(path, &back).ok());
    EXPECT_EQ(names_of(back), "1:" + std::to_string(mesh.cell_region[2]) +
                                  ":top's lid;1:" + std::to_string(mesh.cell_region[3]) +
                                  ":wall;2:" + std::to_string(mesh.cell_region[0]) +
                                  ":fluid domain;3:99:unused volume;");
    if (!test::have_python_module("meshio")) continue;
    if (name.find(".vtk") != std::string::npos && !test::have_python_module("vtk")) continue;
    std::string out;
    ASSERT_EQ(test::run(std::string(kPy) + " " + names_helper() + " names '" + path + "'", &out), 0)
        << out;
    EXPECT_NE(out.find("\tfluid domain|top's lid|unused volume|wall"), std::string::npos) << out;
  }
}

#ifdef TMOP_TEST_WITH_EXODUS
TEST(PhysicalNames, ExodusKeepsNamesAsBlockNames) {
  const std::string dir = test::temp_dir();
  Mesh mesh = named_mesh();
  const std::string long_name(200, 'w');  // beyond Exodus's default of 32 characters
  mesh.set_physical_name(1, mesh.cell_region[2], long_name);
  ASSERT_TRUE(write_mesh(dir + "/a.exo", mesh).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/a.exo", &back).ok());
  ASSERT_NE(back.physical_name(2, back.cell_region[0]), nullptr);
  EXPECT_EQ(*back.physical_name(2, back.cell_region[0]), "fluid domain");
  ASSERT_NE(back.physical_name(1, back.cell_region[3]), nullptr);
  EXPECT_EQ(*back.physical_name(1, back.cell_region[3]), "wall");
  ASSERT_NE(back.physical_name(1, back.cell_region[2]), nullptr);
  EXPECT_EQ(*back.physical_name(1, back.cell_region[2]), long_name);
  if (!test::have_python_module("netCDF4")) return;
  std::string out;
  ASSERT_EQ(test::run(std::string(kPy) + " " + names_helper() + " names '" + dir + "/a.exo'", &out),
            0)
      << out;
  EXPECT_NE(out.find("\tfluid domain|wall|" + long_name), std::string::npos) << out;
}
#endif

#ifdef TMOP_TEST_WITH_CGNS
TEST(PhysicalNames, CgnsKeepsNamesAsSectionNames) {
  const std::string dir = test::temp_dir();
  const Mesh mesh = named_mesh();
  const Status w = write_mesh(dir + "/a.cgns", mesh);
  ASSERT_TRUE(w.ok()) << w.message();
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/a.cgns", &back).ok());
  EXPECT_EQ(test::diff_meshes(mesh, back, false), "");
  ASSERT_NE(back.physical_name(2, mesh.cell_region[0]), nullptr);
  EXPECT_EQ(*back.physical_name(2, mesh.cell_region[0]), "fluid domain");
  ASSERT_NE(back.physical_name(1, mesh.cell_region[2]), nullptr);
  EXPECT_EQ(*back.physical_name(1, mesh.cell_region[2]), "top's lid");
  if (!test::have_python_module("h5py")) return;
  std::string out;
  ASSERT_EQ(
      test::run(std::string(kPy) + " " + names_helper() + " names '" + dir + "/a.cgns'", &out), 0)
      << out;
  EXPECT_NE(out.find("\tfluid domain|top's lid|wall"), std::string::npos) << out;
}
#endif

}  // namespace
}  // namespace tmop
