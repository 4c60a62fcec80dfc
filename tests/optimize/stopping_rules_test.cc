// The stage's stopping rules (solver_options.h), each isolated so that it alone can end the
// solve and checked against what it claims; the progress records (IterationRecord) against the
// stage's own objective; the recipe's JSON record against its documented keys.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "grid_meshes.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {
namespace {

using testing_grid::grid;
using testing_grid::perturb;

Mesh perturbed_grid(CellType type, int n, unsigned seed) {
  std::mt19937 rng(seed);
  Mesh mesh = grid(type, n);
  perturb(&mesh, n, 0.45, &rng);
  return mesh;
}

// Barrier shape improvement, plain mean, every rule off: a test turns on the one it checks.
StageSpec rules_off_stage(int dim) {
  StageSpec spec;
  spec.name = "rules";
  TermSpec term;
  term.metric = std::shared_ptr<const Metric>(make_metric("shape_barrier", dim).release());
  term.target.type = TargetType::kIdealEqualSize;
  spec.terms.push_back(term);
  spec.solver.threads = 1;
  spec.solver.max_iterations = 500;
  spec.solver.function_tolerance = 0;
  spec.solver.objective_tolerance = 0;
  spec.solver.gradient_tolerance = 0;
  spec.solver.movement_tolerance = 0;
  return spec;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class StoppingRules : public ::testing::TestWithParam<CellType> {
 protected:
  StageResult run(const StageSpec& spec) {
    Mesh mesh = perturbed_grid(GetParam(), cell_dim(GetParam()) == 2 ? 8 : 4, 3);
    StageResult result;
    Status s = optimize_stage(&mesh, spec, &result);
    EXPECT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(result.inverted_after, 0);
    return result;
  }
  int dim() const { return cell_dim(GetParam()); }
};

TEST_P(StoppingRules, ObjectiveDecreasePerElement) {
  StageSpec spec = rules_off_stage(dim());
  spec.solver.objective_tolerance = 1e-6;
  const StageResult r = run(spec);
  EXPECT_EQ(r.termination, "mean metric decrease per element below objective_tolerance");
  // The last two successful steps each lowered the solver's objective per element by less.
  int small = 0;
  for (std::size_t k = r.history.size() - 1; k > 0 && small < 2; --k) {
    const double decrease = r.history[k - 1].solver_objective - r.history[k].solver_objective;
    if (decrease == 0) continue;  // a rejected step leaves the objective where it was
    EXPECT_LT(decrease, 1e-6) << "iteration " << k;
    ++small;
  }
  EXPECT_EQ(small, 2);
  EXPECT_GT(r.iterations, 2);
}

TEST_P(StoppingRules, VertexMovementRelativeToLocalEdgeLength) {
  StageSpec spec = rules_off_stage(dim());
  spec.solver.movement_tolerance = 1e-4;
  const StageResult r = run(spec);
  EXPECT_EQ(r.termination, "vertex movement below tolerance (relative to local edge length)");
  EXPECT_GT(r.iterations, 3);
}

TEST_P(StoppingRules, GradientRelativeToTheInitialOne) {
  StageSpec spec = rules_off_stage(dim());
  spec.solver.gradient_tolerance = 1e-4;
  const StageResult r = run(spec);
  EXPECT_EQ(r.termination, "gradient below tolerance (relative to the initial gradient)");
}

TEST_P(StoppingRules, RelativeObjectiveDecrease) {
  // The quad grid's optimum is exact (every quad a square, objective 0): its relative decreases
  // stay near 1 until Ceres's parameter tolerance ends the solve at the minimiser.
  if (GetParam() == CellType::kQuad4) GTEST_SKIP() << "objective 0 at the optimum";
  StageSpec spec = rules_off_stage(dim());
  spec.solver.function_tolerance = 1e-4;
  const StageResult r = run(spec);
  // Ceres judges the step it computed last, which it then does not take or record.
  EXPECT_TRUE(contains(r.termination, "Function tolerance reached")) << r.termination;
  EXPECT_GT(r.iterations, 2);
}

TEST_P(StoppingRules, IterationAndTimeCaps) {
  StageSpec spec = rules_off_stage(dim());
  spec.solver.max_iterations = 2;
  StageResult r = run(spec);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_TRUE(contains(r.termination, "Maximum number of iterations")) << r.termination;
  spec = rules_off_stage(dim());
  spec.solver.max_seconds = 1e-9;
  r = run(spec);
  EXPECT_TRUE(contains(r.termination, "Maximum solver time reached")) << r.termination;
  EXPECT_LE(r.iterations, 1);
}

INSTANTIATE_TEST_SUITE_P(Types, StoppingRules,
                         ::testing::Values(CellType::kTri3, CellType::kQuad4, CellType::kTet4),
                         [](const ::testing::TestParamInfo<CellType>& info) {
                           return std::string(cell_info(info.param).name);
                         });

// With a progress callback every iteration is measured: its objective is the stage's objective
// (iteration 0 is initial_objective, the last final_objective), its worst quality and inverted
// count those of the stage's before / after measures. Without one only the solver's objective is
// recorded; under a power that is the power objective, not the mean metric.
TEST(Progress, RecordsTheStageObjectiveAtEveryIteration) {
  for (double power : {1.0, 2.0}) {
    Mesh mesh = perturbed_grid(CellType::kTet4, 4, 7);
    const Mesh input = mesh;
    StageSpec spec = rules_off_stage(3);
    spec.power = power;
    spec.solver.function_tolerance = 1e-6;
    int calls = 0;
    spec.solver.progress = [&](const IterationRecord&) { ++calls; };
    StageResult r;
    ASSERT_TRUE(optimize_stage(&mesh, spec, &r).ok());
    ASSERT_GE(r.history.size(), 3u);
    EXPECT_EQ(calls, static_cast<int>(r.history.size()));
    EXPECT_EQ(static_cast<int>(r.history.size()), r.iterations + 1);
    const double tol = 1e-12 * r.initial_objective;
    EXPECT_NEAR(r.history.front().objective, r.initial_objective, tol);
    EXPECT_NEAR(r.history.back().objective, r.final_objective, tol);
    EXPECT_DOUBLE_EQ(r.history.front().min_quality, r.min_quality_before);
    EXPECT_DOUBLE_EQ(r.history.back().min_quality, r.min_quality_after);
    for (const IterationRecord& rec : r.history) {
      EXPECT_EQ(rec.inverted, 0);
      EXPECT_GT(rec.solver_objective, 0);
    }
    if (power > 1) {  // the power objective weighs the worst points up
      EXPECT_GT(r.history.front().solver_objective, 1.5 * r.history.front().objective);
    }

    // The same stage without reporting: identical iterates, only the solver's objective.
    Mesh again = input;
    spec.solver.progress = nullptr;
    StageResult quiet;
    ASSERT_TRUE(optimize_stage(&again, spec, &quiet).ok());
    ASSERT_EQ(quiet.history.size(), r.history.size());
    for (std::size_t k = 0; k < r.history.size(); ++k) {
      EXPECT_EQ(quiet.history[k].solver_objective, r.history[k].solver_objective);
      EXPECT_TRUE(std::isnan(quiet.history[k].objective));
      EXPECT_TRUE(std::isnan(quiet.history[k].min_quality));
      EXPECT_EQ(quiet.history[k].inverted, -1);
    }
    EXPECT_EQ(again.coords, mesh.coords);
  }
}

TEST(Progress, VerbosePrintsOneLinePerIteration) {
  Mesh mesh = perturbed_grid(CellType::kTri3, 6, 2);
  StageSpec spec = rules_off_stage(2);
  spec.solver.function_tolerance = 1e-6;
  spec.solver.verbose = true;
  StageResult r;
  ::testing::internal::CaptureStderr();
  ASSERT_TRUE(optimize_stage(&mesh, spec, &r).ok());
  const std::string err = ::testing::internal::GetCapturedStderr();
  int lines = 0;
  for (std::size_t p = err.find("[rules] iter"); p != std::string::npos;
       p = err.find("[rules] iter", p + 1))
    ++lines;
  EXPECT_EQ(lines, r.iterations + 1) << err;
  for (const char* field : {"objective", "(solver", "min quality", "inverted", " s\n"})
    EXPECT_TRUE(contains(err, field)) << field << " in " << err;
}

// recipe_json (tmop_optimize --report's "run") holds every key recipe_result.h documents.
TEST(RecipeJson, HoldsEveryDocumentedKey) {
  Mesh mesh = perturbed_grid(CellType::kTri3, 6, 4);
  ShapeOptions opt;
  opt.solver.verbose = false;
  RecipeResult result;
  ASSERT_TRUE(improve_shape(&mesh, opt, &result).ok());
  const std::string json = recipe_json(result);
  for (const char* key : {"recipe",
                          "seconds",
                          "before",
                          "after",
                          "certified",
                          "uncertified",
                          "layer_cells",
                          "held_vertices",
                          "guard_held_cells",
                          "stages",
                          "name",
                          "linear_solver",
                          "elements",
                          "sample_points",
                          "free_vertices",
                          "initial_objective",
                          "final_objective",
                          "iterations",
                          "termination",
                          "inverted_before",
                          "inverted_after",
                          "min_quality_before",
                          "min_quality_after",
                          "history",
                          "iteration",
                          "objective",
                          "solver_objective",
                          "min_quality",
                          "inverted"})
    EXPECT_TRUE(contains(json, std::string("\"") + key + "\": ")) << key << " in " << json;
  EXPECT_FALSE(contains(json, "nan")) << json;  // JSON has no NaN: unmeasured values are null
  EXPECT_TRUE(contains(json, "\"objective\": null")) << json;
}

}  // namespace
}  // namespace tmop
