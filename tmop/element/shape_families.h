// tmop/element/shape_families.h (internal to element/)
// The bases of the serendipity types, of the quadratic wedges and of the quadratic pyramids, kept
// apart from shape.cc so each file stays one family. Inputs: reference coordinates xi (Gmsh's
// reference elements, shape.h); outputs: values N (num_nodes) and gradients dN (num_nodes x dim,
// row-major), both always written. Node order is Gmsh's (cell_type.h). Allocation-free,
// thread-safe.
#ifndef TMOP_ELEMENT_SHAPE_FAMILIES_H_
#define TMOP_ELEMENT_SHAPE_FAMILIES_H_

namespace tmop {
namespace internal {

// Serendipity quad8 (dim 2) / hex20 (dim 3) on [-1,1]^dim. nodes: the type's reference nodes
// (corners first, then mid-edge nodes, which have exactly one zero coordinate).
//   corner s (s_j = +-1):  prod_j (1 + s_j x_j) / 2^dim * (sum_j s_j x_j - (dim - 1))
//   edge node along axis a: (1 - x_a^2) prod_{j != a} (1 + s_j x_j) / 2^(dim-1)
void serendipity_tensor(int dim, int num_nodes, const double (*nodes)[3], const double* xi,
                        double* N, double* dN);

// Serendipity wedge15: L = triangle barycentrics, z = zeta, z_k = +-1 the corner's level:
//   corner k:                 L_k (1 + z_k z) (2 L_k + z_k z - 2) / 2
//   triangle edge (a, b):     2 L_a L_b (1 + z_k z)
//   vertical edge at corner k: L_k (1 - z^2)
void wedge15(const double* xi, double* N, double* dN);

// Lagrange wedge18 = (tri6 basis in xi, eta) x (line3 basis in zeta): each node is the product of
// the tri6 function and the line3 function whose nodes share its reference coordinates.
void wedge18(const double* xi, double* N, double* dN);

// The quadratic pyramids (Gmsh's bases, checked against gmsh in the element tests). With
// s = 1 - zeta, u = xi / s, v = eta / s the Lagrange pyramid14 spans u^i v^j s^k for
// 0 <= i, j <= k <= 2 (rational in xi, eta, zeta: it contains P2 and, e.g., xi eta / s); the
// serendipity pyramid13 drops u^2 v^2 s^2. The nodal basis is these monomials times the inverse
// of their values at the nodes (computed once). As for pyramid5, the apex (s = 0) is a singular
// point of the gradients: there the values take their limits and the gradients of the rational
// terms are set to 0.
void quadratic_pyramid(bool complete, const double* xi, double* N, double* dN);

}  // namespace internal
}  // namespace tmop

#endif  // TMOP_ELEMENT_SHAPE_FAMILIES_H_
