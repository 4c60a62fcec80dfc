// Gmsh's partitioned meshes (`gmsh -part N`, MSH 4.1 with $PartitionedEntities) read as the
// model's mesh: every cell with the physical group and the model entity it has in the
// unpartitioned file, no cells of the partitioner's own (the cut surfaces, curves and points
// between partitions, and with -part_ghosts the copies of the neighbours' cells), in ASCII and
// binary. Before: every partitioned cell had region 0 (the physical groups were lost) and the
// cuts came in as hundreds of stray triangles inside the volume. One file of -part_split is
// one partition's cells, with their groups.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "tests/io/io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

// One line per cell: type, region, entity and its nodes' coordinates (sorted: the files number
// nodes differently), sorted.
std::vector<std::string> cell_keys(const Mesh& m) {
  std::vector<std::string> keys;
  for (int c = 0; c < m.num_cells(); ++c) {
    std::vector<std::string> nodes;
    for (int k = 0; k < m.cell_size(c); ++k) {
      const double* x = m.vertex(m.cell(c)[k]);
      char b[96];
      std::snprintf(b, sizeof b, "(%.12g %.12g %.12g)", x[0], x[1], m.space_dim == 3 ? x[2] : 0.0);
      nodes.push_back(b);
    }
    std::sort(nodes.begin(), nodes.end());
    std::string key = std::to_string(static_cast<int>(m.cell_type(c))) + " " +
                      std::to_string(m.cell_region[c]) + " " + std::to_string(m.cell_entity[c]);
    for (const std::string& n : nodes) key += " " + n;
    keys.push_back(key);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(PartitionedMsh, GmshPartitionsReadAsTheModelsMesh) {
  if (!test::have_program("gmsh")) GTEST_SKIP() << "gmsh not installed";
  const std::string dir = test::temp_dir();
  {
    std::ofstream geo(dir + "/two.geo");
    geo << "SetFactory(\"OpenCASCADE\");\n"
           "Box(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {1, 0, 0, 1, 1, 1};\n"
           "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
           "Physical Volume(\"left\", 7) = {1};\nPhysical Volume(\"right\", 8) = {2};\n"
           "Physical Surface(\"bottom\", 9) = Surface In BoundingBox{-1, -1, -0.1, 3, 2, 0.1};\n"
           "Mesh.MeshSizeMax = 0.3;\n";
  }
  std::string out;
  auto mesh = [&](const std::string& args, const std::string& name) {
    return test::run("cd " + dir + " && gmsh two.geo -3 -nt 1 -v 0 -format msh41 " + args + " -o " +
                         name + " > /dev/null 2>&1",
                     &out);
  };
  ASSERT_EQ(mesh("", "whole.msh"), 0);
  Mesh whole;
  ASSERT_TRUE(read_mesh(dir + "/whole.msh", &whole).ok());
  const std::vector<std::string> expected = cell_keys(whole);
  ASSERT_GT(whole.num_cells(), 100);
  for (const std::string args : {"-part 3", "-part 3 -bin", "-part 4 -part_ghosts"}) {
    ASSERT_EQ(mesh(args, "parts.msh"), 0) << args;
    Mesh parts;
    const Status s = read_mesh(dir + "/parts.msh", &parts);
    ASSERT_TRUE(s.ok()) << args << ": " << s.message();
    EXPECT_EQ(cell_keys(parts), expected) << args;
    EXPECT_EQ(parts.physical_names.size(), whole.physical_names.size()) << args;
  }
  // -part_split: each file holds one partition's cells; together, the model's.
  ASSERT_EQ(mesh("-part 3 -part_split", "split.msh"), 0);
  std::vector<std::string> together;
  for (int k = 1; k <= 3; ++k) {
    Mesh part;
    const Status s = read_mesh(dir + "/split_" + std::to_string(k) + ".msh", &part);
    ASSERT_TRUE(s.ok()) << k << ": " << s.message();
    const std::vector<std::string> keys = cell_keys(part);
    together.insert(together.end(), keys.begin(), keys.end());
  }
  std::sort(together.begin(), together.end());
  EXPECT_EQ(together, expected);
}

}  // namespace
}  // namespace tmop
