// tmop/recipes/sliver.h
// Sliver removal that preserves a boundary layer (viscous CFD meshes): the seed's formula
//   F = sum_k c_k (|T1|^3 / (3 sqrt3 det T1) - 1) + (1 - c_k) |T2 - I|^2,
//   T1 = A W1^-1, W1 the regular tet (shape_cubic_barrier_3d, mu_304),
//   T2 = A W2^-1, W2 the initial mesh's Jacobian (size_shape_orientation; in its barrier form
//        |T2 - I|^2 / det T2, equal to |T2 - I|^2 to second order at T2 = I, because the input
//        must be valid: see below),
//   c_k = 1 / (1 + exp(-steepness (d_k - threshold))), d_k the element's max dihedral angle in
//        the initial mesh, degrees.
// Good elements (small max dihedral: the boundary layer's flat tets included) have c_k ~ 0 and
// keep their initial Jacobian, size and orientation; slivers (max dihedral near 180) have
// c_k ~ 1 and are driven to the regular shape. Boundary vertices slide on their geometry by
// default. Tets only (other cells in the mesh keep c_k = 0, i.e. their initial shape).
//
// Boundary layer: F alone does not keep it. Where a sliver shares a vertex with a layer cell,
// the sliver's barrier term (unbounded as it flattens) outweighs the layer cell's keep term
// (~1e-3 for a 5 % change), and the minimiser of F shears the layer's outer cells
// (docs/recipes/sliver.md has the numbers). So the recipe finds the layer cells (kept cells
// whose longest edge is >= layer_edge_ratio times their shortest: flat because one edge is
// short, where a sliver is flat with no short edge) and holds the vertices the layer shares with
// other cells; F is minimised over the remaining vertices exactly as written.
//
// The input must be valid: the second term's targets are its own Jacobians, which an inverted
// element would carry into the result (run --recipe=auto first).
#ifndef TMOP_RECIPES_SLIVER_H_
#define TMOP_RECIPES_SLIVER_H_

#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct SliverOptions {
  // The logistic blend of the two terms: c = 1 / (1 + exp(-steepness (d - threshold))), d the
  // max dihedral angle in degrees. The seed's values: 0.4394 per degree around 135 degrees.
  double steepness = 0.4394;
  double threshold_deg = 135;
  // Layer cells: cells the formula keeps (c < 1/2) whose longest edge is at least this many
  // times their shortest. A boundary layer's cells are flat because one edge (the layer height)
  // is short; a sliver is flat with no short edge. The vertices a layer shares with other cells
  // are held, because the sliver term's barrier can always outpull the keep term of a layer
  // cell (docs/recipes/sliver.md). 0: no layer cells, nothing held.
  double layer_edge_ratio = 3;
  // Stretched cells count as a layer only in groups (connected through shared facets) of at
  // least this many cells; fewer are poor cells the formula keeps, and their vertices move.
  int layer_min_cells = 100;
  // Boundary vertices slide on the input's own boundary (or boundary.geometry); false: fixed.
  bool slide = true;
  BoundaryOptions boundary;
  // Per-vertex flags (1 = fixed) added to the geometry's corners (sliding) or to the boundary
  // (fixed) and to the held layer vertices.
  std::vector<char> fixed;
  SampleRule rule = SampleRule::kDefault;
  SolverOptions solver;
  // The worst-element guarantees (recipes/guard.h; type means are not guarded: the recipe keeps
  // good cells, it does not improve the average). false: one solve, unchecked.
  bool guard_worst = true;
  int guard_rounds = 4;
};

// Fails, leaving the mesh unchanged, on a mesh without tets, an inverted input, or a bad
// geometry.
Status remove_slivers(Mesh* mesh, const SliverOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_SLIVER_H_
