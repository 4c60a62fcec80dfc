// tmop/target/target_factors.h
// The factorisation of a target (or of a Jacobian) into the four factors of the paradigm:
// size, orientation, skew and aspect (Knupp). For a cell of type t and dimension d, with
// v_t = det(ideal_jacobian(t)) (ideal_element.h):
//
//   W = h * R * S,    S = (v_t / det Q)^(1/d) * Q * D
//
//   h  size        scalar > 0, the equivalent edge length: det W = h^d v_t, so h is the edge of
//                  the ideal element of t with the volume of W (local_size's h, target.h)
//   R  orientation d x d rotation (det R = +1)
//   Q  skew        d x d upper triangular with unit columns and positive diagonal: Q^T Q holds
//                  the cosines of the angles between W's columns
//   D  aspect      d x d diagonal, positive, product 1: the relative lengths of W's columns
//
// det S = v_t whatever Q and D, so only h changes det W; W^T W = h^2 S^T S does not see R; Q
// alone sets the angles between W's columns and D alone their length ratios. W's columns are
// the images of the reference axes (dX/dxi_j): for simplices the edges from node 0, for quads
// and hexes half the edges at node 0, for the wedge two base edges and half the height.
//
// Any A with det A > 0 factors this way (A = R U is the QR factorisation with a positive
// diagonal, U = l Q D with l = (prod |A e_j|)^(1/d)) and compose_factors(factor_jacobian(A))
// reproduces A to rounding. The ideal element of t has h = 1, R = I and its own Q, D (the
// equilateral triangle: Q = [[1, 1/2], [0, sqrt3/2]], D = I; the square: Q = D = I).
//
// A and W are d x d row-major, d = cell_dim(type) in {2, 3}, as everywhere in tmop. The factor
// matrices are stored 3 x 3 row-major whatever d (2D uses the top-left 2 x 2 block and keeps
// the rest of the identity), so that a default TargetFactors is the identity in both
// dimensions. Angles are in degrees. Allocation-free; no function aborts.
#ifndef TMOP_TARGET_TARGET_FACTORS_H_
#define TMOP_TARGET_TARGET_FACTORS_H_

#include "tmop/element/cell_type.h"

namespace tmop {

struct TargetFactors {
  double size = 1;                                      // h (length units)
  double orientation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // R (3 x 3 storage)
  double skew[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};         // Q (3 x 3 storage)
  double aspect[3] = {1, 1, 1};                         // diagonal of D, d values
};

// The factors of A (d x d) for a cell of `type`. False, leaving *f unchanged, when det A <= 0
// or A is not finite (no rotation and positive size reproduce it).
bool factor_jacobian(CellType type, const double* A, TargetFactors* f);

// The factors of the ideal element of `type` (size 1, R = I).
TargetFactors ideal_factors(CellType type);

// W = h R S (d x d), S as above. The factors are used as given (a skew that is not unit-column
// upper triangular, or an aspect whose product is not 1, changes det W accordingly).
void compose_factors(CellType type, const TargetFactors& f, double* W);

// Conversions from the values a user gives (constants, fields, functions; target.h):
// orientation: the rotated first axis R e1 (2D: 2 values) or the rotated first and second axes
//   (3D: 6 values; the second is made orthogonal to the first, Gram-Schmidt, and
//   R e3 = R e1 x R e2). Lengths do not matter. False for a zero axis or parallel axes.
bool orientation_from_axes(int d, const double* axes, double* R);  // R: 3 x 3 storage
// skew: the angle between the first two columns (2D: 1 value) or the angles (phi12, phi13,
//   phi23) between columns 1-2, 1-3, 2-3 (3D), in degrees, each in (0, 180). False outside
//   that range or when the three angles do not make a trihedron (no volume, or a volume
//   below 1e-6 of the unit cube's).
bool skew_from_angles(int d, const double* degrees, double* Q);  // Q: 3 x 3 storage
// aspect: d positive relative column lengths (only their ratios matter), normalised to
//   product 1. False for a non-positive or non-finite length.
bool aspect_from_lengths(int d, const double* lengths, double* aspect);

}  // namespace tmop

#endif  // TMOP_TARGET_TARGET_FACTORS_H_
