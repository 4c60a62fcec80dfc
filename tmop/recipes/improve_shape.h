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
// vertices fixed) and the stage solves again from the input (recipes/guard.h), per cell type and
// region and for every measure of quality/guarantees.h. So no type's worst element gets worse,
// and the rest of the mesh keeps its improvement.
#ifndef TMOP_RECIPES_IMPROVE_SHAPE_H_
#define TMOP_RECIPES_IMPROVE_SHAPE_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/boundary_layer.h"
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
  // The guarantees (quality/guarantees.h, recipes/guard.h): no cell type's or region's worst
  // element ends worse than in the input (each type by its own measures: mean ratio for
  // simplices, scaled Jacobian for the others, the corner cell and det J ratio for quadratic
  // cells, dihedral angles of tets), no new slivers or inverted cells, and (guard_means) no type's
  // mean falls, each within guard_tolerance (absolute). Cells that would break one are held at
  // their input shape and the stage solves again from the input, at most guard_rounds times;
  // then the largest step back towards the input that keeps them is taken.
  bool guard_worst = true;
  bool guard_means = true;
  double guard_tolerance = 1e-6;
  int guard_rounds = 4;
  // Rounds (before the held ones) that hold nothing but weight the violators' points up x8
  // and solve again from the input (GuardOptions::soft_rounds).
  int guard_soft_rounds = 0;
  // Non-simplex cells (quad, hex, wedge, pyramid; judged by the scaled Jacobian, which sees only
  // angles) are driven to the ideal angles with the input's smoothed aspect (composed aspect
  // "smooth", smoothed_aspect.h) instead of the unit-aspect ideal, when the target is the
  // default (equal_size).
  bool target_aspect_of_input = true;
  // Boundary layers (boundary_layer.h) are kept: their cells' vertices are held.
  bool keep_boundary_layers = true;
  BoundaryLayerOptions boundary_layer;
  std::vector<char> fixed;  // per-vertex flags; empty = boundary fixed (or sliding, below)
  // Boundary vertices slide on their curves and surfaces (corners stay fixed): the input's own
  // boundary, or boundary.geometry. Surface meshes always slide on their surface.
  bool slide = false;
  BoundaryOptions boundary;
  // A geometry already built for this mesh (e.g. by the untangle recipe before this stage);
  // when set, slide/boundary are ignored. Not owned.
  const RecipeGeometry* geometry = nullptr;
  SolverOptions solver;
  // guarantee_baseline(*mesh) of the mesh as given, when the caller has it (tmop_optimize
  // computes it for its own check): the guard takes it instead of computing it again (1M tets:
  // ~80 MB and a pass over the mesh). Not owned; must be of this mesh's current coordinates.
  const GuaranteeBaseline* input_baseline = nullptr;
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
