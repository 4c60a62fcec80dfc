#include "tmop/recipes/recipe.h"

#include <algorithm>
#include <cstdio>

#include "tmop/mesh/topology.h"
#include "tmop/metric/metric.h"
#include "tmop/recipes/equal_edge.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/laplace.h"
#include "tmop/recipes/preserve.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/size_adapt.h"
#include "tmop/recipes/sliver.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

using O = RecipeOption;

// Every recipe's solver settings; laplace has no solver.
#define TMOP_SOLVER_OPTIONS \
  O::kSolverMethod, O::kMaxIterations, O::kMaxSeconds, O::kFunctionTolerance, O::kThreads

const std::vector<RecipeInfo>& table() {
  // auto, shape, surface and high_order: the shape recipe's options (after untangling).
  const std::vector<RecipeOption> shape_family = {
      O::kMetric, O::kTarget,   O::kReference, O::kPower,     O::kSampleRule,
      O::kSlide,  O::kGeometry, O::kFixed,     O::kGuarantee, TMOP_SOLVER_OPTIONS};
  static const std::vector<RecipeInfo> t = {
      {"auto", "untangle if anything is inverted, then improve shape", shape_family, false, false,
       true, true},
      {"shape", "shape improvement with a barrier metric (the input must be valid)", shape_family,
       false, true, true, true},
      {"untangle",
       "untangle only",
       {O::kReference, O::kSampleRule, O::kSlide, O::kGeometry, O::kFixed, O::kGuarantee,
        TMOP_SOLVER_OPTIONS},
       false,
       false,
       true,
       true},
      {"surface", "shape improvement of a surface mesh on its geometry", shape_family, true, false,
       true, true},
      {"equal_edge",
       "equal edge lengths keeping shapes",
       {O::kMetric, O::kSampleRule, O::kSlide, O::kGeometry, O::kFixed, O::kGuarantee,
        O::kShapeGuardWeight, TMOP_SOLVER_OPTIONS},
       false,
       true,
       true,
       false},
      {"size_adapt",
       "shapes with the local (or size-field) size",
       {O::kMetric, O::kPower, O::kSampleRule, O::kSlide, O::kGeometry, O::kFixed, O::kSizeField,
        TMOP_SOLVER_OPTIONS},
       false,
       true,
       false,
       false},
      {"preserve",
       "follow a moved boundary, keeping the input's shapes and sizes",
       {O::kMetric, O::kPower, O::kSampleRule, O::kFixed, O::kMoved, TMOP_SOLVER_OPTIONS},
       false,
       false,
       false,
       false},
      {"laplace",
       "smart Laplacian baseline",
       {O::kSlide, O::kGeometry, O::kFixed, O::kMaxSweeps},
       false,
       true,
       false,
       false},
      {"sliver",
       "remove slivers, keep the boundary layer",
       {O::kSampleRule, O::kSlide, O::kGeometry, O::kFixed, O::kGuarantee, O::kLayerEdgeRatio,
        TMOP_SOLVER_OPTIONS},
       true,
       false,
       true,
       false},
      {"high_order", "quadratic meshes: untangle + shape + Bernstein certificate (as auto)",
       shape_family, false, false, true, true},
  };
  return t;
}
#undef TMOP_SOLVER_OPTIONS

// The options set to other than their defaults.
std::vector<RecipeOption> set_options(const RecipeOptions& o) {
  const RecipeOptions d;
  const SolverOptions& s = o.solver;
  const struct {
    RecipeOption option;
    bool set;
  } all[] = {
      {O::kMetric, !o.metric.empty()},
      {O::kTarget, o.target.type != d.target.type && o.target.type != TargetType::kReference},
      {O::kReference, o.target.type == TargetType::kReference},
      {O::kPower, o.power != d.power},
      {O::kSampleRule, o.rule != d.rule},
      {O::kSlide, o.boundary == BoundaryMode::kSlide},
      {O::kGeometry, !o.geometry.geometry.empty()},
      {O::kFixed, !o.fixed.empty()},
      {O::kGuarantee, o.guarantee != d.guarantee},
      {O::kSolverMethod, s.method != d.solver.method || s.linear_solver != d.solver.linear_solver},
      {O::kMaxIterations, s.max_iterations != d.solver.max_iterations},
      {O::kMaxSeconds, s.max_seconds != d.solver.max_seconds},
      {O::kFunctionTolerance, s.function_tolerance != d.solver.function_tolerance},
      {O::kThreads, s.threads != d.solver.threads},
      {O::kMoved, o.moved != nullptr},
      {O::kSizeField, !o.size_field.empty()},
      {O::kShapeGuardWeight, o.shape_guard_weight != d.shape_guard_weight},
      {O::kLayerEdgeRatio, o.layer_edge_ratio != d.layer_edge_ratio},
      {O::kMaxSweeps, o.max_sweeps != d.max_sweeps},
  };
  std::vector<RecipeOption> out;
  for (const auto& a : all)
    if (a.set) out.push_back(a.option);
  return out;
}

bool is(const std::string& name, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (name == n) return true;
  return false;
}

// The recipe's fixed flags: the caller's plus the boundary when it does not slide (the recipes
// read non-empty flags as the whole fixed set).
std::vector<char> recipe_fixed(const std::string& name, const Mesh& mesh,
                               const RecipeOptions& options) {
  std::vector<char> fixed = options.fixed;
  if (fixed.empty() || name == "sliver") return fixed;  // sliver adds its boundary itself
  if (!recipe_slides(name, options) && !is_surface_mesh(mesh)) {
    const std::vector<char> boundary = boundary_vertex_mask(mesh);
    for (std::size_t v = 0; v < fixed.size() && v < boundary.size(); ++v) fixed[v] |= boundary[v];
  }
  return fixed;
}

// The shape options of recipes auto, shape, surface and high_order.
ShapeOptions shape_options(const std::string& name, const RecipeOptions& o,
                           const std::vector<char>& fixed) {
  ShapeOptions s;
  s.metric = o.metric;
  s.target = o.target;
  s.rule = o.rule;
  s.power = o.power;
  s.guard_worst = o.guarantee != GuaranteeMode::kOff;
  s.guard_means = o.guarantee == GuaranteeMode::kAll;
  s.fixed = fixed;
  s.slide = recipe_slides(name, o);
  s.boundary = o.geometry;
  s.solver = o.solver;
  s.input_baseline = o.input_baseline;
  return s;
}

Status dispatch(const std::string& name, Mesh* mesh, const RecipeOptions& o, RecipeResult* result) {
  const std::vector<char> fixed = recipe_fixed(name, *mesh, o);
  const bool slide = recipe_slides(name, o);
  const bool guard_worst = o.guarantee != GuaranteeMode::kOff;
  if (name == "shape") return improve_shape(mesh, shape_options(name, o, fixed), result);
  if (name == "equal_edge") {
    EqualEdgeOptions e;
    if (!o.metric.empty()) e.metric = o.metric;
    e.shape_guard_weight = o.shape_guard_weight;
    if (o.rule != SampleRule::kDefault) e.rule = o.rule;
    e.fixed = fixed;
    e.slide = slide;
    e.boundary = o.geometry;
    e.solver = o.solver;
    e.guard_worst = guard_worst;
    return equal_edge(mesh, e, result);
  }
  if (name == "size_adapt") {
    SizeAdaptOptions a;
    a.size_field = o.size_field;
    if (!o.metric.empty()) a.metric = o.metric;
    if (o.power > 0) a.power = o.power;
    a.rule = o.rule;
    a.fixed = fixed;
    a.slide = slide;
    a.boundary = o.geometry;
    a.solver = o.solver;
    return size_adapt(mesh, a, result);
  }
  if (name == "preserve") {
    PreserveOptions p;
    p.moved = o.moved;
    if (!o.metric.empty()) p.metric = o.metric;
    if (o.power > 0) p.power = o.power;
    p.rule = o.rule;
    p.fixed = fixed;
    p.solver = o.solver;
    return preserve(mesh, p, result);
  }
  if (name == "sliver") {
    SliverOptions s;
    s.slide = slide;
    s.boundary = o.geometry;
    s.fixed = fixed;
    s.rule = o.rule;
    s.solver = o.solver;
    s.guard_worst = guard_worst;
    s.layer_edge_ratio = o.layer_edge_ratio;
    return remove_slivers(mesh, s, result);
  }
  if (name == "laplace") {
    LaplaceOptions l;
    l.max_sweeps = o.max_sweeps;
    l.fixed = fixed;
    l.slide = slide;
    l.boundary = o.geometry;
    l.progress = o.solver.progress;
    return laplace(mesh, l, result);
  }
  // auto, high_order, untangle, surface: the untangler, then (but for untangle) the shape stage.
  UntangleOptions u;
  u.target = o.target;  // untangle toward the reference when one is given
  if (o.target.type != TargetType::kReference) u.target.type = TargetType::kIdealEqualSize;
  u.rule = o.rule;
  u.solver = o.solver;
  u.improve_shape_after = name != "untangle";
  u.fixed = fixed;
  u.slide = slide;
  u.boundary = o.geometry;
  u.shape = shape_options(name, o, fixed);
  const Status s = untangle(mesh, u, result);
  if (name == "surface" || name == "high_order") result->recipe = name;
  return s;
}

}  // namespace

const char* recipe_option_flag(RecipeOption option) {
  switch (option) {
    case O::kMetric:
      return "metric";
    case O::kTarget:
      return "target";
    case O::kReference:
      return "reference";
    case O::kPower:
      return "power";
    case O::kSampleRule:
      return "sample_points";
    case O::kSlide:
      return "boundary=slide";
    case O::kGeometry:
      return "geometry";
    case O::kFixed:
      return "fixed_nodes";
    case O::kGuarantee:
      return "guarantee";
    case O::kSolverMethod:
      return "solver";
    case O::kMaxIterations:
      return "max_iterations";
    case O::kMaxSeconds:
      return "max_seconds";
    case O::kFunctionTolerance:
      return "function_tolerance";
    case O::kThreads:
      return "threads";
    case O::kMoved:
      return "moved";
    case O::kSizeField:
      return "size_field";
    case O::kShapeGuardWeight:
      return "shape_guard_weight";
    case O::kLayerEdgeRatio:
      return "layer_edge_ratio";
    case O::kMaxSweeps:
      return "max_sweeps";
  }
  return "?";
}

bool guarantee_mode_from_name(const std::string& name, GuaranteeMode* mode) {
  for (GuaranteeMode m : {GuaranteeMode::kAll, GuaranteeMode::kWorst, GuaranteeMode::kOff})
    if (name == guarantee_mode_name(m)) {
      *mode = m;
      return true;
    }
  return false;
}

const char* guarantee_mode_name(GuaranteeMode mode) {
  return mode == GuaranteeMode::kAll ? "all" : mode == GuaranteeMode::kWorst ? "worst" : "off";
}

const std::vector<RecipeInfo>& recipes() { return table(); }

const RecipeInfo* find_recipe(const std::string& name) {
  for (const RecipeInfo& r : table())
    if (name == r.name) return &r;
  return nullptr;
}

std::string recipe_names() {
  std::string out;
  for (const RecipeInfo& r : table()) out += (out.empty() ? "" : ", ") + std::string(r.name);
  return out;
}

std::vector<RecipeOption> unused_options(const std::string& name, const RecipeOptions& options) {
  std::vector<RecipeOption> out;
  const RecipeInfo* r = find_recipe(name);
  if (!r) return out;
  for (RecipeOption o : set_options(options))
    if (std::find(r->honours.begin(), r->honours.end(), o) == r->honours.end()) out.push_back(o);
  return out;
}

bool recipe_slides(const std::string& name, const RecipeOptions& options) {
  const RecipeInfo* r = find_recipe(name);
  return options.boundary == BoundaryMode::kSlide || name == "surface" ||
         (options.boundary == BoundaryMode::kDefault && r && r->slides_by_default);
}

bool recipe_guarantees(const std::string& name, const RecipeOptions& options,
                       GuaranteeOptions* guarantees) {
  const RecipeInfo* r = find_recipe(name);
  if (!r || !r->keeps_guarantees || options.guarantee == GuaranteeMode::kOff) return false;
  *guarantees = GuaranteeOptions();
  guarantees->means = r->keeps_means && options.guarantee == GuaranteeMode::kAll;
  // A tangled input is untangled: only new inversions count (docs/quality.md).
  guarantees->tangled_inversions_only = true;
  return true;
}

Status check_recipe(const std::string& name, const Mesh& mesh, const RecipeOptions& options) {
  if (!find_recipe(name))
    return Status::Failure("unknown recipe '" + name + "' (known: " + recipe_names() + ")");
  const std::vector<RecipeOption> unused = unused_options(name, options);
  if (!unused.empty())
    return Status::Failure("option " + std::string(recipe_option_flag(unused[0])) +
                           " is not used by recipe " + name);
  if (name == "sliver" && !(mesh.dim() == 3 && mesh.space_dim == 3))
    return Status::Failure("recipe sliver needs a volume mesh (tets), not a " +
                           std::to_string(mesh.dim()) + "D mesh");
  if (name == "surface" && !is_surface_mesh(mesh))
    return Status::Failure("recipe surface needs a surface mesh (2D cells in 3D)");
  if (name == "preserve" && !options.moved)
    return Status::Failure("recipe preserve needs the moved mesh (options.moved)");
  if (!options.fixed.empty() && static_cast<int>(options.fixed.size()) != mesh.num_vertices())
    return Status::Failure("fixed: " + std::to_string(options.fixed.size()) +
                           " flags for a mesh of " + std::to_string(mesh.num_vertices()) +
                           " vertices");
  if (!options.metric.empty() && !make_metric(options.metric, mesh.dim())) {
    std::string known;
    for (const std::string& n : metric_names(mesh.dim())) known += (known.empty() ? "" : ", ") + n;
    return Status::Failure("unknown metric '" + options.metric + "' for " +
                           std::to_string(mesh.dim()) + "D meshes (known: " + known +
                           "; or W1*NAME1+W2*NAME2 with weights >= 0)");
  }
  if (!options.geometry.geometry.empty()) {
    BoundaryOptions b = options.geometry;
    b.slide = recipe_slides(name, options);
    const Status s = check_geometry_spec(mesh, b);
    if (!s.ok() && !b.slide && !is_surface_mesh(mesh))
      return Status::Failure(s.message() + " (add --boundary=slide)");
    return s;
  }
  return Status::Ok();
}

Status check_valid_input(const std::string& name, const Mesh& mesh, SampleRule rule,
                         int* inverted) {
  const RecipeInfo* r = find_recipe(name);
  *inverted = r && r->needs_valid_input ? measure_mesh(mesh, rule).inverted : 0;
  if (*inverted == 0) return Status::Ok();
  return Status::Failure(std::to_string(*inverted) + " inverted elements: recipe " + name +
                         " needs a valid mesh (use --recipe=auto or untangle)");
}

std::string recipe_settings_json(const std::string& name, const Mesh& mesh,
                                 const RecipeOptions& o) {
  std::string metric = o.metric;
  if (metric.empty()) {
    if (is(name, {"auto", "shape", "surface", "high_order"}))
      metric = mesh.dim() == 3 ? "shape_barrier_3d" : "shape_barrier_2d";
    else if (is(name, {"equal_edge", "size_adapt", "preserve"}))
      metric = "size_shape_barrier";
    else if (name == "sliver")
      metric = "shape_cubic_barrier_3d+size_shape_orientation_barrier";
    else if (name == "untangle")
      metric = "untangle";
  }
  double power = o.power;
  if (power == 0)
    power = is(name, {"auto", "shape", "surface", "high_order", "preserve"}) ? 2
            : name == "size_adapt"                                           ? 1
                                                                             : 0;
  int fixed = 0;
  for (char f : o.fixed) fixed += f != 0;
  const char* linear = o.solver.linear_solver == SolverOptions::LinearSolver::kAuto   ? "auto"
                       : o.solver.linear_solver == SolverOptions::LinearSolver::kCgnr ? "cgnr"
                                                                                      : "cholesky";
  GuaranteeOptions g;
  const bool checked = recipe_guarantees(name, o, &g);
  return "{\"recipe\": " + json_string(name) +
         ", \"metric\": " + (metric.empty() ? std::string("null") : json_string(metric)) +
         ", \"target\": " + json_string(target_type_name(o.target.type)) +
         ", \"power\": " + (power > 0 ? json_number(power) : "null") +
         ", \"sample_points\": " + json_string(sample_rule_name(o.rule)) +
         ", \"boundary\": " + json_string(recipe_slides(name, o) ? "slide" : "fixed") +
         ", \"geometry\": " + json_string(o.geometry.geometry) +
         ", \"feature_angle\": " + json_number(o.geometry.feature_angle_deg) +
         ", \"fixed_nodes\": " + std::to_string(fixed) +
         ", \"guarantee\": " + json_string(guarantee_mode_name(o.guarantee)) +
         ", \"guarantees_checked\": " +
         (checked ? json_string(g.means ? "all" : "worst") : std::string("null")) +
         ", \"solver\": " +
         json_string(o.solver.method == SolverOptions::Method::kDogleg ? "dogleg" : "lm") +
         ", \"linear_solver\": " + json_string(linear) +
         ", \"max_iterations\": " + std::to_string(o.solver.max_iterations) +
         ", \"max_seconds\": " + json_number(o.solver.max_seconds) +
         ", \"function_tolerance\": " + json_number(o.solver.function_tolerance) +
         ", \"threads\": " + std::to_string(o.solver.threads) +
         ", \"size_field\": " + json_string(o.size_field) +
         ", \"shape_guard_weight\": " + json_number(o.shape_guard_weight) +
         ", \"layer_edge_ratio\": " + json_number(o.layer_edge_ratio) +
         ", \"max_sweeps\": " + std::to_string(o.max_sweeps) + "}";
}

Status run_recipe(const std::string& name, Mesh* mesh, const RecipeOptions& options,
                  RecipeResult* result) {
  *result = RecipeResult();
  result->recipe = name;
  Status s = check_recipe(name, *mesh, options);
  if (!s.ok()) return s;
  int inverted = 0;
  s = check_valid_input(name, *mesh, options.rule, &inverted);
  if (!s.ok()) return s;
  RecipeOptions o = options;
  // One callback for every stage: the caller's (when set) and the cancel flag behind it.
  if (options.cancel || options.solver.progress) {
    const ProgressCallback user = options.solver.progress;
    const std::atomic<bool>* cancel = options.cancel;
    o.solver.progress = [user, cancel](const ProgressRecord& r) {
      if (cancel && cancel->load()) return false;
      return !user || user(r);
    };
    // The loops that start solves, rounds, phases and parts check cancelled(): they see the flag
    // at once, not only after the next iteration's record (a stage's set-up can take seconds).
    o.solver.progress.watch(cancel);
  }
  s = dispatch(name, mesh, o, result);
  if (o.solver.progress.cancelled())
    return Status::Cancelled("recipe " + name + " cancelled" +
                             (s.ok() || s.cancelled() ? std::string() : " (" + s.message() + ")"));
  return s;
}

}  // namespace tmop
