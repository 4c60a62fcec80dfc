// A coarse tri6 mesh of a gear-like curve made by gmsh with its mid-edge nodes placed on the
// curve (no high-order optimisation): the curved boundary folds some elements. Untangling with
// the boundary fixed (so every boundary node stays on the curve) must leave every element
// certified valid everywhere by the Bernstein bound of det J.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

bool have_gmsh() { return std::system("gmsh --version > /dev/null 2>&1") == 0; }

std::string make_gear(const std::string& dir) {
  const int n = 60;
  std::ofstream geo(dir + "/gear.geo");
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n, r = 1 + 0.2 * std::sin(10 * t);
    char line[160];
    std::snprintf(line, sizeof line, "Point(%d) = {%.17g, %.17g, 0};\n", i + 1, r * std::cos(t),
                  r * std::sin(t));
    geo << line;
  }
  geo << "Spline(1) = {";
  for (int i = 0; i < n; ++i) geo << i + 1 << ",";
  geo << "1};\nCurve Loop(1) = {1};\nPlane Surface(1) = {1};\nPhysical Surface(1) = {1};\n"
         "Mesh.CharacteristicLengthMax = 0.6;\nMesh.ElementOrder = 2;\n"
         "Mesh.HighOrderOptimize = 0;\nMesh.SecondOrderLinear = 0;\n";
  geo.close();
  const std::string msh = dir + "/gear.msh";
  const std::string cmd =
      "gmsh -2 " + dir + "/gear.geo -format msh22 -o " + msh + " > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0 ? msh : "";
}

TEST(HighOrderUntangle, GearTri6IsCertifiedValidWithBoundaryOnTheCurve) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  char dir[] = "/tmp/tmop_gear_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string path = make_gear(dir);
  ASSERT_FALSE(path.empty());
  Mesh mesh;
  ASSERT_TRUE(read_mesh(path, &mesh).ok());
  ASSERT_EQ(mesh.dim(), 2);
  QualityReport before = compute_quality(mesh);
  ASSERT_GT(before.inverted_cells, 0) << "the fixture should start tangled";
  const Mesh original = mesh;
  const std::vector<char> boundary = boundary_vertex_mask(mesh);

  UntangleOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  QualityReport after = compute_quality(mesh);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_EQ(result.uncertified, 0);
  EXPECT_EQ(result.certified, mesh.num_elements());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!boundary[v]) continue;
    for (int a = 0; a < mesh.space_dim; ++a) {
      EXPECT_EQ(mesh.vertex(v)[a], original.vertex(v)[a]) << "boundary node " << v;
    }
  }
  std::printf("gear tri6: %d of %d inverted -> %d; certified %d of %d; worst quality %.3f\n",
              static_cast<int>(before.inverted_cells), mesh.num_elements(),
              static_cast<int>(after.inverted_cells), result.certified, mesh.num_elements(),
              result.after.min_quality);
  std::system(("rm -rf " + std::string(dir)).c_str());
}

}  // namespace
}  // namespace tmop
