// tmop/recipes/boundary_layer.h
// Boundary layers of viscous (CFD) meshes: sheets of stretched cells along the boundary whose
// anisotropy is wanted. A mean-ratio objective would flatten them (a 10-layer tet mesh: median
// edge ratio 13.6 -> 9.4 under the plain shape recipe), so recipes find them and keep them.
//
// A layer cell is a simplex whose longest edge is at least `edge_ratio` times its shortest while
// it is not a sliver-like cell: its largest angle (triangles) or dihedral angle (tets) stays
// below `max_angle_deg` (a layer cell is flat because one edge is short; a sliver or needle is
// flat with no short edge). Such cells count only in groups, connected through shared facets,
// of at least `min_cells` cells that touch the boundary: a few stretched cells on their own are
// poor cells to be improved, not a layer. Prisms, hexes and the other non-simplex types are not
// flagged unless simplices_only is false: the recipes keep their aspect through their targets.
#ifndef TMOP_RECIPES_BOUNDARY_LAYER_H_
#define TMOP_RECIPES_BOUNDARY_LAYER_H_

#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

struct BoundaryLayerOptions {
  double edge_ratio = 3;       // <= 0: no layer
  double max_angle_deg = 135;  // tets: max dihedral; triangles: max angle
  int min_cells = 100;
  bool require_boundary = true;  // a group must touch the domain boundary
  bool simplices_only = true;    // false: any cell type may be a layer cell
};

// Per cell (num_cells() entries): 1 for layer cells. `candidate` (optional, per cell) limits the
// cells that may be layer cells (e.g. the sliver recipe's kept cells).
std::vector<char> find_boundary_layer(const Mesh& mesh, const BoundaryLayerOptions& options,
                                      const std::vector<char>* candidate = nullptr);

}  // namespace tmop

#endif  // TMOP_RECIPES_BOUNDARY_LAYER_H_
