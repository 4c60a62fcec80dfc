// tmop/recipes/quadratic_shape.h
// Shape improvement of quadratic meshes (tri6, quad9, tet10, hex27) through their corner mesh.
//
// Optimising every sample point of a quadratic cell lets the solver buy corner-mesh quality
// with curvature: on Gmsh's t5 at order 2 (13,391 straight-sided tet10) it lowered the worst
// corner-tet mean ratio 0.367 -> 0.249, made 3 slivers and curved 13,464 straight interior
// edges. Here the shape stage runs on the corner (linear) mesh instead - the same vertex array,
// each quadratic cell replaced by its corner cell (tri3, quad4, tet4, hex8), so the mid-edge,
// mid-face and centre nodes are in no residual block - through improve_shape and its guard.
// Then every other node is placed from the moved corners: a mid-edge node at the new chord's
// midpoint plus its input offset from the old chord's midpoint, turned and scaled with the chord
// (a straight edge stays straight to round-off, a curved one keeps its shape); mid-face and
// centre nodes at the corners' linear interpolation plus their input offset. Sliding boundary
// nodes that are not corners are then projected onto their curve / surface (boundary
// constraints built from the quadratic mesh: the polylines and triangles through its corners
// and mid nodes, or the user's geometry), so they stay on the geometry.
//
// Guarantees, checked per cell after the placement, against the input's worst of the cell's
// type (quadratic cells only; tolerance ShapeOptions::guard_tolerance):
//   - validity: a cell the Bernstein certificate proves valid (tri6, tet10; the other types:
//     det J > 0 at every sample point) stays so;
//   - corner cell: mean ratio (tri3 / tet4 corners) or scaled Jacobian (quad4 / hex8 corners)
//     not below the input's worst; tets: dihedral angles inside the input's range, no new sliver
//     (max dihedral > 150 and min < 10 degrees);
//   - curved cell: pointwise mean ratio (simplices: minimum over the sample points) and the
//     det J ratio min / max over the sample points not below the input's worst;
//   - the mean over the cells of the type of each of these does not fall.
// Cells that break one are held at their input shape (their corners join the fixed set) and the
// corner stage solves again from the input, at most guard_rounds + 2 times. Where a mean fell,
// the cells whose own measure fell most are held until they give back the shortfall; cells next
// to a cell whose input is below the round's worst are held only when the others cannot give
// back half of it (holding them lowers the worst again). Each round's violators are first stepped
// back towards the round's start over rings of neighbours without a solve (quadratic_guard.h);
// when that keeps every guarantee the next round starts there with them held. If a round limit
// is reached the last state that kept every guarantee (at first the input) is kept. With
// guard_worst false only validity is enforced.
//
// Then the curved-node stage (quadratic_curving.h) moves the interior non-corner nodes that are
// curved or belong to cells next to a curved boundary (or an invalid cell): shape_barrier +
// size_barrier_quadratic toward the straight-sided cell scaled to the curved cell's area, which
// raises the det J ratio, under the same guard, then puts back on their chords the mid-edge nodes
// whose curvature buys less than 1e-2 of a cell's measure. Straight edges away from curved
// boundaries stay straight, boundary nodes stay where they are. Gear tri6 (untangled; default
// recipe): det J ratio worst 0.185 -> 0.540 (Gmsh's elastic curving: 0.410); t5 at order 2
// 0.129 -> 0.678 (Gmsh: 0.364).
//
// Measured (tmop_optimize, default recipe, one thread): Gmsh t5 -order 2 (13,391 tet10): corner
// mean ratio worst 0.367 -> 0.387, mean 0.784 -> 0.804, dihedral 11.75..156.64 -> 13.16..154.33
// deg, 0 slivers, 828 curved (interface) edges kept, every straight edge straight, 2.5 s (the
// all-sample-point stage: 0.249, 3 slivers, 13,464 interior edges curved where the input had 828,
// 34 s).
//
// Used by improve_shape for volume and planar meshes with quadratic elements; surface meshes
// (tri6 in 3D) keep the all-sample-point stage.
#ifndef TMOP_RECIPES_QUADRATIC_SHAPE_H_
#define TMOP_RECIPES_QUADRATIC_SHAPE_H_

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

// True when improve_shape should take the corner-mesh path: the mesh has quadratic element
// cells and is not a surface mesh.
bool use_quadratic_shape(const Mesh& mesh);

// As improve_shape (same options and failure behaviour), by the corner-mesh method above.
Status improve_quadratic_shape(Mesh* mesh, const ShapeOptions& options, RecipeResult* result);

// The corner mesh of `mesh`: the same vertices (and point data), every cell replaced by the
// cell of its corners (cell_info(type).linear), regions and entities kept.
Mesh corner_mesh(const Mesh& mesh);

// Per-cell measures the guarantees above are stated in (NaN where one does not apply).
struct QuadraticCellMeasures {
  bool valid = false;          // certified (tri6, tet10) or det J > 0 at every sample point
  double corner = 0;           // corner cell: mean ratio (simplices) or scaled Jacobian
  double min_dihedral = 0;     // corner tet, degrees (NaN for other types)
  double max_dihedral = 0;     //
  double pointwise_ratio = 0;  // simplices: min over the sample points of the mean ratio of T
  double det_ratio = 0;        // min / max of det J over the sample points (default rule)
};
// `nodes`: cell_num_nodes(type) x 3 (z = 0 for planar meshes).
QuadraticCellMeasures quadratic_cell_measures(CellType type, const double* nodes);

}  // namespace tmop

#endif  // TMOP_RECIPES_QUADRATIC_SHAPE_H_
