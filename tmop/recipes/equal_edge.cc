#include "tmop/recipes/equal_edge.h"

#include <chrono>

#include "tmop/mesh/topology.h"
#include "tmop/recipes/guard.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

// Length of a TermSpec::weights vector: sample points of `rule` over the elements, canonical
// order (target.h). A per-term scalar weight in TermSpec would make this unnecessary.
int count_sample_points(const Mesh& mesh, SampleRule rule) {
  const int d = mesh.dim();
  int n = 0;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) n += static_cast<int>(sample_points(mesh.cell_type(c), rule).size());
  return n;
}

}  // namespace

Status equal_edge(Mesh* mesh, const EqualEdgeOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "equal_edge";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  if (!(options.shape_guard_weight >= 0))
    return Status::Failure("equal_edge: shape_guard_weight must be >= 0");
  result->before = measure_mesh(*mesh, options.rule);

  RecipeGeometry geometry;
  if (options.slide) {
    Status g = build_recipe_geometry(*mesh, options.boundary, &geometry);
    if (!g.ok()) return g;
  }
  StageSpec stage;
  stage.name = "equal_edge";
  if (options.slide) geometry.apply(&stage);
  stage.rule = options.rule;
  stage.fixed = options.fixed;
  stage.solver = options.solver;
  // Equal sizes couple the whole mesh (a lambda I target is not scale-invariant), so a step
  // needs long-range corrections that CGNR's capped inner iterations resolve slowly: with
  // CGNR instead of Cholesky it took 20-45 % longer at 306-16,982 free coordinates (cube 1.6k
  // tets +40 %, part 4k tets +45 %, cube 5k tets +25 %, plate 17.6k triangles +20 %;
  // docs/benchmarks.md, 2026-12-02). It keeps the library's earlier Cholesky limits unless the
  // caller set its own.
  if (stage.solver.cholesky_max_free_coordinates_2d < 0)
    stage.solver.cholesky_max_free_coordinates_2d = 20000;
  if (stage.solver.cholesky_max_free_coordinates_3d < 0)
    stage.solver.cholesky_max_free_coordinates_3d = 4000;
  std::string error;
  TermSpec size_shape;
  size_shape.metric = recipe_metric(options.metric, d, 1.0, &error);
  if (!size_shape.metric) return Status::Failure(error);
  size_shape.target.type = TargetType::kMeanEdgeLength;
  stage.terms.push_back(size_shape);
  if (options.shape_guard_weight > 0) {
    TermSpec guard;
    guard.metric = recipe_metric("shape_barrier", d, 1.0, &error);
    if (!guard.metric) return Status::Failure(error);
    // The shape metric is scale-invariant, so the target's size is irrelevant; the same
    // lambda target keeps both terms on one set of matrices.
    guard.target.type = TargetType::kMeanEdgeLength;
    guard.weights.assign(count_sample_points(*mesh, options.rule), options.shape_guard_weight);
    stage.terms.push_back(guard);
  }
  GuardOptions guard;
  guard.enabled = options.guard_worst;
  guard.guarantees.means = false;
  guard.warm_start = false;
  guard.soft_rounds = options.shape_guard_weight > 0 ? 3 : 0;
  guard.rounds = options.guard_rounds + guard.soft_rounds;
  guard.threads = options.solver.threads;
  guard.progress = options.solver.progress;
  GuaranteeBaseline baseline;
  if (guard.enabled) baseline = guarantee_baseline(*mesh, guard.threads);
  std::vector<char> fixed = options.fixed;
  if (fixed.empty())
    fixed =
        options.slide ? std::vector<char>(mesh->num_vertices(), 0) : boundary_vertex_mask(*mesh);
  const SampleSet points = canonical_sample_set(*mesh, options.rule);
  auto solve = [&](const std::vector<char>& held, const std::vector<double>& weight, int round) {
    StageSpec st = stage;
    st.fixed = held;
    if (st.terms.size() > 1)  // the shape guard term, weighted up where the guard asks
      for (std::size_t p = 0; p < points.size(); ++p)
        st.terms[1].weights[p] =
            options.shape_guard_weight * (weight.empty() ? 1.0 : weight[points.cell[p]]);
    if (round > 0) st.name += " (guard round " + std::to_string(round) + ")";
    StageResult sr;
    Status s = optimize_stage(mesh, st, &sr);
    if (s.ok()) result->stages.push_back(sr);
    return s;
  };
  Status s = guarded_solve(mesh, baseline, guard, fixed, solve, result);
  if (!s.ok()) return s;
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
