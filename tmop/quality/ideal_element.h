// tmop/quality/ideal_element.h
// The ideal element of each linear cell type, the reference shape every quality measure compares
// against ("1 = ideal"): all edges of unit length where the type allows it.
//   tri3     equilateral triangle (0,0) (1,0) (1/2, sqrt3/2)
//   quad4    unit square
//   tet4     regular tetrahedron (0,0,0) (1,0,0) (1/2, sqrt3/2, 0) (1/2, sqrt3/6, sqrt(2/3))
//   hex8     unit cube
//   wedge6   right prism with an equilateral base, unit height
//   pyramid5 pyramid with a unit square base and equilateral sides (apex height 1/sqrt2)
// The corners are in Gmsh order and orientation (positive Jacobian). Quadratic types use the ideal
// element of their linear type (straight edges, mid-edge nodes at midpoints). The same elements
// as target/ideal_element.h (which gives W only); quality/ cannot depend on target/, and the
// corner frames need the corner coordinates.
#ifndef TMOP_QUALITY_IDEAL_ELEMENT_H_
#define TMOP_QUALITY_IDEAL_ELEMENT_H_

#include "tmop/element/cell_type.h"

namespace tmop {

// Coordinates (3 values, z = 0 for 2D types) of corner `corner` of the ideal element of
// cell_info(type).linear. CHECK-fails (aborts) for types without an ideal element (vertex, lines).
const double* ideal_corner(CellType type, int corner);

// W = dX/dxi of the affine map from the Gmsh reference element (element/shape.h) onto the ideal
// element, row-major d x d with d = cell_dim(type): the Jacobian the ideal element has at every
// point. Only for types whose linear type is a simplex, quad4 or hex8 (the parents of the
// quadratic types).
const double* ideal_reference_jacobian(CellType type);

}  // namespace tmop

#endif  // TMOP_QUALITY_IDEAL_ELEMENT_H_
