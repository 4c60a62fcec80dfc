// tmop/element/bezier.h
// Bernstein (Bezier) coefficients of det J over a cell. det J is a polynomial in the reference
// coordinates; written in the Bernstein basis of its degree, every value of det J inside the cell
// is a convex combination of the coefficients (the basis is non-negative and sums to 1), so
// min(coefficients) > 0 proves the cell valid everywhere (a certificate) and
// min(coefficients) <= min det J <= max det J <= max(coefficients).
//
// Supported types, polynomial space of det J and coefficient count:
//   tri3  constant                    1      tet4   constant                    1
//   tri6  degree 2 on the triangle    6      tet10  degree 3 on the tet        20
//   quad4 bilinear (1,1)              4      quad9  degree (3,3)               16
//   hex8  degree (2,2,2)             27      wedge6 degree 1 (tri) x 2 (zeta)   9
// Others (lines, pyramid5 which is rational, hex27 with 216 coefficients) return 0: rely on
// sample points there.
//
// Coefficient k belongs to a lattice point of the reference element (jacobian_bezier_point);
// where that point is a corner the coefficient equals det J at the corner. Lattice order: the
// simplex part varies fastest (xi, then eta, then zeta with i + j + k <= p), then the tensor axes
// (xi, eta, zeta for quad/hex; zeta for the wedge), each at -1 + 2m/p, m = 0..p.
//
// Cost: det J at every lattice point plus one small matrix-vector product with an inverse
// collocation matrix built once per type (the only allocation, at first use, thread-safe).
#ifndef TMOP_ELEMENT_BEZIER_H_
#define TMOP_ELEMENT_BEZIER_H_

#include "tmop/element/cell_type.h"

namespace tmop {

constexpr int kMaxBezierCoefficients = 27;

// Number of coefficients for `type`; 0 when the type has no certificate here (then rely on
// sample points).
int jacobian_bezier_count(CellType type);

// node_coords: num_nodes x dim row-major with dim == cell_dim(type) (planar 2D / volume 3D).
// Writes jacobian_bezier_count(type) coefficients to out; returns their count.
int jacobian_bezier_coefficients(CellType type, const double* node_coords, double* out);

// Reference coordinates (3 values, unused ones 0) of the lattice point of coefficient k,
// 0 <= k < jacobian_bezier_count(type): where a negative coefficient says the cell is in danger.
void jacobian_bezier_point(CellType type, int k, double* xi);

}  // namespace tmop

#endif  // TMOP_ELEMENT_BEZIER_H_
