#include "tmop/recipes/improve_shape.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "tmop/mesh/topology.h"
#include "tmop/metric/power_mean.h"
#include "tmop/quality/parallel_for.h"
#include "tmop/recipes/boundary_layer.h"
#include "tmop/recipes/guard.h"
#include "tmop/recipes/quadratic_shape.h"

namespace tmop {

std::shared_ptr<const Metric> recipe_metric(const std::string& name, int dim, double power,
                                            std::string* error) {
  const std::string n = name.empty() ? "shape_barrier" : name;
  std::shared_ptr<const Metric> m(make_metric(n, dim).release());
  if (!m) {
    std::string known;
    for (const std::string& s : metric_names(dim)) known += (known.empty() ? "" : ", ") + s;
    *error =
        "unknown metric '" + n + "' for " + std::to_string(dim) + "D meshes (known: " + known + ")";
    return nullptr;
  }
  if (!(power >= 1)) {
    *error = "power-mean order must be >= 1";
    return nullptr;
  }
  if (power == 1) return m;
  return std::make_shared<PowerMeanMetric>(m, power);
}

namespace {

bool is_simplex_cell(CellType t) {
  const CellType l = cell_info(t).linear;
  return l == CellType::kTri3 || l == CellType::kTet4;
}

// The shape stage's terms. A simplex is judged by its mean ratio, which the shape metric with
// the ideal target measures exactly (mu = 1/q - 1 for tets), so simplices get the caller's
// target. The other types are judged by their scaled Jacobian, which sees only angles: an ideal
// (unit-aspect) target would trade angles for aspect (sg_transfinite's 4,374 hexes: mean scaled
// Jacobian 0.896 -> 0.854). With target_aspect_of_input (and the default target) they get the
// ideal angles with the input's smoothed aspect (composed: skew ideal, aspect smooth), whose
// shape-metric minimum is a corner with scaled Jacobian 1 and the neighbourhood's edge ratios.
Status shape_terms(const Mesh& mesh, const ShapeOptions& options, std::vector<TermSpec>* terms) {
  std::string error;
  TermSpec term;
  term.metric = recipe_metric(options.metric, mesh.dim(), 1.0, &error);
  if (!term.metric) return Status::Failure(error);
  term.target = options.target;
  const int d = mesh.dim();
  bool simplices = false, others = false;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) (is_simplex_cell(mesh.cell_type(c)) ? simplices : others) = true;
  const bool aspect = options.target_aspect_of_input && others &&
                      options.target.type == TargetType::kIdealEqualSize;
  if (!aspect) {
    terms->push_back(term);
    return Status::Ok();
  }
  TermSpec kept = term;
  kept.target.type = TargetType::kComposed;
  kept.target.composed = ComposedTarget();  // size equal (irrelevant to shape), orientation ideal
  kept.target.composed.aspect.source = FactorSource::kSmooth;
  if (!simplices) {
    terms->push_back(kept);
    return Status::Ok();
  }
  // Mixed: one term per kind of cell, each weighted 0 on the other kind's points.
  const SampleSet points = canonical_sample_set(mesh, options.rule);
  term.weights.resize(points.size());
  kept.weights.resize(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const bool s = is_simplex_cell(mesh.cell_type(points.cell[p]));
    term.weights[p] = s ? 1 : 0;
    kept.weights[p] = s ? 0 : 1;
  }
  if (!options.extra_points.cell.empty())
    for (std::size_t p = 0; p < options.extra_points.size(); ++p) {
      const bool s = is_simplex_cell(mesh.cell_type(options.extra_points.cell[p]));
      term.weights.push_back(s ? 1 : 0);
      kept.weights.push_back(s ? 0 : 1);
    }
  terms->push_back(term);
  terms->push_back(kept);
  return Status::Ok();
}

}  // namespace

Status improve_shape(Mesh* mesh, const ShapeOptions& options, RecipeResult* result) {
  // Quadratic cells: through their corner mesh (quadratic_shape.h); it calls back with that.
  if (use_quadratic_shape(*mesh)) return improve_quadratic_shape(mesh, options, result);
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "shape";
  RecipeGeometry own;
  const RecipeGeometry* geometry = nullptr;
  Status gs = resolve_recipe_geometry(*mesh, options.slide, options.boundary, options.geometry,
                                      &own, &geometry);
  if (!gs.ok()) {
    result->before = measure_mesh(*mesh, options.rule);  // measured beside the mask below
    return gs;
  }
  const int threads = options.solver.threads;
  // Vertices held fixed: the caller's, else the boundary (stage.h); the guard adds to them.
  // The boundary's facet matching runs beside the quality passes (1M tets: 0.6 s hidden).
  std::vector<char> fixed = options.fixed;
  const bool need_mask = fixed.empty() && !geometry;
  // The guard's baseline: the caller's when it has one of this mesh, else computed here.
  const bool own_baseline =
      options.guard_worst &&
      !(options.input_baseline &&
        static_cast<int>(options.input_baseline->cell_type.size()) == mesh->num_cells());
  GuaranteeBaseline computed;
  side_by_side(
      threads != 1,
      [&] {
        if (need_mask) fixed = boundary_vertex_mask(*mesh);
      },
      [&] {
        result->before = measure_mesh(*mesh, options.rule);
        if (own_baseline) computed = guarantee_baseline(*mesh, threads);
      });
  if (fixed.empty()) fixed.assign(mesh->num_vertices(), 0);
  if (static_cast<int>(fixed.size()) != mesh->num_vertices())
    return Status::Failure("shape: fixed-vertex flags: one per vertex expected");
  // Boundary layers are kept as they are: their vertices are held (boundary_layer.h).
  if (options.keep_boundary_layers) {
    const std::vector<char> layer = find_boundary_layer(*mesh, options.boundary_layer);
    result->layer_cells = 0;
    result->held_vertices = 0;
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (!layer[c]) continue;
      ++result->layer_cells;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        result->held_vertices += !f;
        f = 1;
      }
    }
    if (result->layer_cells == 0) result->layer_cells = result->held_vertices = -1;
  }
  std::vector<TermSpec> terms;
  Status ts = shape_terms(*mesh, options, &terms);
  if (!ts.ok()) return ts;
  GuardOptions guard;
  guard.enabled = options.guard_worst;
  guard.guarantees.tolerance = options.guard_tolerance;
  guard.guarantees.means = options.guard_means;
  guard.rounds = options.guard_rounds;
  guard.threads = threads;
  guard.verbose = options.solver.verbose;
  guard.progress = options.solver.progress;
  guard.soft_rounds = options.guard_soft_rounds;
  SampleSet weighted_points;  // canonical + extra points, for the soft rounds' cell weights
  auto solve = [&](const std::vector<char>& held, const std::vector<double>& cell_weight,
                   int round) {
    StageSpec stage;
    stage.name = round == 0 ? "shape" : "shape (guard round " + std::to_string(round) + ")";
    stage.rule = options.rule;
    stage.extra_points = options.extra_points;
    stage.fixed = held;
    stage.solver = options.solver;
    if (geometry) geometry->apply(&stage);
    stage.power = options.power > 0 ? options.power : 2.0;
    stage.terms = terms;
    bool weighted = false;
    for (double w : cell_weight) weighted = weighted || w != 1;
    if (weighted) {
      if (weighted_points.cell.empty()) {
        weighted_points = canonical_sample_set(*mesh, options.rule);
        for (std::size_t p = 0; p < options.extra_points.size(); ++p)
          weighted_points.add(options.extra_points.cell[p], &options.extra_points.xi[3 * p],
                              options.extra_points.weight[p]);
      }
      for (TermSpec& t : stage.terms) {
        t.weights.resize(weighted_points.size(), 1.0);
        for (std::size_t p = 0; p < weighted_points.size(); ++p)
          t.weights[p] *= cell_weight[weighted_points.cell[p]];
      }
    }
    StageResult sr;
    Status s = optimize_stage(mesh, stage, &sr);
    if (s.ok()) result->stages.push_back(sr);
    return s;
  };
  const GuaranteeBaseline& baseline =
      own_baseline || !options.guard_worst ? computed : *options.input_baseline;
  Status s = guarded_solve(mesh, baseline, guard, fixed, solve, result);
  if (!s.ok()) return s;
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
