// Issue 22's acceptance run: a Gmsh mesh with named physical groups and a periodic pair of sides
// goes through tmop_optimize into .msh 2.2, .msh 4.1, .vtu, .exo, .cgns and .su2, and every
// name survives as each format's own client reads it (tests/io/names_check.py: the Gmsh API,
// meshio and VTK, netCDF4, h5py; SU2 has markers for boundary names only). The periodic
// vertices come out bit for bit where they went in, with the boundary sliding. The boundary names
// are also in the sets solvers read: Exodus side sets and CGNS BC_t nodes (names_check.py sides:
// netCDF4 / h5py and VTK's readers); and a Cubit-style copy (triangle blocks and side sets only)
// goes through tmop_optimize with its boundary names into .exo and .cgns.
#include <gtest/gtest.h>
#include <stdio.h>
#include <sys/wait.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include "run_command.h"
#include "tmop/io/exodus_sides.h"
#include "tmop/io/mesh_io.h"

#ifdef TMOP_TEST_WITH_EXODUS
#include <exodusII.h>
#endif

namespace tmop {
namespace {

const std::string kPy = "/usr/bin/python3";
const std::string kHelper = std::string(TMOP_SOURCE_DIR) + "/tests/io/names_check.py";

int run(const std::string& cmd, std::string* out) { return testing_recipes::run_command(cmd, out); }

bool have(const std::string& module) {
  std::string out;
  return run(kPy + " -c 'import " + module + "'", &out) == 0;
}

// The number of boundary cells (dimension dim - 1) of each name, "name:count|...".
std::string boundary_counts(const Mesh& m) {
  std::map<std::string, int> n;
  const int dim = m.dim();
  for (int c = 0; c < m.num_cells(); ++c) {
    if (cell_dim(m.cell_types[c]) != dim - 1) continue;
    const std::string* name = m.physical_name(dim - 1, m.cell_region[c]);
    ++n[name ? *name : "(none)"];
  }
  std::string s;
  for (const auto& e : n) s += e.first + ":" + std::to_string(e.second) + "|";
  return s;
}

// Writes dir/cubit.exo from dir/o.exo as Cubit does: the triangles as blocks, the boundary as
// side sets only, and runs it through tmop_optimize into .exo and .cgns.
void boundary_names_survive_from_side_sets(const std::string& dir, const std::string& tool) {
#ifdef TMOP_TEST_WITH_EXODUS
  Mesh m;
  ASSERT_TRUE(read_mesh(dir + "/o.exo", &m).ok());
  ASSERT_EQ(m.dim(), 2);
  std::vector<int> number(m.num_cells(), 0);
  std::vector<int> conn;
  int ne = 0;
  for (int c = 0; c < m.num_cells(); ++c) {
    if (m.cell_types[c] != CellType::kTri3) continue;
    number[c] = ++ne;
    for (int i = 0; i < 3; ++i) conn.push_back(m.cell(c)[i] + 1);
  }
  ASSERT_GT(ne, 0);
  const std::vector<io::ExoSideSet> sets = io::plan_exodus_side_sets(m, number, 2);
  ASSERT_EQ(sets.size(), 3u);
  const std::string cubit = dir + "/cubit.exo";
  int ws = 8, iows = 8;
  const int f = ex_create(cubit.c_str(), EX_CLOBBER, &ws, &iows);
  ASSERT_GE(f, 0);
  std::vector<double> x, y;
  for (int v = 0; v < m.num_vertices(); ++v)
    x.push_back(m.vertex(v)[0]), y.push_back(m.vertex(v)[1]);
  ASSERT_GE(ex_put_init(f, "cubit-style", 2, m.num_vertices(), ne, 1, 0, 3), 0);
  ASSERT_GE(ex_put_coord(f, x.data(), y.data(), nullptr), 0);
  ASSERT_GE(ex_put_block(f, EX_ELEM_BLOCK, 1, "TRI3", ne, 3, 0, 0, 0), 0);
  ASSERT_GE(ex_put_conn(f, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr), 0);
  std::vector<std::string> names;
  for (const io::ExoSideSet& s : sets) {
    ASSERT_GE(ex_put_set_param(f, EX_SIDE_SET, s.id, static_cast<int>(s.elems.size()), 0), 0);
    ASSERT_GE(ex_put_set(f, EX_SIDE_SET, s.id, s.elems.data(), s.sides.data()), 0);
    names.push_back(s.name);
  }
  std::vector<char*> ptr;
  for (std::string& n : names) ptr.push_back(&n[0]);
  ASSERT_GE(ex_put_names(f, EX_SIDE_SET, ptr.data()), 0);
  ex_close(f);
  Mesh c;
  ASSERT_TRUE(read_mesh(cubit, &c).ok());
  const std::string want = boundary_counts(m);
  EXPECT_EQ(boundary_counts(c), want);
  EXPECT_EQ(want.find("(none)"), std::string::npos) << want;
  for (const char* name : {"c.exo", "c.cgns"}) {
    std::string out;
    ASSERT_EQ(run(tool + " --input=" + cubit + " --output=" + dir + "/" + name +
                      " --boundary=slide --threads=1",
                  &out),
              0)
        << out;
    Mesh back;
    ASSERT_TRUE(read_mesh(dir + "/" + name, &back).ok());
    EXPECT_EQ(boundary_counts(back), want) << name;
    if (!have(std::string(name) == "c.exo" ? "netCDF4" : "h5py")) continue;
    out.clear();
    ASSERT_EQ(run(kPy + " " + kHelper + " sides " + dir + "/" + name, &out), 0) << out;
    EXPECT_NE(out.find("\tinlet|outlet|wall\n"), std::string::npos) << name << ": " << out;
  }
#else
  (void)dir;
  (void)tool;
#endif
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

  // The boundary names as side sets and BCs.
  for (const char* name : {"o.exo", "o.cgns"}) {
    if (!have(std::string(name) == "o.exo" ? "netCDF4" : "h5py")) continue;
    out.clear();
    ASSERT_EQ(run(kPy + " " + kHelper + " sides " + dir + "/" + name, &out), 0) << out;
    EXPECT_NE(out.find("\tinlet|outlet|wall\n"), std::string::npos) << name << ": " << out;
  }
  boundary_names_survive_from_side_sets(dir, tool);

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
