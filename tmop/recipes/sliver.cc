#include "tmop/recipes/sliver.h"

#include <chrono>
#include <cmath>

#include "tmop/mesh/topology.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/recipes/boundary_layer.h"
#include "tmop/recipes/guard.h"

namespace tmop {

Status remove_slivers(Mesh* mesh, const SliverOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "sliver";
  const int d = mesh->dim();
  if (d != 3 || mesh->space_dim != 3)
    return Status::Failure("recipe sliver needs a volume mesh (tets)");
  result->before = measure_mesh(*mesh, options.rule);
  if (result->before.inverted > 0)
    return Status::Failure(std::to_string(result->before.inverted) +
                           " inverted elements: recipe sliver needs a valid mesh (its second "
                           "term keeps the initial Jacobians); run recipe auto first");

  // Per element cell: c_k from the initial max dihedral angle (tets; other cells keep c = 0),
  // and whether it is a layer cell (kept, c < 1/2, and stretched: a short edge).
  const int num_cells = mesh->num_cells();
  std::vector<double> cell_c(num_cells, 0);
  std::vector<char> layer(num_cells, 0);
  int tets = 0;
  {
    double nodes[kMaxCellNodes * 3];
    for (int cell = 0; cell < num_cells; ++cell) {
      if (!mesh->is_element(cell)) continue;
      const CellType t = mesh->cell_type(cell);
      for (int i = 0; i < mesh->cell_size(cell); ++i)
        for (int a = 0; a < 3; ++a) nodes[3 * i + a] = mesh->vertex(mesh->cell(cell)[i])[a];
      const CellQuality q = cell_quality(t, nodes, nullptr);
      if (cell_info(t).linear == CellType::kTet4) {
        ++tets;
        cell_c[cell] =
            1 / (1 + std::exp(-options.steepness * (q.max_dihedral_deg - options.threshold_deg)));
      }
      layer[cell] = options.layer_edge_ratio > 0 && cell_c[cell] < 0.5 &&
                    q.max_edge_length >= options.layer_edge_ratio * q.min_edge_length;
    }
  }
  if (tets == 0) return Status::Failure("recipe sliver: the mesh has no tets");

  // A layer is a sheet of many stretched cells. A few stretched cells on their own are poor
  // cells the formula keeps, not a layer: holding their vertices would freeze the bad cells
  // around them (the part mesh: 25 such cells in groups of at most 4; holding them lowered the
  // worst mean ratio 0.42 -> 0.36). So groups connected through shared facets count only from
  // layer_min_cells cells (boundary_layer.h; here a group need not touch the boundary).
  {
    BoundaryLayerOptions lo;
    lo.edge_ratio = options.layer_edge_ratio;
    lo.max_angle_deg = 180;  // the candidates are the cells the formula keeps (c < 1/2)
    lo.min_cells = options.layer_min_cells;
    lo.require_boundary = false;
    lo.simplices_only = false;
    layer = find_boundary_layer(*mesh, lo, &layer);
  }

  // The layer's outer surface is held: vertices of layer cells that also belong to another
  // element. F alone would move them: a sliver's barrier term grows without bound as it
  // flattens, a layer cell's keep term is ~1e-3 for a 5 % change, and the minimiser of F shears
  // the layer's outer cells (sliver_test.cc, TheFormulaAloneMovesTheBoundaryLayer). Inside the
  // layer nothing pulls (every cell there is at its target and has c ~ 0), so the layer keeps
  // its shape; its vertices on the domain boundary slide like all others.
  std::vector<char> fixed = options.fixed;
  if (fixed.empty()) fixed.assign(mesh->num_vertices(), 0);
  if (static_cast<int>(fixed.size()) != mesh->num_vertices())
    return Status::Failure("recipe sliver: fixed-vertex flags: one per vertex expected");
  if (!options.slide) {
    const std::vector<char> boundary = boundary_vertex_mask(*mesh);
    for (std::size_t v = 0; v < fixed.size() && v < boundary.size(); ++v) fixed[v] |= boundary[v];
  }
  result->layer_cells = 0;
  result->held_vertices = 0;
  {
    std::vector<char> in_layer(mesh->num_vertices(), 0), outside(mesh->num_vertices(), 0);
    for (int cell = 0; cell < num_cells; ++cell) {
      if (!mesh->is_element(cell)) continue;
      result->layer_cells += layer[cell];
      std::vector<char>& mark = layer[cell] ? in_layer : outside;
      for (int i = 0; i < mesh->cell_size(cell); ++i) mark[mesh->cell(cell)[i]] = 1;
    }
    for (int v = 0; v < mesh->num_vertices(); ++v)
      if (in_layer[v] && outside[v] && !fixed[v]) {
        fixed[v] = 1;
        ++result->held_vertices;
      }
  }

  // c_k per sample point, in the canonical order.
  const SampleSet points = canonical_sample_set(*mesh, options.rule);
  std::vector<double> c_shape(points.size()), c_keep(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double c = cell_c[points.cell[p]];
    c_shape[p] = c;
    // The barrier form |T2 - I|^2 / (2 det T2) is half the seed's |T2 - I|^2 near T2 = I; the
    // factor 2 restores the seed's magnitude (|T2 - I|^2 / det T2 = |T2 - I|^2 (1 + O(T2 - I))).
    c_keep[p] = 2 * (1 - c);
  }

  RecipeGeometry geometry;
  if (options.slide) {
    Status s = build_recipe_geometry(*mesh, options.boundary, &geometry);
    if (!s.ok()) return s;
  }
  StageSpec stage;
  stage.name = "sliver";
  stage.rule = options.rule;
  stage.fixed = fixed;
  stage.solver = options.solver;
  if (options.slide) geometry.apply(&stage);
  TermSpec shape, keep;
  shape.metric = std::shared_ptr<const Metric>(make_metric("shape_cubic_barrier", 3).release());
  shape.target.type = TargetType::kIdealUnitSize;  // the metric is scale invariant
  shape.weights = c_shape;
  keep.metric =
      std::shared_ptr<const Metric>(make_metric("size_shape_orientation_barrier", 3).release());
  keep.target.type = TargetType::kReference;  // the mesh itself, as it is now
  keep.weights = c_keep;
  stage.terms = {shape, keep};
  GuardOptions guard;
  guard.enabled = options.guard_worst;
  guard.guarantees.means = false;
  guard.rounds = options.guard_rounds;
  guard.threads = options.solver.threads;
  guard.progress = options.solver.progress;
  GuaranteeBaseline baseline;
  if (guard.enabled) baseline = guarantee_baseline(*mesh, guard.threads);
  auto solve = [&](const std::vector<char>& held, const std::vector<double>&, int round) {
    StageSpec st = stage;
    st.fixed = held;
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
