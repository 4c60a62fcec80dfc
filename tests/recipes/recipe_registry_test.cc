// The recipe registry (recipes/recipe.h): every recipe by name, options a recipe does not use
// refused, one progress callback for every stage that names its stage and can cancel, fixed
// nodes kept bit for bit.
#include <gtest/gtest.h>

#include <atomic>
#include <random>
#include <set>
#include <string>
#include <thread>

#include "tests/optimize/grid_meshes.h"
#include "tmop/mesh/topology.h"
#include "tmop/recipes/recipe.h"

namespace tmop {
namespace {

Mesh jittered_grid(int n, unsigned seed) {
  Mesh m = testing_grid::grid(CellType::kTri3, n);
  std::mt19937 rng(seed);
  testing_grid::perturb(&m, n, 0.3, &rng);
  return m;
}

// One interior vertex pushed 1.5 cells to the right: several triangles inverted.
Mesh tangled_grid(int n) {
  Mesh m = testing_grid::grid(CellType::kTri3, n);
  const int v = (n / 2) * (n + 1) + n / 2;
  m.vertex(v)[0] += 1.5 / n;
  return m;
}

TEST(RecipeRegistry, KnowsEveryRecipeByName) {
  const char* names[] = {"auto",       "shape",    "untangle", "surface", "equal_edge",
                         "size_adapt", "preserve", "laplace",  "sliver",  "high_order"};
  for (const char* n : names) EXPECT_NE(find_recipe(n), nullptr) << n;
  EXPECT_EQ(recipes().size(), 10u);
  EXPECT_EQ(find_recipe("nope"), nullptr);
  EXPECT_EQ(recipe_names().rfind("auto, shape, untangle", 0), 0u) << recipe_names();
  Mesh m = jittered_grid(4, 1);
  RecipeResult r;
  const Status s = run_recipe("nope", &m, RecipeOptions(), &r);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("known: auto, shape"), std::string::npos) << s.message();
}

TEST(RecipeRegistry, RefusesOptionsARecipeDoesNotUse) {
  const Mesh input = jittered_grid(4, 2);
  const struct {
    const char* recipe;
    void (*set)(RecipeOptions*);
    const char* message;
  } cases[] = {
      {"laplace", [](RecipeOptions* o) { o->metric = "shape_2d"; },
       "option metric is not used by recipe laplace"},
      {"laplace", [](RecipeOptions* o) { o->solver.max_iterations = 5; },
       "option max_iterations is not used by recipe laplace"},
      {"sliver", [](RecipeOptions* o) { o->power = 3; },
       "option power is not used by recipe sliver"},
      {"equal_edge", [](RecipeOptions* o) { o->power = 3; },
       "option power is not used by recipe equal_edge"},
      {"untangle", [](RecipeOptions* o) { o->target.type = TargetType::kIdealLocalSize; },
       "option target is not used by recipe untangle"},
      {"preserve", [](RecipeOptions* o) { o->boundary = BoundaryMode::kSlide; },
       "option boundary=slide is not used by recipe preserve"},
      {"shape", [](RecipeOptions* o) { o->max_sweeps = 3; },
       "option max_sweeps is not used by recipe shape"},
  };
  for (const auto& c : cases) {
    RecipeOptions o;
    c.set(&o);
    Mesh m = input;
    RecipeResult r;
    const Status s = run_recipe(c.recipe, &m, o, &r);
    EXPECT_EQ(s.message(), c.message) << c.recipe;
    EXPECT_EQ(m.coords, input.coords) << c.recipe;
  }
  // Defaults are never "set": every recipe takes RecipeOptions() as it is (laplace here).
  EXPECT_TRUE(unused_options("laplace", RecipeOptions()).empty());
}

// --power reaches preserve: p = 1 and p = 4 give different meshes, p = 2 (its default) the
// default's.
TEST(RecipeRegistry, PowerReachesPreserve) {
  const int n = 6;
  const Mesh input = testing_grid::grid(CellType::kTri3, n);
  Mesh moved = input;
  for (int v = 0; v < moved.num_vertices(); ++v)
    if (moved.vertex(v)[0] > 1 - 1e-9) moved.vertex(v)[0] += 0.3 * moved.vertex(v)[1];
  auto run = [&](double power) {
    RecipeOptions o;
    o.moved = &moved;
    o.power = power;
    o.solver.threads = 1;
    Mesh m = input;
    RecipeResult r;
    EXPECT_TRUE(run_recipe("preserve", &m, o, &r).ok());
    return m.coords;
  };
  const std::vector<double> p0 = run(0), p1 = run(1), p2 = run(2), p4 = run(4);
  EXPECT_EQ(p0, p2);
  EXPECT_NE(p1, p2);
  EXPECT_NE(p4, p2);
}

// One callback set once sees the untangling and the shape stage of auto, each record named.
TEST(RecipeRegistry, OneProgressCallbackSeesEveryStageByName) {
  Mesh m = tangled_grid(6);
  ASSERT_GT(measure_mesh(m, SampleRule::kDefault).inverted, 0);
  RecipeOptions o;
  o.solver.threads = 1;
  std::vector<std::string> stages;
  o.solver.progress = [&](const ProgressRecord& r) {
    if (stages.empty() || stages.back() != r.stage) stages.push_back(r.stage);
  };
  RecipeResult r;
  ASSERT_TRUE(run_recipe("auto", &m, o, &r).ok());
  ASSERT_GE(stages.size(), 2u);
  EXPECT_EQ(stages[0], "untangle");
  EXPECT_EQ(stages[1], "shape");
  EXPECT_EQ(measure_mesh(m, SampleRule::kDefault).inverted, 0);
}

// A callback returning false stops the running stage at that iteration: Cancelled, the mesh moved
// part of the way and valid, no record after the cancelling one.
TEST(RecipeRegistry, ProgressCallbackCancels) {
  const Mesh input = jittered_grid(12, 3);
  for (const char* recipe : {"shape", "auto", "equal_edge", "laplace"}) {
    Mesh m = input;
    RecipeOptions o;
    if (std::string(recipe) != "laplace") o.solver.threads = 1;  // laplace has no threads
    int calls = 0, after_cancel = 0;
    // Cancels at the second record: Ceres stages after one step, laplace after two sweeps.
    o.solver.progress = [&](const ProgressRecord&) {
      if (calls >= 2) ++after_cancel;
      return ++calls < 2;
    };
    RecipeResult r;
    const Status s = run_recipe(recipe, &m, o, &r);
    EXPECT_TRUE(s.cancelled()) << recipe << ": " << s.message();
    EXPECT_FALSE(s.ok()) << recipe;
    EXPECT_EQ(calls, 2) << recipe;
    EXPECT_EQ(after_cancel, 0) << recipe;
    EXPECT_EQ(measure_mesh(m, SampleRule::kDefault).inverted, 0) << recipe;
    EXPECT_NE(m.coords, input.coords) << recipe << ": one iteration was taken";
  }
  // A cancel flag raised before the run: stopped at iteration 0, the mesh unchanged.
  Mesh m = input;
  std::atomic<bool> cancel{true};
  RecipeOptions o;
  o.cancel = &cancel;
  RecipeResult r;
  EXPECT_TRUE(run_recipe("shape", &m, o, &r).cancelled());
  EXPECT_EQ(m.coords, input.coords);
}

// Every recipe in the registry: the cancel flag raised from the progress callback at the first
// record (as a signal handler raises it) stops the run there: Cancelled, no further record of any
// stage or round, the mesh without an inverted cell (untangle: no more than its input's).
TEST(RecipeRegistry, EveryRecipeStopsAtTheCancelFlag) {
  std::string names = recipe_names() + ", ";
  int recipes = 0;
  for (std::size_t at; (at = names.find(", ")) != std::string::npos; names.erase(0, at + 2)) {
    const std::string recipe = names.substr(0, at);
    const bool untangle = recipe == "untangle";
    const Mesh input = untangle ? tangled_grid(12) : jittered_grid(12, 3);
    const int inverted_before = measure_mesh(input, SampleRule::kDefault).inverted;
    Mesh m = input;
    RecipeOptions o;
    if (recipe != "laplace") o.solver.threads = 1;
    std::atomic<bool> cancel{false};
    o.cancel = &cancel;
    int calls = 0, after_cancel = 0;
    o.solver.progress = [&](const ProgressRecord&) {
      if (cancel.load()) ++after_cancel;
      ++calls;
      cancel.store(true);
    };
    RecipeResult r;
    const Status s = run_recipe(recipe, &m, o, &r);
    if (!s.cancelled() && !s.ok() && calls == 0) continue;  // needs inputs a grid lacks
    ++recipes;
    EXPECT_TRUE(s.cancelled()) << recipe << ": " << s.message();
    EXPECT_EQ(calls, 1) << recipe;
    EXPECT_EQ(after_cancel, 0) << recipe;
    EXPECT_LE(measure_mesh(m, SampleRule::kDefault).inverted, inverted_before) << recipe;
  }
  EXPECT_GE(recipes, 5);
}

// A partitioned shape stage: cancelled at its first record (the end of its first phase) no other
// phase starts; cancelled from another thread mid-phase, the workers start no further part and
// the run ends Cancelled, the mesh valid.
TEST(RecipeRegistry, PartitionedStageStopsAtTheCancelFlag) {
  const Mesh input = jittered_grid(60, 7);  // 7,200 triangles
  for (bool from_thread : {false, true}) {
    Mesh m = input;
    RecipeOptions o;
    o.solver.threads = 2;
    o.solver.partitions = 16;
    std::atomic<bool> cancel{false};
    o.cancel = &cancel;
    int calls = 0, after_cancel = 0;
    o.solver.progress = [&](const ProgressRecord&) {
      if (cancel.load()) ++after_cancel;
      ++calls;
      if (!from_thread) cancel.store(true);
    };
    std::thread raiser;
    if (from_thread) raiser = std::thread([&] { cancel.store(true); });
    RecipeResult r;
    const Status s = run_recipe("shape", &m, o, &r);
    if (raiser.joinable()) raiser.join();
    EXPECT_TRUE(s.cancelled()) << s.message();
    EXPECT_LE(calls, 1) << from_thread;
    EXPECT_EQ(after_cancel, 0);
    EXPECT_EQ(measure_mesh(m, SampleRule::kDefault).inverted, 0);
    if (from_thread) continue;
    ASSERT_FALSE(r.stages.empty());
    EXPECT_GT(r.stages[0].parts, 1) << "the stage was not partitioned";
  }
}

// The cancel flag is watched, not only read at the next record: raised before the run (as a
// signal during a stage's set-up does), the partitioned stage starts no phase and no part, so no
// vertex moves. (Read only at records, phase 1 would run every part first: parts report none.)
TEST(RecipeRegistry, CancelRaisedBeforeTheFirstRecordMovesNothing) {
  const Mesh input = jittered_grid(60, 7);
  Mesh m = input;
  RecipeOptions o;
  o.solver.threads = 2;
  o.solver.partitions = 16;
  std::atomic<bool> cancel{true};
  o.cancel = &cancel;
  RecipeResult r;
  const Status s = run_recipe("shape", &m, o, &r);
  EXPECT_TRUE(s.cancelled()) << s.message();
  EXPECT_EQ(m.coords, input.coords);
}

// Fixed nodes keep their exact bits in every recipe that moves interior nodes; the boundary
// stays fixed too (the fixed flags add to the boundary mode).
TEST(RecipeRegistry, FixedNodesKeepTheirBits) {
  const Mesh input = jittered_grid(8, 4);
  const std::vector<char> boundary = boundary_vertex_mask(input);
  std::vector<char> fixed(input.num_vertices(), 0);
  for (int v = 0; v < input.num_vertices(); v += 3) fixed[v] = !boundary[v];
  for (const char* recipe : {"auto", "shape", "untangle", "equal_edge", "size_adapt", "laplace"}) {
    RecipeOptions o;
    o.fixed = fixed;
    if (std::string(recipe) != "laplace") o.solver.threads = 1;
    Mesh m = input;
    RecipeResult r;
    ASSERT_TRUE(run_recipe(recipe, &m, o, &r).ok()) << recipe;
    int moved_free = 0;
    for (int v = 0; v < m.num_vertices(); ++v) {
      const bool same =
          m.vertex(v)[0] == input.vertex(v)[0] && m.vertex(v)[1] == input.vertex(v)[1];
      if (fixed[v] || boundary[v]) {
        EXPECT_TRUE(same) << recipe << " vertex " << v;
      } else {
        moved_free += !same;
      }
    }
    if (std::string(recipe) != "untangle") {
      EXPECT_GT(moved_free, 0) << recipe;
    }
  }
  RecipeOptions o;
  o.fixed.assign(3, 1);
  Mesh m = input;
  RecipeResult r;
  EXPECT_NE(run_recipe("shape", &m, o, &r).message().find("3 flags for a mesh of"),
            std::string::npos);
}

TEST(RecipeRegistry, SettingsResolveTheDefaults) {
  const Mesh m = jittered_grid(4, 5);
  const std::string shape = recipe_settings_json("shape", m, RecipeOptions());
  EXPECT_NE(shape.find("\"metric\": \"shape_barrier_2d\""), std::string::npos) << shape;
  EXPECT_NE(shape.find("\"power\": 2"), std::string::npos) << shape;
  EXPECT_NE(shape.find("\"boundary\": \"fixed\""), std::string::npos) << shape;
  const std::string sliver = recipe_settings_json("sliver", m, RecipeOptions());
  EXPECT_NE(sliver.find("\"boundary\": \"slide\""), std::string::npos) << sliver;
}

}  // namespace
}  // namespace tmop
