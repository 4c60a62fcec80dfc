// tmop/recipes/equal_edge.h
// Equal-edge smoothing: move the free vertices so that every element approaches the ideal
// element (square, equilateral triangle, cube, ...) whose edge length is lambda = the mean edge
// length of the initial mesh. This is the fix for explicit solvers whose time step is set by the
// shortest edge: paved or size-graded quad meshes have a few very short edges, and pulling every
// edge toward the mean lengthens them without inverting anything.
//
// Stage: W = lambda * ideal (TargetType::kMeanEdgeLength), metric size_shape_barrier
// |T - T^-t|^2 (a barrier, invariant to rotation, so elements may turn freely while their size
// and shape are pulled to the target), sampled at the corners of quads and hexes. Size and
// shape compete where the boundary is fixed and fine; an optional second term (shape_barrier,
// which ignores size) guards the shapes so the scaled Jacobian does not pay for the sizes.
//
// Inputs: a valid mesh (nothing inverted; barrier metrics cannot start otherwise), options.
// Output: the mesh moved in place, and *result (stages, worst shape quality before / after).
// Failure: an inverted input (the message names the cells; the mesh is unchanged), an unknown
// metric name, or a solver failure. Because the metric is a barrier, a successful run never
// inverts an element.
#ifndef TMOP_RECIPES_EQUAL_EDGE_H_
#define TMOP_RECIPES_EQUAL_EDGE_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct EqualEdgeOptions {
  // The size+shape metric that pulls elements to lambda * ideal. Default "size_shape_barrier"
  // (|T - T^-t|^2). "size_shape_orientation_barrier" also keeps each element's orientation
  // (use it when the elements are aligned with something, e.g. a boundary layer direction).
  std::string metric = "size_shape_barrier";

  // Weight g of the shape guard term (shape_barrier, |T|^2 / (2 det T) - 1 in 2D) added to the
  // size+shape term: F = sum mu_size_shape + g * sum mu_shape. 0 turns the guard off. Default 1:
  // without it, elements next to a fine fixed boundary get stretched to reach the mean size and
  // their scaled Jacobian drops; raise it when shape matters more than edge uniformity, lower
  // it (toward 0) to equalise edges harder.
  double shape_guard_weight = 1.0;

  // Where the metric is evaluated. Default kCorners: a quad's scaled Jacobian and its validity
  // are decided at its corners, so that is where the barrier must act (simplices have one
  // Jacobian, so the rule does not matter for them).
  SampleRule rule = SampleRule::kCorners;

  // Per-vertex flags (1 = fixed), num_vertices() entries. Empty (default): every boundary vertex
  // is fixed (or slides, below).
  std::vector<char> fixed;
  // Boundary vertices slide on their curves and surfaces (recipe_geometry.h); corners stay.
  bool slide = false;
  BoundaryOptions boundary;

  // Solver settings of the stage (optimize/solver_options.h); defaults suit meshes up to ~1M
  // elements.
  SolverOptions solver;
  // The worst-element guarantees (recipes/guard.h): no cell type's or region's worst element,
  // by its own measures, ends worse than in the input, no new slivers or inverted cells (equal
  // edges trade the average shape, so type means are not guarded). false: one solve, unchecked.
  bool guard_worst = true;
  int guard_rounds = 4;
};

Status equal_edge(Mesh* mesh, const EqualEdgeOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_EQUAL_EDGE_H_
