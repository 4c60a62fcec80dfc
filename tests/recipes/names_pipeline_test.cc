// Issue 22's acceptance run: a Gmsh mesh with named physical groups and a periodic pair of sides
// goes through tmop_optimize into .msh 2.2, .msh 4.1, .vtu, .exo, .cgns and .su2, and every
// name survives as each format's own client reads it (tests/io/names_check.py: the Gmsh API,
// meshio and VTK, netCDF4, h5py; SU2 has markers for boundary names only). The periodic
// vertices come out bit for bit where they went in, with the boundary sliding.
#include <gtest/gtest.h>
#include <stdio.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "run_command.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

const std::string kPy = "/usr/bin/python3";
const std::string kHelper = std::string(TMOP_SOURCE_DIR) + "/tests/io/names_check.py";

int run(const std::string& cmd, std::string* out) { return testing_recipes::run_command(cmd, out); }

bool have(const std::string& module) {
  std::string out;
  return run(kPy + " -c 'import " + module + "'", &out) == 0;
}

TEST(NamesPipeline, EveryNameSurvivesTmopOptimizeIntoEveryFormat) {
  const std::string tool = TMOP_BINARY_DIR "/tools/tmop_optimize";
  if (std::system(("test -x " + tool).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
  if (!have("gmsh")) GTEST_SKIP() << "python3-gmsh not installed";
  char tmpl[] = "/tmp/tmop_names_XXXXXX";
  ASSERT_NE(mkdtemp(tmpl), nullptr);
  const std::string dir = tmpl;
  std::string out;
  ASSERT_EQ(run(kPy + " " + kHelper + " make-gmsh " + dir, &out), 0) << out;
  Mesh input;
  ASSERT_TRUE(read_mesh(dir + "/named.msh", &input).ok());
  ASSERT_FALSE(input.periodic.empty());

  struct Output {
    std::string name, flags, names, module;
  };
  const std::string all = "fluid domain|inlet|outlet|wall";
  const Output outputs[] = {
      {"o22.msh", "--msh_version=2.2", all, "gmsh"},
      {"o41.msh", "--binary", all, "gmsh"},
      {"o.vtu", "", all, "meshio"},
      {"o.exo", "", all, "netCDF4"},
      {"o.cgns", "", all, "h5py"},
      {"o.su2", "", "inlet|outlet|wall", "meshio"},  // markers: boundary names only
  };
  for (const Output& o : outputs) {
    const std::string path = dir + "/" + o.name;
    out.clear();
    const int rc = run(tool + " --input=" + dir + "/named.msh --output=" + path +
                           " --boundary=slide --threads=1 " + o.flags,
                       &out);
    ASSERT_EQ(rc, 0) << o.name << "\n" << out;
    Mesh back;
    const Status s = read_mesh(path, &back);
    ASSERT_TRUE(s.ok()) << s.message();
    // tmop's own reader finds the names at the same cells.
    for (int c = 0; c < back.num_cells(); ++c) {
      const std::string* name =
          back.physical_name(cell_dim(back.cell_types[c]), back.cell_region[c]);
      if (o.name != "o.su2" || cell_dim(back.cell_types[c]) == 1) {
        EXPECT_NE(name, nullptr) << o.name << " cell " << c;
      }
    }
    if (!have(o.module)) {
      std::printf("%s: %s not installed, names checked by tmop only\n", o.name.c_str(),
                  o.module.c_str());
      continue;
    }
    out.clear();
    ASSERT_EQ(run(kPy + " " + kHelper + " names " + path, &out), 0) << out;
    EXPECT_NE(out.find("\t" + o.names + "\n"), std::string::npos) << o.name << ": " << out;
  }

  // Periodic pairs: Gmsh reads them back from 4.1, tmop from both, and no such vertex moved.
  out.clear();
  ASSERT_EQ(run(kPy + " " + kHelper + " periodic " + dir + "/o41.msh", &out), 0) << out;
  std::size_t pairs = 0;
  for (const PeriodicLink& l : input.periodic) pairs += l.nodes.size();
  EXPECT_EQ(std::stoul(out), pairs);
  for (const char* name : {"o22.msh", "o41.msh"}) {
    Mesh back;
    ASSERT_TRUE(read_mesh(dir + "/" + name, &back).ok());
    std::size_t back_pairs = 0;
    for (const PeriodicLink& l : back.periodic) back_pairs += l.nodes.size();
    EXPECT_EQ(back_pairs, pairs) << name;
    ASSERT_EQ(back.num_vertices(), input.num_vertices());
    int moved = 0;
    for (int v = 0; v < input.num_vertices(); ++v)
      moved += std::memcmp(back.vertex(v), input.vertex(v), 2 * sizeof(double)) != 0;
    EXPECT_GT(moved, 0) << name << ": the optimizer moved nothing";
    for (const PeriodicLink& l : input.periodic)
      for (const auto& p : l.nodes)
        for (int v : {p.first, p.second})
          EXPECT_EQ(std::memcmp(back.vertex(v), input.vertex(v), 2 * sizeof(double)), 0)
              << name << ": periodic vertex " << v << " moved";
  }
  std::system(("rm -rf " + dir).c_str());
}

}  // namespace
}  // namespace tmop
