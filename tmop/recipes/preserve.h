// tmop/recipes/preserve.h
// Deforming-mesh preservation: the boundary moves to new positions and the interior follows so
// that every element keeps the shape, size and orientation it had ("keep what is there").
//
// The targets are the Jacobians of the original mesh (TargetType::kReference), so the ideal
// of every element is itself before the motion. Moving only the boundary usually inverts the
// elements next to it; the recipe then (1) untangles toward the reference (tmop::untangle with
// the reference target: the regularised energy pulls the inverted elements back to their
// original shape, not to an ideal one), and (2) runs a barrier stage with size_shape_barrier
// |T - T^-t|^2 against the reference, which spreads the deformation over the interior.
//
// Inputs: *mesh = the original mesh (its coordinates are the reference). The new positions of
// the fixed vertices come from options.moved (a mesh with the same vertices and cells: its
// coordinates of the fixed vertices are used, and the interior starts from its coordinates too)
// or options.move (a function applied to the fixed vertices; the interior starts where it was).
// Exactly one of the two must be given.
// Output: the mesh in place (fixed vertices at their new positions, the interior optimized);
// *result with the untangling stage (when anything was inverted) and the barrier stage.
// Failure: neither or both motions given, topology mismatch, an unknown metric, or untangling
// that fails (the message names the cells; the mesh then holds the best state reached, with the
// boundary moved). A singular original element (zero area) cannot be a target: failure.
#ifndef TMOP_RECIPES_PRESERVE_H_
#define TMOP_RECIPES_PRESERVE_H_

#include <functional>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct PreserveOptions {
  // The moved mesh: same vertex and cell numbering as *mesh. Not owned; must outlive the call.
  // nullptr when `move` is used.
  const Mesh* moved = nullptr;
  // Or: new position of a fixed vertex: (vertex index, original coordinates in, new out), both
  // space_dim values.
  std::function<void(int vertex, const double* x, double* y)> move;

  // Metric of the barrier stage. Default "size_shape_barrier": keeps shape and size, lets
  // elements rotate with the boundary (a bent boundary turns its elements).
  // "size_shape_orientation_barrier" also keeps orientation: use it for small motions where
  // elements should stay aligned (boundary layers, anisotropic meshes).
  std::string metric = "size_shape_barrier";

  // Power-mean order p >= 1 of the barrier stage's objective (optimize/stage.h StageSpec::power).
  // Default 2: the motion concentrates distortion in a few elements next to the moved boundary,
  // and a plain mean (p = 1) lets those get worse to keep the many others exact; p = 2 weights
  // them up. Use 1 for the cheapest run.
  double power = 2.0;

  // Where the metric is evaluated. Default kDefault (quads / hexes at corners).
  SampleRule rule = SampleRule::kDefault;

  // Untangling energy parameters (untangle.h); the defaults work for boundary motions of up to a
  // few element layers.
  double untangle_theta = 0.5;
  int untangle_max_rounds = 60;

  // Per-vertex flags (1 = fixed: these take the new positions), num_vertices() entries. Empty
  // (default): the boundary vertices.
  std::vector<char> fixed;

  SolverOptions solver;
};

Status preserve(Mesh* mesh, const PreserveOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_PRESERVE_H_
