// Mirrored-block tangles: a tet mesh of a box whose interior vertices within a slab around the
// mid-plane are reflected through it (the boundary stays), so that half or more of the tets
// invert. Read as a tangle (not as the opposite orientation convention: mesh/orientation.h) and
// untangled with the boundary fixed, by the library and by tmop_optimize.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/count_inverted.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

// An n^3 Kuhn grid of the unit cube, its interior vertices jittered and then those with
// |z - 1/2| <= slab mirrored through z = 1/2.
Mesh mirrored_block(int n, double slab, unsigned seed) {
  Mesh m = testing_grid::grid(CellType::kTet4, n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.1 / n, 0.1 / n);  // keeps every tet valid
  const std::vector<char> boundary = boundary_vertex_mask(m);
  for (int v = 0; v < m.num_vertices(); ++v)
    if (!boundary[v])
      for (int a = 0; a < 3; ++a) m.vertex(v)[a] += jitter(rng);
  for (int v = 0; v < m.num_vertices(); ++v)
    if (!boundary[v] && std::abs(m.vertex(v)[2] - 0.5) <= slab) m.vertex(v)[2] = 1 - m.vertex(v)[2];
  return m;
}

double inverted_fraction(const Mesh& m) {
  return static_cast<double>(count_inverted(m, 1)) / m.num_elements();
}

TEST(MirroredBlock, HalfAndSeventyPercentInvertedUntangleWithTheBoundaryFixed) {
  ASSERT_EQ(count_inverted(mirrored_block(12, -1, 5), 1), 0);  // the jitter alone inverts nothing
  for (const double slab : {0.35, 0.45}) {
    Mesh mesh = mirrored_block(12, slab, 5);
    const double fraction = inverted_fraction(mesh);
    ASSERT_GT(fraction, slab < 0.4 ? 0.45 : 0.6) << slab;
    ASSERT_FALSE(check_orientation(mesh).opposite_convention());
    const std::vector<double> before = mesh.coords;
    const std::vector<char> boundary = boundary_vertex_mask(mesh);
    UntangleOptions opt;
    opt.solver.threads = 1;
    opt.improve_shape_after = false;
    RecipeResult result;
    const Status s = untangle(&mesh, opt, &result);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(count_inverted(mesh, 1), 0);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      if (!boundary[v]) continue;
      for (int a = 0; a < 3; ++a) ASSERT_EQ(mesh.vertex(v)[a], before[3 * v + a]);
    }
    std::printf(
        "mirrored block slab %.2f: %.1f %% of %d tets inverted -> 0 in %d eps rounds, "
        "%.2f s\n",
        slab, 100 * fraction, mesh.num_elements(), result.stages[0].solves, result.seconds);
  }
}

class MirroredBlockTool : public ::testing::Test {
 protected:
  void SetUp() override {
    tool_ = TMOP_BINARY_DIR "/tools/tmop_optimize";
    if (std::system(("test -x " + tool_).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
    char dir[] = "/tmp/tmop_mirrored_XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    dir_ = dir;
    mesh_ = mirrored_block(8, 0.45, 7);  // 57 % of 3,072 tets inverted
    ASSERT_GT(2 * check_orientation(mesh_).negative, mesh_.num_elements());
    ASSERT_TRUE(write_mesh(dir_ + "/in.msh", mesh_).ok());
  }
  void TearDown() override {
    if (!dir_.empty()) std::system(("rm -rf " + dir_).c_str());
  }
  // Exit status; *out receives stdout and stderr.
  int run(const std::string& args, std::string* out) {
    const std::string cmd = tool_ + " --input=" + dir_ + "/in.msh --output=" + dir_ +
                            "/out.msh --threads=1 " + args + " > " + dir_ + "/log 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream f(dir_ + "/log");
    std::stringstream ss;
    ss << f.rdbuf();
    *out = ss.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string tool_, dir_;
  Mesh mesh_;
};

// More than half the tets negative, yet the boundary says Gmsh's convention: untangled, and the
// note says what was decided and why.
TEST_F(MirroredBlockTool, AutoReadsTheBoundaryAndUntangles) {
  std::string out;
  ASSERT_EQ(run("--recipe=untangle", &out), 0) << out;
  EXPECT_NE(out.find("Gmsh's convention: the boundary"), std::string::npos) << out;
  EXPECT_NE(out.find("the negative cells are inverted"), std::string::npos) << out;
  Mesh result;
  ASSERT_TRUE(read_mesh(dir_ + "/out.msh", &result).ok());
  EXPECT_EQ(count_inverted(result, 1), 0);
  ASSERT_EQ(run("--recipe=untangle --orientation=gmsh", &out), 0) << out;
  EXPECT_EQ(out.find("note:"), std::string::npos) << out;  // the default convention: no note
}

// --orientation=opposite states the other convention: the all-boundary tets are then inverted
// with every node fixed, an honest failure that says which convention was used.
TEST_F(MirroredBlockTool, OrientationFlagIsObeyedAndChecked) {
  std::string out;
  EXPECT_EQ(run("--recipe=untangle --orientation=opposite", &out), 1) << out;
  EXPECT_NE(out.find("opposite convention (--orientation=opposite"), std::string::npos) << out;
  EXPECT_NE(out.find("the boundary says Gmsh's convention: try --orientation=auto"),
            std::string::npos)
      << out;
  EXPECT_EQ(run("--orientation=inside_out", &out), 2) << out;
  EXPECT_NE(out.find("--orientation must be auto, gmsh or opposite"), std::string::npos) << out;
}

}  // namespace
}  // namespace tmop
