#include "tmop/recipes/size_adapt.h"

#include <chrono>

#include "tmop/recipes/improve_shape.h"

namespace tmop {

Status size_adapt(Mesh* mesh, const SizeAdaptOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "size_adapt";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  if (!(options.power >= 1)) return Status::Failure("size_adapt: power must be >= 1");
  result->before = measure_mesh(*mesh, options.rule);

  RecipeGeometry geometry;
  if (options.slide) {
    Status g = build_recipe_geometry(*mesh, options.boundary, &geometry);
    if (!g.ok()) return g;
  }
  StageSpec stage;
  stage.name = "size_adapt";
  if (options.slide) geometry.apply(&stage);
  stage.rule = options.rule;
  stage.fixed = options.fixed;
  stage.solver = options.solver;
  stage.power = options.power;
  std::string error;
  TermSpec term;
  term.metric = recipe_metric(options.metric, d, 1.0, &error);
  if (!term.metric) return Status::Failure(error);
  if (options.size_field.empty()) {
    term.target.type = TargetType::kIdealLocalSize;
  } else {
    term.target.type = TargetType::kIdealSizeField;
    term.target.size_field = options.size_field;
  }
  stage.terms.push_back(term);
  StageResult sr;
  Status s = optimize_stage(mesh, stage, &sr);
  if (!s.ok()) return s;
  result->stages.push_back(sr);
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
