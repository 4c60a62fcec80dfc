#include "tmop/recipes/preserve.h"

#include <chrono>

#include "tmop/mesh/topology.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

bool same_topology(const Mesh& a, const Mesh& b) {
  return a.space_dim == b.space_dim && a.num_vertices() == b.num_vertices() &&
         a.cell_types == b.cell_types && a.cell_offsets == b.cell_offsets &&
         a.cell_nodes == b.cell_nodes;
}

}  // namespace

Status preserve(Mesh* mesh, const PreserveOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "preserve";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  if ((options.moved != nullptr) == static_cast<bool>(options.move))
    return Status::Failure("preserve: give exactly one of a moved mesh or a motion function");
  if (options.moved && !same_topology(*mesh, *options.moved))
    return Status::Failure("preserve: the moved mesh's vertices and cells do not match the mesh's");
  std::vector<char> fixed = options.fixed;
  if (fixed.empty()) fixed = boundary_vertex_mask(*mesh);
  if (static_cast<int>(fixed.size()) != mesh->num_vertices())
    return Status::Failure("preserve: fixed-vertex flags: one per vertex expected");
  if (!(options.power >= 1)) return Status::Failure("preserve: power must be >= 1");
  std::string error;
  if (!recipe_metric(options.metric, d, 1.0, &error)) return Status::Failure(error);

  // The original stays alive as the reference of every target below.
  const Mesh original = *mesh;
  if (options.moved) {
    mesh->coords = options.moved->coords;
  } else {
    for (int v = 0; v < mesh->num_vertices(); ++v)
      if (fixed[v]) options.move(v, original.vertex(v), mesh->vertex(v));
  }
  // Stages solve in normalised coordinates and map back, which moves fixed vertices by round-off;
  // the caller asked for exact boundary positions, so they are put back after every stage.
  const std::vector<double> prescribed = mesh->coords;
  auto restore_fixed = [&]() {
    for (int v = 0; v < mesh->num_vertices(); ++v)
      if (fixed[v])
        for (int a = 0; a < mesh->space_dim; ++a)
          mesh->vertex(v)[a] = prescribed[v * mesh->space_dim + a];
  };
  result->before = measure_mesh(*mesh, options.rule);

  TargetSpec reference;
  reference.type = TargetType::kReference;
  reference.reference = &original;

  UntangleOptions untangle_options;
  untangle_options.target = reference;
  untangle_options.rule = options.rule;
  untangle_options.theta = options.untangle_theta;
  untangle_options.max_rounds = options.untangle_max_rounds;
  untangle_options.improve_shape_after = false;
  untangle_options.fixed = fixed;
  untangle_options.solver = options.solver;
  RecipeResult untangled;
  Status s = untangle(mesh, untangle_options, &untangled);
  for (StageResult& st : untangled.stages) result->stages.push_back(std::move(st));
  restore_fixed();
  if (!s.ok()) {
    result->after = measure_mesh(*mesh, options.rule);
    return Status::Failure("preserve: " + s.message());
  }

  StageSpec stage;
  stage.name = "preserve";
  stage.rule = options.rule;
  stage.fixed = fixed;
  stage.solver = options.solver;
  stage.power = options.power;
  TermSpec term;
  term.metric = recipe_metric(options.metric, d, 1.0, &error);
  term.target = reference;
  stage.terms.push_back(term);
  StageResult sr;
  s = optimize_stage(mesh, stage, &sr);
  if (!s.ok()) return s;
  restore_fixed();
  result->stages.push_back(sr);
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
