// tmop/recipes/quadratic_curving.h (internal to recipes/)
// The curved-node stage of the quadratic shape recipe (quadratic_shape.h): where the interior
// non-corner nodes of quadratic cells go once the corners are placed.
//
// Which nodes move: the interior mid-edge, mid-face and centre nodes (not on the boundary, not
// fixed) that are off their corners' interpolation (curved by the input or by untangling), and
// those of the cells within kCurvingRings rings of a cell that has a curved fixed node (a
// curved boundary or interface) or is not valid: curvature a curved boundary needs is spread
// into its neighbours, as Gmsh's elastic analogy (HighOrderOptimize = 3) does, and nowhere else.
// Every other node keeps its place: a straight interior edge away from curved boundaries stays
// straight bit for bit.
//
// The measure, at every sample point: shape_barrier + size_barrier_quadratic toward the
// straight-sided cell (every non-corner node at its corners' interpolation) scaled to the curved
// cell's area (volume) at the start (TargetSpec::cell_scale), under the power objective (when no
// result keeps every guarantee, the plain mean: probe_starts in the .cc). It is zero exactly when
// the curved cell is a rotation of that cell: det J constant over the cell (the det J ratio min /
// max is 1) and the pointwise mean ratio the corner cell's; both barriers are infinite as
// det J -> 0. (Toward the unscaled straight-sided cell, a cell whose curved boundary edge takes
// a third of its area is pushed to grow into its neighbours.) Two starts are solved and the
// better kept (every guarantee kept, every cell valid, then the worst and the sum of the det J
// ratio of the cells touched): the nodes where they are, and the elastic start (the moving nodes on
// their chords, then |T - I|^2 toward the straight-sided cell, a linear least-squares problem: the
// boundary's curvature spread elastically). Measured on the untangled gear tri6 of
// high_order_untangle_test (the first solve from the elastic start; det J ratio worst / mean):
// the size+shape barrier |T - T^-t|^2
// unscaled 0.297 / 0.848, scaled 0.365 / 0.855; shape + size barrier (tau - 1)^2 / tau 0.333;
// shape + size_barrier_quadratic 0.540 / 0.883 (0.3 x shape: 0.709, but pointwise mean ratio
// worst 0.276 where Gmsh's elastic has 0.354); the elastic start alone 0.419 (pointwise 0.151).
//
// Then the guard of quadratic_guard.h against the input (violators held, rounds; when they give
// nothing, the first round's result stepped back, else the nodes as they were), and a last pass
// puts the moved mid-edge nodes back on their chords one by one, smallest offset first, where
// none of its cells loses more than kSnapLoss of its det J ratio or pointwise mean ratio or its
// validity, and every guarantee still holds.
#ifndef TMOP_RECIPES_QUADRATIC_CURVING_H_
#define TMOP_RECIPES_QUADRATIC_CURVING_H_

#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/quadratic_guard.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

// Rings of cells around a curved-boundary or invalid cell whose interior nodes may curve. Gmsh
// t5 at order 2 (13,391 tet10, curved interfaces): 0 / 1 / 2 / 3 rings give det J ratio worst
// 0.660 / 0.678 / 0.677 / 0.677 with 2,648 / 4,575 / 5,581 / 5,668 curved interior edges (the
// gear: 0.540 with any, the untangler's curved nodes move anyway).
constexpr int kCurvingRings = 1;
// The largest loss of a cell's det J ratio or pointwise mean ratio that putting one of its
// mid-edge nodes back on its chord may cost. With 1e-2 the gear (tmop_optimize's default
// recipe) keeps 119 of its 182 interior edges curved, t5 at order 2 3,778 of 13,703 (an earlier
// form of the stage: 1e-3 / 1e-2 / 3e-2 kept 176 / 144 / 121 on the gear, det J ratio mean
// 0.884 / 0.883 / 0.882).
constexpr double kSnapLoss = 1e-2;

// The stage above on `mesh` (corners placed; boundary: the vertices that never move, the
// boundary mask and the caller's fixed nodes; input: the guard's baseline). Its stages are
// appended to result->stages. Leaves the nodes as they were when nothing keeps every guarantee.
void curve_interior_nodes(Mesh* mesh, const ShapeOptions& options, const RecipeGeometry* geometry,
                          const std::vector<char>& boundary, const QuadraticBaseline& input,
                          RecipeResult* result);

// After untangling (recipes/untangle.h): the same stage on an untangled quadratic mesh with
// validity as its only guarantee (the untangled cells are the untangler's work, not the user's
// input), so curvature the untangler put where a cell does not need it for validity or a curved
// boundary is taken back before the shape stage takes this mesh as its baseline. shape: the
// shape stage's options (fixed nodes, geometry, extra sample points). No-op for meshes that
// use_quadratic_shape rejects.
void curve_untangled_nodes(Mesh* mesh, const ShapeOptions& shape, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_QUADRATIC_CURVING_H_
