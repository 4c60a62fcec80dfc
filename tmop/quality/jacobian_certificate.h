// tmop/quality/jacobian_certificate.h
// certify_jacobian: decides the sign of det J over a whole tri6 / tet10 with the Bernstein
// coefficients of det J (element/bezier.h), subdividing where the bound is inconclusive.
//
// The coefficients bound det J from below, but a valid cell can still have a coefficient <= 0.
// Then the reference simplex is split into 4 (triangle: corner triangles + middle) or 8
// (tet: corner tets + 4 around an octahedron diagonal) children, each of which is again a
// quadratic cell (the same map restricted to the child), and its coefficients are tighter
// (the bound converges quadratically under subdivision). The coefficient at a child's corner is
// det J at that point (times the positive child scale), so a corner coefficient <= 0 proves
// det J <= 0 somewhere.
#ifndef TMOP_QUALITY_JACOBIAN_CERTIFICATE_H_
#define TMOP_QUALITY_JACOBIAN_CERTIFICATE_H_

#include "tmop/element/cell_type.h"

namespace tmop {

enum class JacobianSign {
  kPositive,     // det J > 0 everywhere: proven
  kNonPositive,  // det J <= 0 at some point: proven (the cell is inverted or degenerate)
  kUnknown,      // still undecided after max_depth subdivisions (det J's minimum is ~0)
};

// type: tri6 or tet10 (other types return kUnknown). nodes: num_nodes x d row-major, d =
// cell_dim(type) (planar 2D / volume 3D), Gmsh order. max_depth 0 = the plain bound of the whole
// cell. Allocation-free, thread-safe. Cost: one coefficient evaluation for a cell the plain bound
// proves; at most 1 + 4 + ... + 4^max_depth (tri) or 8^k (tet) for hard cells.
JacobianSign certify_jacobian(CellType type, const double* nodes, int max_depth);

}  // namespace tmop

#endif  // TMOP_QUALITY_JACOBIAN_CERTIFICATE_H_
