#include "tmop/recipes/untangle.h"

#include <chrono>

#include "tmop/metric/untangle.h"

namespace tmop {
namespace {

std::string cell_list(const std::vector<int>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < 10; ++i)
    s += (i ? ", " : "") + std::to_string(cells[i]);
  if (cells.size() > 10) s += ", ... (" + std::to_string(cells.size()) + " in all)";
  return s;
}

}  // namespace

Status untangle(Mesh* mesh, const UntangleOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = options.improve_shape_after ? "auto" : "untangle";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  result->before = measure_mesh(*mesh, options.rule);
  auto finish = [&]() {
    result->after = measure_mesh(*mesh, options.rule);
    result->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  if (result->before.inverted > 0) {
    StageSpec stage;
    stage.name = "untangle";
    stage.rule = options.rule;
    stage.fixed = options.fixed;
    stage.solver = options.solver;
    stage.untangle = true;
    stage.untangle_max_rounds = options.max_rounds;
    stage.untangle_round_iterations = options.round_iterations;
    TermSpec term;
    try {
      term.metric = std::make_shared<UntangleMetric>(d, options.initial_eps, options.theta);
    } catch (const std::exception& e) {
      return Status::Failure(std::string("untangle options: ") + e.what());
    }
    term.target = options.target;
    stage.terms.push_back(term);
    StageResult sr;
    Status s = optimize_stage(mesh, stage, &sr);
    if (!s.ok()) return s;
    result->stages.push_back(sr);
    if (!sr.inverted_cells.empty()) {
      finish();
      return Status::Failure("could not untangle within " + std::to_string(options.max_rounds) +
                             " rounds: " + std::to_string(sr.inverted_cells.size()) +
                             " cells still inverted: " + cell_list(sr.inverted_cells));
    }
  }
  if (options.improve_shape_after) {
    ShapeOptions shape = options.shape;
    shape.fixed = options.fixed;
    RecipeResult shape_result;
    Status s = improve_shape(mesh, shape, &shape_result);
    if (!s.ok()) return s;
    for (StageResult& st : shape_result.stages) result->stages.push_back(std::move(st));
  }
  finish();
  return Status::Ok();
}

}  // namespace tmop
