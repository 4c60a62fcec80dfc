// tmop/mesh/orientation.h
// Orientation of the elements of planar 2D meshes (space_dim 2, triangles / quads) and volume
// meshes (3D cells in space_dim 3). tmop's convention is Gmsh's: det J > 0 for a valid element.
// Some files (and some mesh generators) use the opposite convention for all cells; reorient()
// turns such a mesh into tmop's.
//
// Which convention a mesh uses is decided by its boundary, not by a vote of its cells: the
// signed volume (2D: area) enclosed by the boundary facets, each in the outward order its element
// gives it (cell_type.h), is positive in tmop's convention and negative in the opposite one.
// Moving nodes inside the boundary does not change it, so a tangle cannot outvote it (a box whose
// interior block is mirrored through its mid-plane has 50-70 % of its tets negative and still
// encloses +1 x its volume). Only when the boundary gives no evidence (it encloses ~0: the mesh is
// not consistently connected, or has no boundary) do the cells' signs decide, by majority.
//
// The sign of a cell is taken from its linear part (corners only): det J of the corner-only map
// at every corner (the pyramid's apex, where that map has no Jacobian, uses the four tets made by
// the apex and three consecutive base corners). Curved quadratic cells can still be inverted
// between corners: use the Bezier certificate (element/bezier.h) for that.
#ifndef TMOP_MESH_ORIENTATION_H_
#define TMOP_MESH_ORIENTATION_H_

#include <string>

#include "tmop/mesh/mesh.h"

namespace tmop {

struct OrientationReport {
  int positive = 0;       // det > 0 at every corner
  int negative = 0;       // det < 0 at every corner
  int mixed_or_zero = 0;  // some corners of each sign, or a zero det (degenerate / tangled)
  // Signed volume (3D) or area (2D) enclosed by the boundary facets (their corners; quad facets
  // as four triangles around their centroid), in the mesh's units. > 0 in tmop's convention.
  double boundary_measure = 0;
  // Sum of the absolute contributions of the facets to boundary_measure (taken about the centre
  // of the bounding box): the scale that says whether boundary_measure is evidence (below).
  double boundary_scale = 0;
  int dim = 0;  // 2 or 3 when the elements have an orientation sign, else 0

  enum class Evidence {
    kNone,      // no elements with an orientation sign (surface meshes, curves, empty)
    kBoundary,  // |boundary_measure| >= 1e-6 boundary_scale: its sign decides
    kCells,     // the boundary encloses ~0: the majority of the cells' signs decides
  };
  Evidence evidence() const;
  // True when the evidence says the mesh uses the opposite convention.
  bool opposite_convention() const;
  // The elements counted (positive + negative + mixed_or_zero).
  int num_elements() const { return positive + negative + mixed_or_zero; }
};

// Counts elements (cells with dim == mesh.dim()) by sign and measures the boundary's enclosed
// volume. Meshes that are neither planar 2D (space_dim 2) nor volume (surfaces in 3D, curves)
// have no orientation sign here: everything is 0 and evidence() is kNone.
OrientationReport check_orientation(const Mesh& mesh);

// One line saying what the report decided and why, e.g. "opposite convention: the boundary
// encloses -1 (in the mesh's units^3) as its cells orient it; 49,577 of 98,565 cells negative".
std::string describe_orientation(const OrientationReport& report);

// Applies to every element a node permutation that reverses its orientation while keeping it the
// same geometric element (quadratic nodes move with their edges and faces). Lower-dimensional
// cells are left alone. Calling it twice restores the original node order.
void reorient(Mesh* mesh);

// The permutation reorient() uses: new local node i is old local node perm[i]
// (cell_num_nodes(type) entries).
const int* reorient_permutation(CellType type);

}  // namespace tmop

#endif  // TMOP_MESH_ORIENTATION_H_
