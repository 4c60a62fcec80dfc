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
  Mesh mesh;
  const int got =
      testing_recipes::gmsh_doc_mesh("tutorial", "t16", "-3 -order 2 -clscale 3", &mesh);
  if (got == 1) GTEST_SKIP() << "gmsh or its tutorials (gmsh-doc) not installed";
  ASSERT_EQ(got, 0);
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
