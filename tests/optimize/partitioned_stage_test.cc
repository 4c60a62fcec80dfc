// Partitioned stages (SolverOptions::part_size, optimize/partitioned_stage.h) against the
// one-problem solve of the same stage: the same objective to within 0.5 %, never inverted,
// fixed vertices keep their bits, and the result does not depend on the number of threads.
#include "tmop/optimize/partitioned_stage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "grid_meshes.h"
#include "tmop/mesh/topology.h"
#include "tmop/optimize/stage.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

using testing_grid::grid;
using testing_grid::perturb;

struct Case {
  CellType type;
  int n, part_size;
};

class PartitionedStage : public ::testing::TestWithParam<Case> {
 protected:
  static Mesh input(const Case& k) {
    Mesh mesh = grid(k.type, k.n);
    std::mt19937 rng(7);
    perturb(&mesh, k.n, 0.4, &rng);
    return mesh;
  }
  static RecipeResult run(Mesh* mesh, int part_size, int threads, int rings = 2) {
    ShapeOptions opt;
    opt.solver.part_size = part_size;
    opt.solver.threads = threads;
    opt.solver.sweep_rings = rings;
    RecipeResult result;
    EXPECT_TRUE(improve_shape(mesh, opt, &result).ok());
    return result;
  }
};

TEST_P(PartitionedStage, MatchesTheOneProblemSolve) {
  const Case k = GetParam();
  const Mesh start = input(k);
  Mesh whole = start, parts = start;
  const RecipeResult one = run(&whole, 0, 2);
  const RecipeResult many = run(&parts, k.part_size, 2, /*rings=*/0);
  ASSERT_FALSE(one.stages.empty());
  ASSERT_FALSE(many.stages.empty());
  const StageResult& a = one.stages.front();
  const StageResult& b = many.stages.front();
  EXPECT_EQ(a.parts, 0);
  EXPECT_GE(b.parts, 4) << b.termination;
  EXPECT_GE(b.sweeps, 1);
  EXPECT_EQ(b.inverted_after, 0);
  EXPECT_LT(b.final_objective, b.initial_objective);
  EXPECT_LE(std::abs(b.final_objective - a.final_objective), 5e-3 * a.final_objective)
      << a.final_objective << " vs " << b.final_objective;
  EXPECT_GE(b.min_quality_after, 0.95 * a.min_quality_after);
  EXPECT_EQ(measure_mesh(parts, SampleRule::kCorners).inverted, 0);
  // The boundary is fixed: its vertices keep their bits.
  const std::vector<char> boundary = boundary_vertex_mask(start);
  int moved = 0;
  for (int v = 0; v < start.num_vertices(); ++v) {
    bool same = true;
    for (int x = 0; x < start.space_dim; ++x) same &= parts.vertex(v)[x] == start.vertex(v)[x];
    if (boundary[v]) {
      EXPECT_TRUE(same) << "boundary vertex " << v << " moved";
    }
    moved += !same;
  }
  EXPECT_GT(moved, 0);
}

TEST_P(PartitionedStage, TheThreadsDoNotChangeTheResult) {
  const Case k = GetParam();
  Mesh one = input(k), two = one;
  run(&one, k.part_size, 1);
  run(&two, k.part_size, 2);
  EXPECT_EQ(one.coords, two.coords);
}

// The shape recipe's guarantees (docs/quality.md: per type, no worse worst or mean, no new
// sliver or inversion) hold when its stage is partitioned, as they do for one problem.
TEST_P(PartitionedStage, ShapeGuaranteesHoldInParts) {
  const Case k = GetParam();
  const Mesh start = input(k);
  Mesh parts = start;
  const RecipeResult r = run(&parts, k.part_size, 2);
  ASSERT_FALSE(r.stages.empty());
  EXPECT_GE(r.stages.front().parts, 4);
  const std::vector<GuaranteeViolation> broken =
      check_guarantees(guarantee_baseline(start, 1), guarantee_values(parts, 1));
  for (const GuaranteeViolation& v : broken) ADD_FAILURE() << v.message();
}

// A sliding boundary across the cuts (issue 20): boundary vertices of parts and of the cut
// phases slide on their faces of the box (to round-off: the stage's frame is not bit-exact),
// nothing inverts, and the parts reach most of the one-problem decrease. Not all of it: with a
// sliding boundary this perturbed grid's optimum is a global shear of the whole mesh, which
// parts with held halos approach slowly (tri3 40 x 40: 0.685 -> 0.0517 in 4 sweeps, 0.0037 in
// 20, one problem 0.00046; docs/partitioning.md).
TEST_P(PartitionedStage, SlidingBoundaryAcrossCuts) {
  const Case k = GetParam();
  // The Sizes cases measure the sweeps' restriction; there the gap grows (tri3 90 x 90: 86 % of
  // the one-problem decrease).
  if (k.part_size >= 2000) GTEST_SKIP() << "sliding is checked on the Types cases";
  const Mesh start = input(k);
  const auto slide = [&](Mesh* m, int part_size) {
    ShapeOptions opt;
    opt.solver.part_size = part_size;
    opt.solver.threads = 2;
    opt.slide = true;
    RecipeResult r;
    EXPECT_TRUE(improve_shape(m, opt, &r).ok());
    return r;
  };
  Mesh whole = start, parts = start;
  const RecipeResult one = slide(&whole, 0);
  const RecipeResult many = slide(&parts, k.part_size);
  ASSERT_FALSE(many.stages.empty());
  const StageResult& a = one.stages.front();
  const StageResult& b = many.stages.front();
  EXPECT_GE(b.parts, 4) << b.termination;
  EXPECT_EQ(b.inverted_after, 0);
  EXPECT_GE(b.initial_objective - b.final_objective,
            0.9 * (a.initial_objective - a.final_objective))
      << a.initial_objective << " -> " << a.final_objective << " (one problem) vs "
      << b.final_objective;
  // The grid is the unit square / cube: a boundary coordinate that was 0 or 1 stays so, and
  // some boundary vertex slid.
  const std::vector<char> boundary = boundary_vertex_mask(start);
  int slid = 0;
  for (int v = 0; v < start.num_vertices(); ++v) {
    if (!boundary[v]) continue;
    for (int x = 0; x < start.space_dim; ++x) {
      const double was = start.vertex(v)[x];
      if (was == 0 || was == 1) {
        EXPECT_NEAR(parts.vertex(v)[x], was, 1e-12) << "vertex " << v << " left its face";
      }
      slid += std::abs(parts.vertex(v)[x] - was) > 1e-9;
    }
  }
  EXPECT_GT(slid, 0);
}

INSTANTIATE_TEST_SUITE_P(Types, PartitionedStage,
                         ::testing::Values(Case{CellType::kTri3, 40, 400},
                                           Case{CellType::kQuad4, 40, 200},
                                           Case{CellType::kTet4, 9, 600},
                                           Case{CellType::kHex8, 10, 150}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(cell_info(info.param.type).name);
                         });

// Later sweeps re-solve only the vertices near what moved since (sweep_rings, the default 2),
// where that at least halves a part: less work than whole parts again, the objective within 1 %
// of the one-problem solve (docs/partitioning.md has the measured gaps), never inverted. Where
// no part is cut down (small parts), the result is bit-identical to whole parts.
TEST_P(PartitionedStage, LaterSweepsSolveOnlyNearWhatMoved) {
  const Case k = GetParam();
  Mesh whole = input(k), whole_parts = whole, near = whole;
  const RecipeResult one = run(&whole, 0, 2);
  const RecipeResult a = run(&whole_parts, k.part_size, 2, 0);
  const RecipeResult b = run(&near, k.part_size, 2, 2);
  ASSERT_FALSE(one.stages.empty());
  ASSERT_FALSE(a.stages.empty());
  ASSERT_FALSE(b.stages.empty());
  const StageResult& sa = a.stages.front();
  const StageResult& sb = b.stages.front();
  ASSERT_GE(sa.sweeps, 2) << sa.termination;  // else there is no later sweep to compare
  ASSERT_GT(sa.part_element_iterations, 0);
  EXPECT_LE(sb.part_element_iterations, sa.part_element_iterations);
  if (sb.part_element_iterations == sa.part_element_iterations) {
    EXPECT_EQ(near.coords, whole_parts.coords);
  } else {
    const double best = one.stages.front().final_objective;
    EXPECT_LE(sb.final_objective - best, 1e-2 * best)
        << best << " vs " << sb.final_objective << " (whole parts " << sa.final_objective << ")";
  }
  EXPECT_EQ(sb.inverted_after, 0);
  EXPECT_EQ(measure_mesh(near, SampleRule::kCorners).inverted, 0);
}

INSTANTIATE_TEST_SUITE_P(Sizes, PartitionedStage,
                         ::testing::Values(Case{CellType::kTri3, 90, 2000},
                                           Case{CellType::kTet4, 14, 2500}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(cell_info(info.param.type).name) + "_" +
                                  std::to_string(info.param.part_size);
                         });

TEST(PartitionedStage, OnlyShapeStagesOfLargeEnoughMeshes) {
  const Mesh mesh = grid(CellType::kTet4, 4);  // 384 tets
  StageSpec spec;
  spec.solver.part_size = 100;
  EXPECT_TRUE(use_partitions(mesh, spec));
  spec.solver.part_size = 200;
  EXPECT_FALSE(use_partitions(mesh, spec));  // fewer than 2 parts' worth
  spec.solver.part_size = 0;
  EXPECT_FALSE(use_partitions(mesh, spec));
  spec.solver.part_size = 100;
  spec.untangle = true;
  EXPECT_FALSE(use_partitions(mesh, spec));
}

TEST(PartitionedStage, PartsByCount) {
  const Mesh mesh = grid(CellType::kTet4, 4);  // 384 tets
  StageSpec spec;
  spec.solver.part_size = 100000;  // the default: far too few elements
  EXPECT_EQ(stage_num_parts(mesh, spec), 1);
  spec.solver.partitions = 3;  // a count overrides the size
  EXPECT_EQ(stage_num_parts(mesh, spec), 3);
  spec.solver.partitions = 1;
  EXPECT_EQ(stage_num_parts(mesh, spec), 1);
  spec.solver.partitions = 100;  // at least 64 elements per part: 384 / 64 = 6
  EXPECT_EQ(stage_num_parts(mesh, spec), 6);
  spec.solver.partitions = 0;
  spec.solver.part_size = 100;
  EXPECT_EQ(stage_num_parts(mesh, spec), 4);  // ceil(384 / 100)
  spec.solver.partitions = 3;
  spec.untangle = true;
  EXPECT_EQ(stage_num_parts(mesh, spec), 1);
}

}  // namespace
}  // namespace tmop
