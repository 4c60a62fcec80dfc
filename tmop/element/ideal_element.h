// tmop/element/ideal_element.h
// The ideal element of each type, with unit edge length where the type allows it: the shape
// every "1 = ideal" quality measure and every ideal-shape target refers to.
//   tri3     equilateral triangle (0,0) (1,0) (1/2, sqrt3/2)
//   quad4    unit square
//   tet4     regular tetrahedron (0,0,0) (1,0,0) (1/2, sqrt3/2, 0) (1/2, sqrt3/6, sqrt(2/3))
//   hex8     unit cube
//   wedge6   right prism with an equilateral base and unit height
//   pyramid5 unit square base, all eight edges of unit length (apex height 1/sqrt2)
// Corners are in Gmsh order with positive Jacobian. Quadratic types use the ideal element of
// their linear type (straight edges, mid-edge nodes at midpoints).
//
// W is the Jacobian dX/dxi of the affine map from the Gmsh reference element (shape.h) onto the
// ideal element: row-major d x d, d = cell_dim(type). The affine map reproduces every type's
// corners exactly (the pyramid's too), so W is the ideal element's Jacobian at every point.
// Types of dimension < 2 have no ideal element: asking for one aborts (a programmer error).
#ifndef TMOP_ELEMENT_IDEAL_ELEMENT_H_
#define TMOP_ELEMENT_IDEAL_ELEMENT_H_

#include "tmop/element/cell_type.h"

namespace tmop {

// Coordinates (3 values, z = 0 for 2D types) of corner `corner` of the ideal element.
const double* ideal_corner(CellType type, int corner);

// W (d*d values, row-major), returned or written to W.
const double* ideal_jacobian(CellType type);
void ideal_jacobian(CellType type, double* W);

// Volume (area in 2D) of the ideal element: a cell's "equivalent edge length" is
// (volume / ideal_volume(type))^(1/d).
double ideal_volume(CellType type);

// Volume of the reference element, so that an affine cell's volume is det(A) * reference_volume.
double reference_volume(CellType type);

}  // namespace tmop

#endif  // TMOP_ELEMENT_IDEAL_ELEMENT_H_
