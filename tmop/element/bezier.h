// tmop/element/bezier.h
// Bernstein (Bezier) coefficients of det J over a cell. det J of a tri6 is a degree-2 polynomial
// (6 coefficients), of a tet10 degree 3 (20 coefficients); of a tri3/tet4 a constant (1). Every
// value of det J inside the cell is a convex combination of the coefficients, so
// min(coefficients) > 0 proves the cell valid everywhere (a certificate), and the coefficients at
// the corners equal det J there.
#ifndef TMOP_ELEMENT_BEZIER_H_
#define TMOP_ELEMENT_BEZIER_H_

#include "tmop/element/cell_type.h"

namespace tmop {

constexpr int kMaxBezierCoefficients = 20;

// Number of coefficients for `type`; 0 when the type has no certificate here (then rely on
// sample points).
int jacobian_bezier_count(CellType type);

// node_coords: num_nodes x dim row-major with dim == cell_dim(type) (planar 2D / volume 3D).
// Writes jacobian_bezier_count(type) coefficients to out; returns their count.
int jacobian_bezier_coefficients(CellType type, const double* node_coords, double* out);

}  // namespace tmop

#endif  // TMOP_ELEMENT_BEZIER_H_
