#include "tmop/recipes/improve_shape.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "tmop/mesh/topology.h"
#include "tmop/metric/power_mean.h"
#include "tmop/quality/parallel_for.h"
#include "tmop/quality/worst_quality.h"
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

Status improve_shape(Mesh* mesh, const ShapeOptions& options, RecipeResult* result) {
  // Quadratic cells: through their corner mesh (quadratic_shape.h); it calls back with that.
  if (use_quadratic_shape(*mesh)) return improve_quadratic_shape(mesh, options, result);
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "shape";
  const int d = mesh->dim();
  RecipeGeometry own;
  const RecipeGeometry* geometry = nullptr;
  Status gs = resolve_recipe_geometry(*mesh, options.slide, options.boundary, options.geometry,
                                      &own, &geometry);
  if (!gs.ok()) {
    result->before = measure_mesh(*mesh, options.rule);  // measured beside the mask below
    return gs;
  }
  const std::vector<double> original = mesh->coords;
  const int threads = options.solver.threads;
  // Vertices held fixed: the caller's, else the boundary (stage.h); the guard adds to them.
  // The boundary's facet matching runs beside the quality passes (1M tets: 0.6 s hidden).
  std::vector<char> fixed = options.fixed;
  const bool need_mask = fixed.empty() && !geometry;
  std::vector<double> q_before;
  double worst_before = 0;
  side_by_side(
      threads != 1,
      [&] {
        if (need_mask) fixed = boundary_vertex_mask(*mesh);
      },
      [&] {
        result->before = measure_mesh(*mesh, options.rule);
        if (!options.guard_worst) return;
        q_before = cell_headline_quality(*mesh, threads);
        worst_before = std::numeric_limits<double>::infinity();
        for (double q : q_before)
          if (!std::isnan(q)) worst_before = std::min(worst_before, q);
      });
  if (fixed.empty() && geometry) fixed.assign(mesh->num_vertices(), 0);
  int held_cells = 0;
  for (int round = 0; round <= options.guard_rounds; ++round) {
    std::string error;
    StageSpec stage;
    stage.name = round == 0 ? "shape" : "shape (guard round " + std::to_string(round) + ")";
    stage.rule = options.rule;
    stage.extra_points = options.extra_points;
    stage.fixed = fixed;
    stage.solver = options.solver;
    if (geometry) geometry->apply(&stage);
    TermSpec term;
    term.metric = recipe_metric(options.metric, d, 1.0, &error);
    stage.power = options.power > 0 ? options.power : 2.0;
    if (!term.metric) return Status::Failure(error);
    term.target = options.target;
    stage.terms.push_back(term);
    StageResult sr;
    Status s = optimize_stage(mesh, stage, &sr);
    if (!s.ok()) return s;
    result->stages.push_back(sr);
    result->after = measure_mesh(*mesh, options.rule);
    if (!options.guard_worst) break;
    // Cells that fell below the input's worst quality are held at their input shape: their
    // vertices join the fixed set and the stage solves again from the input. Every input cell
    // is at least as good as the input's worst, so held cells cannot violate; the set only
    // grows, so this ends (at worst with the input itself).
    const std::vector<double> q = cell_headline_quality(*mesh, threads);
    int violators = 0, newly_fixed = 0;
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (std::isnan(q[c]) || q[c] >= worst_before - options.guard_tolerance) continue;
      ++violators;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        newly_fixed += !f;
        f = 1;
      }
    }
    if (violators == 0) break;
    held_cells += violators;
    mesh->coords = original;
    result->after = result->before;
    if (newly_fixed == 0 || round == options.guard_rounds) {
      result->stages.back().termination += "; the worst element would get worse: input mesh kept";
      break;
    }
    result->stages.back().termination += "; worst-element guard: " + std::to_string(violators) +
                                         " cells below the input's worst quality, " +
                                         std::to_string(newly_fixed) + " vertices held";
  }
  (void)held_cells;
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
