// tmop/recipes/size_adapt.h
// Size adaptation: every element is pulled toward the ideal shape at a prescribed local size,
// so a graded mesh keeps (or takes on) its grading while the shapes improve.
//
// Sizes come from either
//   - the initial mesh (default): each element's own equivalent edge length
//     h = (volume / ideal_volume)^(1/d) (TargetType::kIdealLocalSize): "keep the grading, fix the
//     shapes", or
//   - a size field (options.size_field names a 1-component point_data array of target edge
//     lengths, interpolated to each sample point: TargetType::kIdealSizeField): "make the mesh
//     follow this size field" within what its topology and fixed boundary allow.
// Metric: size_shape_barrier |T - T^-t|^2 (barrier: a valid mesh stays valid; rotation
// invariant: elements may turn; size and shape are both penalised, so neither is traded away).
//
// Inputs: a valid mesh, options. Output: the mesh moved in place and *result.
// Failure: inverted input (barrier), a missing or non-positive size field, unknown metric, solver
// failure; the mesh is unchanged then.
#ifndef TMOP_RECIPES_SIZE_ADAPT_H_
#define TMOP_RECIPES_SIZE_ADAPT_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct SizeAdaptOptions {
  // Name of a 1-component point_data array of target edge lengths (mesh length units). Empty
  // (default): the local size of the initial mesh.
  std::string size_field;

  // The size+shape metric. Default "size_shape_barrier"; "size_shape_orientation_barrier" also
  // keeps the orientation of the ideal element (axis-aligned squares), which only makes sense
  // for structured, aligned meshes.
  std::string metric = "size_shape_barrier";

  // Power-mean order p >= 1 of the objective (optimize/stage.h StageSpec::power). Default 1:
  // sizes are a mean property; raise to 2 when the worst shapes matter more than the average.
  double power = 1.0;

  // Where the metric is evaluated. Default kDefault (quads / hexes at corners).
  SampleRule rule = SampleRule::kDefault;

  // Per-vertex flags (1 = fixed), num_vertices() entries. Empty (default): the boundary.
  std::vector<char> fixed;
  // Boundary vertices slide on their curves and surfaces (recipe_geometry.h); corners stay.
  bool slide = false;
  BoundaryOptions boundary;

  SolverOptions solver;
};

Status size_adapt(Mesh* mesh, const SizeAdaptOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_SIZE_ADAPT_H_
