// tmop/recipes/recipe.h
// The recipe registry: every canonical problem by name, over one common set of options, so a
// C++ pipeline runs exactly what `tmop_optimize --recipe=NAME` runs.
//
//   auto        untangle if anything is inverted, then improve shape (quadratic cells: and
//               certify with the Bernstein bound)
//   shape       shape improvement with a barrier metric (the input must be valid)
//   untangle    untangle only
//   surface     shape improvement of a surface mesh on its geometry (boundary always slides)
//   equal_edge  equal edge lengths keeping shapes (equal_edge.h)
//   size_adapt  shapes at the local size or a size field (size_adapt.h)
//   preserve    follow a moved boundary (preserve.h; RecipeOptions::moved)
//   laplace     smart Laplacian baseline (laplace.h)
//   sliver      remove slivers, keep the boundary layer (sliver.h; slides by default)
//   high_order  the same as auto, named for quadratic meshes
//
// Each recipe declares the options it honours (RecipeInfo::honours). An option set to anything
// but its default that the recipe does not honour is refused: run_recipe fails with
// "option metric is not used by recipe laplace" rather than ignoring it.
//
// Inputs: the mesh (moved in place, in tmop's orientation convention), RecipeOptions.
// Output: *result (stages, measures before / after). Failure: a one-line Status (bad options,
// an inverted input for a barrier recipe, a recipe's own failure); Status::Cancelled when the
// progress callback returned false or options.cancel was raised: no further solve, round, sweep
// or part starts, and the mesh is valid: as the stopped solve left it (barrier stages never
// invert; the guard's guarantees are not checked), untangling keeps its best state and never ends
// with more inverted cells than the input, quadratic_shape gives back the input when its corner
// mesh's solve was cancelled.
#ifndef TMOP_RECIPES_RECIPE_H_
#define TMOP_RECIPES_RECIPE_H_

#include <atomic>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/mesh.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

// The options of RecipeOptions a recipe may or may not honour.
enum class RecipeOption {
  kMetric,             // metric
  kTarget,             // target (any TargetSpec but the default and a reference)
  kReference,          // target.type == kReference (untangle toward a mesh)
  kPower,              // power
  kSampleRule,         // rule
  kSlide,              // boundary == kSlide
  kGeometry,           // geometry.geometry (a user geometry string or file)
  kFixed,              // fixed
  kGuarantee,          // guarantee != kAll
  kSolverMethod,       // solver.method, solver.linear_solver
  kMaxIterations,      // solver.max_iterations
  kMaxSeconds,         // solver.max_seconds
  kFunctionTolerance,  // solver.function_tolerance
  kThreads,            // solver.threads
  kMoved,              // moved
  kSizeField,          // size_field
  kShapeGuardWeight,   // shape_guard_weight
  kLayerEdgeRatio,     // layer_edge_ratio
  kMaxSweeps,          // max_sweeps
};

// The option's command-line spelling without "--" ("metric", "boundary=slide", "fixed_nodes").
const char* recipe_option_flag(RecipeOption option);

enum class BoundaryMode {
  kDefault,  // the recipe's: slide for surface and sliver, fixed otherwise
  kFixed,    // boundary vertices fixed
  kSlide,    // boundary vertices slide on their curves and surfaces; corners stay
};

// What the result must keep against the input (quality/guarantees.h; docs/quality.md).
enum class GuaranteeMode {
  kAll,    // no type's or region's worst element worse, no type mean lower, no new slivers or
           // inverted cells (as far as the recipe promises: sliver and equal_edge the worst)
  kWorst,  // the same without the means
  kOff,    // nothing guarded
};
bool guarantee_mode_from_name(const std::string& name, GuaranteeMode* mode);
const char* guarantee_mode_name(GuaranteeMode mode);

struct RecipeOptions {
  // Metric name or combination (metric_names(), make_metric); "" = the recipe's default.
  std::string metric;
  // Targets (target.h); the default (ideal shape, equal size) is what the recipes use unless
  // told. kReference needs target.reference (not owned).
  TargetSpec target;
  // Power order p >= 1 of the objective (StageSpec::power); 0 = the recipe's default (shape,
  // auto, surface, high_order, preserve: 2; size_adapt: 1).
  double power = 0;
  SampleRule rule = SampleRule::kDefault;
  BoundaryMode boundary = BoundaryMode::kDefault;
  // Geometry to slide on and the feature angle (geometry.slide is set from `boundary`).
  BoundaryOptions geometry;
  // Per-vertex flags (1 = fixed), num_vertices() entries, or empty. Added to what the boundary
  // mode fixes (the whole boundary, or the corners when sliding); fixed vertices keep their
  // coordinates bit for bit (recipe preserve: they take their positions in `moved`).
  std::vector<char> fixed;
  GuaranteeMode guarantee = GuaranteeMode::kAll;
  // Solver settings of every stage (threads, iterations, tolerances, verbose) and the progress
  // callback, which sees every stage of the recipe and may cancel (solver_options.h).
  SolverOptions solver;
  // Raised by another thread: the run stops at the next iteration, as a cancelling callback
  // does. Not owned; may be null. Like a progress callback it makes every iteration measure the
  // mesh (objective, worst quality, inverted count: a pass over the mesh per iteration).
  const std::atomic<bool>* cancel = nullptr;
  // guarantee_baseline of the mesh run_recipe is given, when the caller has it (tmop_optimize
  // computes it for its own check): the shape guard of recipes shape and auto (on an input that
  // needs no untangling) takes it instead of computing it again. Not owned; may be null.
  const GuaranteeBaseline* input_baseline = nullptr;

  // Recipe-specific (refused by the others when set):
  const Mesh* moved = nullptr;    // preserve: the mesh with its boundary moved (not owned)
  std::string size_field;         // size_adapt: point-data array of target edge lengths
  double shape_guard_weight = 1;  // equal_edge: weight of the shape guard term
  double layer_edge_ratio = 3;    // sliver: boundary-layer edge ratio (0: nothing held)
  int max_sweeps = 100;           // laplace: maximum Gauss-Seidel sweeps
};

struct RecipeInfo {
  const char* name;
  const char* summary;  // one line
  std::vector<RecipeOption> honours;
  bool slides_by_default;
  bool needs_valid_input;  // a barrier recipe: refuses an inverted input
  bool keeps_guarantees;   // its result is checked against quality/guarantees.h
  bool keeps_means;        // ... including the type means (under GuaranteeMode::kAll)
};

// Every recipe in the order of the table above.
const std::vector<RecipeInfo>& recipes();
// nullptr when unknown.
const RecipeInfo* find_recipe(const std::string& name);
// "auto, shape, untangle, ..." for messages and --help.
std::string recipe_names();

// The options set to other than their defaults that the recipe does not honour (empty when
// all are fine, or when the recipe is unknown).
std::vector<RecipeOption> unused_options(const std::string& name, const RecipeOptions& options);

// Whether the recipe slides the boundary under these options.
bool recipe_slides(const std::string& name, const RecipeOptions& options);

// What the recipe's result must keep under options.guarantee (tools check it again after the
// run, independently of the recipe's guard). false: nothing to check.
bool recipe_guarantees(const std::string& name, const RecipeOptions& options,
                       GuaranteeOptions* guarantees);

// The checks run_recipe makes of the recipe, the options and the mesh before any work (an
// unknown recipe, an unused option, a mesh of the wrong kind, a malformed or unused geometry,
// fixed flags of the wrong count, preserve without `moved`). Not the inverted-input check.
Status check_recipe(const std::string& name, const Mesh& mesh, const RecipeOptions& options);

// A recipe that needs a valid input (RecipeInfo::needs_valid_input) refuses an inverted one:
// *inverted is the count (measure_mesh at `rule`'s validity points), 0 for the other recipes.
Status check_valid_input(const std::string& name, const Mesh& mesh, SampleRule rule, int* inverted);

// The settings as the recipe uses them, defaults resolved (metric name, power, boundary, ...):
// a JSON object with stable keys, one line.
std::string recipe_settings_json(const std::string& name, const Mesh& mesh,
                                 const RecipeOptions& options);

Status run_recipe(const std::string& name, Mesh* mesh, const RecipeOptions& options,
                  RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_RECIPE_H_
