// Hopeless untangling fails early: Gmsh's t16 at -order 2, coarsened (-clscale 3: 1,934 tet10,
// 32 of them inverted where the curved boundary folds them), with a sliding boundary. The eps
// rounds only fold neighbours over (318 inverted after one round, 273 after two) and repair
// none of the 32 cells: the schedule stops after UntangleOptions::spread_rounds (2) such rounds
// with the one-line failure, instead of running on to its patience (8 rounds without a better
// state).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "tests/recipes/recipe_test_meshes.h"
#include "tmop/quality/count_inverted.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

TEST(UntangleSpread, CurvedBoundaryFoldsFailAfterTwoSpreadingRounds) {
  const std::string geo = "/usr/share/doc/gmsh-doc/doc/gmsh/tutorial/t16.geo";
  if (!testing_recipes::have_gmsh() || testing_recipes::exit_code("test -f " + geo) != 0)
    GTEST_SKIP() << "gmsh or its tutorials not installed";
  char dir[] = "/tmp/tmop_untangle_spread_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string msh = std::string(dir) + "/t16.msh";
  ASSERT_EQ(testing_recipes::exit_code("cd " + std::string(dir) + " && gmsh -3 -nt 1 -v 0 " + geo +
                                       " -order 2 -clscale 3 -format msh41 -o " + msh +
                                       " > /dev/null 2>&1"),
            0);
  Mesh mesh;
  ASSERT_TRUE(read_mesh(msh, &mesh).ok());
  testing_recipes::exit_code(std::string("rm -rf ") + dir);
  mesh.remove_lower_dimensional_cells();
  const std::int64_t inverted = count_inverted(mesh, 1);
  ASSERT_GT(inverted, 10);
  UntangleOptions opt;
  opt.solver.threads = 1;
  opt.slide = true;
  RecipeResult result;
  const Status s = untangle(&mesh, opt, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().find('\n'), std::string::npos);
  EXPECT_EQ(s.message().rfind("could not untangle in ", 0), 0u) << s.message();
  ASSERT_FALSE(result.stages.empty());
  // Round 0 spreads, round 1 spreads again: stop (the patience stop came after 8 rounds).
  EXPECT_LE(result.stages[0].solves, 3) << result.stages[0].termination;
  EXPECT_NE(result.stages[0].termination.find("the tangle spread"), std::string::npos)
      << result.stages[0].termination;
  EXPECT_LE(count_inverted(mesh, 1), inverted);  // the best state (the start) is kept
}

}  // namespace
}  // namespace tmop
