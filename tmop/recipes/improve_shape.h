// tmop/recipes/improve_shape.h
// Shape improvement: move the free vertices so that every element is as close as possible to
// the ideal element's shape (equilateral triangle, square, regular tet, cube, right prism,
// pyramid), whatever its size. Barrier metric by default, so a valid mesh stays valid.
//
// The objective is the power objective of order 2 of the shape metric (ShapeOptions::power,
// StageSpec::power; p = 1 is the plain mean), one Ceres solve either way; the result
// follows translation, scaling and rotation of the input (stage.h). Even so a mean can let the
// worst element get worse while the average improves, so the recipe checks every cell afterwards
// against the input's worst quality (the minimum tmop_quality prints: mean ratio for simplices,
// scaled Jacobian otherwise): cells that fell below it are held at their input shape (their
// vertices fixed) and the stage solves again from the input, until no cell is below (guard_rounds
// at most; then the input is kept). So the worst element never gets worse, and the rest of the mesh
// keeps its improvement.
#ifndef TMOP_RECIPES_IMPROVE_SHAPE_H_
#define TMOP_RECIPES_IMPROVE_SHAPE_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct ShapeOptions {
  // Metric name (metric_names()); empty picks the default shape barrier metric of the
  // dimension: shape_barrier_2d (mu_2) in 2D, shape_barrier_3d (mu_303,
  // |T|^2 / (3 tau^(2/3)) - 1) in 3D.
  std::string metric;
  TargetSpec target;  // default: ideal shape, equal size (size does not matter to shape)
  SampleRule rule = SampleRule::kDefault;
  SampleSet extra_points;  // appended to the rule's points (see StageSpec::extra_points)
  // Power order p >= 1 (StageSpec::power); 0 = the default, 2. The plain mean (p = 1) is the
  // fastest (100k tets: 9 iterations against 14) but lets the worst elements lag (100k tets:
  // mean ratio min 0.36 vs 0.44, docs/benchmarks.md), and with a sliding boundary it can leave
  // the worst dihedral worse than a fixed boundary does.
  double power = 0;
  // Never return a mesh whose worst element is worse than the input's: no cell's headline
  // quality (mean ratio for simplices, scaled Jacobian for the other types) may end below the
  // input's minimum by more than guard_tolerance (absolute; qualities are in (0, 1]). Cells that
  // would are held at their input shape, at most guard_rounds re-solves (see above).
  bool guard_worst = true;
  double guard_tolerance = 1e-6;
  int guard_rounds = 4;
  std::vector<char> fixed;  // per-vertex flags; empty = boundary fixed (or sliding, below)
  // Boundary vertices slide on their curves and surfaces (corners stay fixed): the input's own
  // boundary, or boundary.geometry. Surface meshes always slide on their surface.
  bool slide = false;
  BoundaryOptions boundary;
  // A geometry already built for this mesh (e.g. by the untangle recipe before this stage);
  // when set, slide/boundary are ignored. Not owned.
  const RecipeGeometry* geometry = nullptr;
  SolverOptions solver;
};

// Fails, leaving the mesh unchanged, on an inverted input when the metric is a barrier (the
// message names the inverted cells), on an unknown metric, or when the solver fails.
Status improve_shape(Mesh* mesh, const ShapeOptions& options, RecipeResult* result);

// The metric a recipe uses for `name` (empty = default shape metric) and power p, wrapped in a
// power mean when p != 1. nullptr and a message when the name is unknown.
std::shared_ptr<const Metric> recipe_metric(const std::string& name, int dim, double power,
                                            std::string* error);

}  // namespace tmop

#endif  // TMOP_RECIPES_IMPROVE_SHAPE_H_
