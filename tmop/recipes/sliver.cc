#include "tmop/recipes/sliver.h"

#include <chrono>
#include <cmath>

#include "tmop/quality/cell_quality.h"

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

  // c_k per sample point from the element's initial max dihedral angle.
  const SampleSet points = canonical_sample_set(*mesh, options.rule);
  std::vector<double> c_shape(points.size()), c_keep(points.size());
  int tets = 0;
  {
    double nodes[kMaxCellNodes * 3];
    int cached = -1;
    double c = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
      const int cell = points.cell[p];
      if (cell != cached) {
        cached = cell;
        const CellType t = mesh->cell_type(cell);
        c = 0;
        if (cell_info(t).linear == CellType::kTet4) {
          ++tets;
          for (int i = 0; i < mesh->cell_size(cell); ++i)
            for (int a = 0; a < 3; ++a) nodes[3 * i + a] = mesh->vertex(mesh->cell(cell)[i])[a];
          const CellQuality q = cell_quality(t, nodes, nullptr);
          c = 1 / (1 + std::exp(-options.steepness * (q.max_dihedral_deg - options.threshold_deg)));
        }
      }
      c_shape[p] = c;
      // The barrier form |T2 - I|^2 / (2 det T2) is half the seed's |T2 - I|^2 near T2 = I; the
      // factor 2 restores the seed's magnitude (|T2 - I|^2 / det T2 = |T2 - I|^2 (1 + O(T2 - I))).
      c_keep[p] = 2 * (1 - c);
    }
  }
  if (tets == 0) return Status::Failure("recipe sliver: the mesh has no tets");

  RecipeGeometry geometry;
  if (options.slide) {
    Status s = build_recipe_geometry(*mesh, options.boundary, &geometry);
    if (!s.ok()) return s;
  }
  StageSpec stage;
  stage.name = "sliver";
  stage.rule = options.rule;
  stage.fixed = options.fixed;
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
  StageResult sr;
  Status s = optimize_stage(mesh, stage, &sr);
  if (!s.ok()) return s;
  result->stages.push_back(sr);
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
