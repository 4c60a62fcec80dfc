// Untangling never returns more inverted cells than it reached: when the eps schedule ends worse
// than an earlier round (or than its start), the stage returns the best state it reached; and a
// failure names its counts as tmop_quality counts them and says what would help.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/quality/count_inverted.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

// An n x n quad grid of the unit square whose vertices, boundary ones included (all but the
// square's corners), moved by up to `amount` spacings: some inverted cells lean on the fixed,
// displaced boundary and cannot all be repaired, so the schedule drives eps down to its end.
Mesh tangled_boundary_grid(int n, double amount, unsigned seed) {
  Mesh m = testing_grid::grid(CellType::kQuad4, n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount / n, amount / n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      if ((i == 0 || i == n) && (j == 0 || j == n)) continue;
      for (int a = 0; a < 2; ++a) m.vertex(j * (n + 1) + i)[a] += u(rng);
    }
  return m;
}

struct GridRun {
  int before = 0, after = 0;
  int best_round_start = 0;  // fewest inverted at the start of any eps round (the input too)
  Status status;
  std::string termination;
};

GridRun untangle_grid(unsigned seed) {
  Mesh mesh = tangled_boundary_grid(10, 0.9, seed);
  GridRun r;
  r.before = static_cast<int>(count_inverted(mesh, 1));
  UntangleOptions opt;
  opt.solver.threads = 1;
  opt.improve_shape_after = false;
  // A record whose iteration repeats the previous one is iteration 0 of a new eps round: the
  // state the previous round ended in (quads: counted at the corners, the stage's points).
  r.best_round_start = r.before;
  int last_iteration = -1;
  opt.solver.progress = [&](const IterationRecord& rec) {
    if (rec.iteration == last_iteration)
      r.best_round_start = std::min(r.best_round_start, rec.inverted);
    last_iteration = rec.iteration;
  };
  RecipeResult result;
  r.status = untangle(&mesh, opt, &result);
  r.after = static_cast<int>(count_inverted(mesh, 1));
  if (!result.stages.empty()) r.termination = result.stages[0].termination;
  return r;
}

// 40 such meshes: none ends with more inverted cells than any eps round started with. Seed 25
// ends its last round with 2 inverted cells after round 39 had 1: the result has 1.
TEST(UntangleBestState, NeverEndsWorseThanARoundReached) {
  int failures = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const GridRun r = untangle_grid(seed);
    if (r.before == 0) continue;
    EXPECT_LE(r.after, r.best_round_start) << "seed " << seed << ": " << r.termination;
    EXPECT_LE(r.after, r.before) << "seed " << seed;
    if (!r.status.ok()) {
      ++failures;
      EXPECT_GT(r.after, 0) << "seed " << seed;
    }
  }
  EXPECT_GT(failures, 5);  // the property is exercised where the schedule cannot finish
  const GridRun r = untangle_grid(25);
  ASSERT_FALSE(r.status.ok());
  EXPECT_EQ(r.after, 1);
  EXPECT_NE(r.termination.find("the best state kept"), std::string::npos) << r.termination;
  EXPECT_NE(r.termination.find("the last round 2"), std::string::npos) << r.termination;
}

// The one-line failure counts the cells as tmop_quality does (the same number the tool prints
// for the result) and, when the inverted cells have nodes on the default fixed boundary, says
// that sliding it would help.
TEST(UntangleBestState, FailureCountsAgreeAndSuggestSliding) {
  int refused = 0;
  for (unsigned seed : {1u, 3u, 25u}) {
    Mesh mesh = tangled_boundary_grid(10, 0.9, seed);
    UntangleOptions opt;
    opt.solver.threads = 1;
    opt.improve_shape_after = false;
    RecipeResult result;
    const Status s = untangle(&mesh, opt, &result);
    ASSERT_FALSE(s.ok()) << seed;
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
    if (s.message().rfind("cannot untangle: ", 0) == 0) {
      // Refused before any solve: a quad inverted at a corner whose three nodes there (the
      // only ones its Jacobian sees) are all on the fixed boundary.
      EXPECT_NE(s.message().find("on the fixed boundary (try --boundary=slide)"), std::string::npos)
          << s.message();
      ++refused;
      continue;
    }
    const long long n = count_inverted(mesh, 1);
    const std::string count =
        ": " + std::to_string(n) + (n == 1 ? " cell" : " cells") + " still inverted";
    EXPECT_NE(s.message().find(count), std::string::npos) << s.message();
    EXPECT_NE(s.message().find("on the fixed boundary: try --boundary=slide"), std::string::npos)
        << s.message();
  }
  EXPECT_LT(refused, 3);  // the eps rounds' own failure line is exercised too
}

}  // namespace
}  // namespace tmop
