#include "tmop/recipes/improve_shape.h"

#include <chrono>

#include "tmop/metric/power_mean.h"

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
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "shape";
  const int d = mesh->dim();
  result->before = measure_mesh(*mesh, options.rule);

  RecipeGeometry own;
  const RecipeGeometry* geometry = nullptr;
  Status gs = resolve_recipe_geometry(*mesh, options.slide, options.boundary, options.geometry,
                                      &own, &geometry);
  if (!gs.ok()) return gs;
  const std::vector<double> original = mesh->coords;
  double power = options.power;
  for (int attempt = 0; attempt < 3; ++attempt) {
    std::string error;
    StageSpec stage;
    stage.name = attempt == 0 ? "shape" : "shape (power " + std::to_string(int(power)) + ")";
    stage.rule = options.rule;
    stage.extra_points = options.extra_points;
    stage.fixed = options.fixed;
    stage.solver = options.solver;
    if (geometry) geometry->apply(&stage);
    TermSpec term;
    term.metric = recipe_metric(options.metric, d, 1.0, &error);
    stage.power = power;
    if (!term.metric) return Status::Failure(error);
    term.target = options.target;
    stage.terms.push_back(term);
    StageResult sr;
    Status s = optimize_stage(mesh, stage, &sr);
    if (!s.ok()) return s;
    result->stages.push_back(sr);
    result->after = measure_mesh(*mesh, options.rule);
    if (!options.guard_worst || result->after.min_quality >= result->before.min_quality) break;
    // The worst element got worse: weight the worst elements up and start again.
    mesh->coords = original;
    result->after = result->before;
    power = power < 2 ? 2 : power * 2;
    if (attempt == 2) {
      result->stages.back().termination +=
          "; worst element would get worse at every power tried: input mesh kept";
    }
  }
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
