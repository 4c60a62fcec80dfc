// tmop/mesh/orientation.h
// Orientation of the elements of planar 2D meshes (space_dim 2, triangles / quads) and volume
// meshes (3D cells in space_dim 3). tmop's convention is Gmsh's: det J > 0 for a valid element.
// Some files (and some mesh generators) use the opposite convention for all cells; reorient()
// turns such a mesh into tmop's.
//
// The sign of a cell is taken from its linear part (corners only): det J of the corner-only map
// at every corner (the pyramid's apex, where that map has no Jacobian, uses the four tets made by
// the apex and three consecutive base corners). Curved quadratic cells can still be inverted
// between corners: use the Bezier certificate (element/bezier.h) for that.
#ifndef TMOP_MESH_ORIENTATION_H_
#define TMOP_MESH_ORIENTATION_H_

#include "tmop/mesh/mesh.h"

namespace tmop {

struct OrientationReport {
  int positive = 0;       // det > 0 at every corner
  int negative = 0;       // det < 0 at every corner
  int mixed_or_zero = 0;  // some corners of each sign, or a zero det (degenerate / tangled)
  // True when most elements are negative: the mesh uses the opposite convention.
  bool opposite_convention() const { return 2 * negative > positive + negative + mixed_or_zero; }
};

// Counts elements (cells with dim == mesh.dim()). Meshes that are neither planar 2D nor volume
// (surfaces in 3D, curves) have no orientation sign here: all counts are 0.
OrientationReport check_orientation(const Mesh& mesh);

// Applies to every element a node permutation that reverses its orientation while keeping it the
// same geometric element (quadratic nodes move with their edges and faces). Lower-dimensional
// cells are left alone. Calling it twice restores the original node order.
void reorient(Mesh* mesh);

// The permutation reorient() uses: new local node i is old local node perm[i]
// (cell_num_nodes(type) entries).
const int* reorient_permutation(CellType type);

}  // namespace tmop

#endif  // TMOP_MESH_ORIENTATION_H_
