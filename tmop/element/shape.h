// tmop/element/shape.h
// Reference elements (Gmsh's): line [-1,1]; tri (0,0) (1,0) (0,1); quad [-1,1]^2; tet (0,0,0)
// (1,0,0) (0,1,0) (0,0,1); hex [-1,1]^3; wedge = tri x [-1,1] (xi, eta in the triangle, zeta in
// [-1,1]); pyramid: base [-1,1]^2 at zeta = 0, apex (0,0,1). Node order is Gmsh's (cell_type.h);
// tests/element/gmsh_agreement_test.cc checks both against the gmsh module itself.
// Bases: Lagrange (tensor products of 1D Lagrange for quad/hex, barycentric for simplices,
// triangle x line for the wedges: wedge6 tri3 x line2, wedge18 tri6 x line3); serendipity for
// quad8, hex20 and wedge15 (shape_families.h gives the formulas); the pyramid uses Gmsh's rational
// basis N = (1 - zeta +- xi)(1 - zeta +- eta) / (4 (1 - zeta)) for the base nodes, N = zeta for the
// apex.
//
// All functions here are allocation-free, have no failure mode (type must be a valid enum value,
// arrays large enough) and are safe to call from many threads.
#ifndef TMOP_ELEMENT_SHAPE_H_
#define TMOP_ELEMENT_SHAPE_H_

#include "tmop/element/cell_type.h"

namespace tmop {

// Reference coordinates of local node `node` (3 values; unused trailing ones are 0).
const double* reference_node(CellType type, int node);

// Shape-function values N_i(xi), i < num_nodes. xi has cell_dim(type) entries (3 may be passed).
void shape_values(CellType type, const double* xi, double* N);

// Reference gradients dN_i/dxi_j, row-major num_nodes x cell_dim(type).
// The pyramid's rational functions are singular at the apex: do not ask for the gradient there.
void shape_gradients(CellType type, const double* xi, double* dN);

// Jacobian A = dX/dxi = sum_i x_i (grad N_i)^T at xi, row-major space_dim x cell_dim(type).
// node_coords holds the cell's nodes, num_nodes x space_dim, row-major.
void cell_jacobian(CellType type, const double* node_coords, int space_dim, const double* xi,
                   double* A);

}  // namespace tmop

#endif  // TMOP_ELEMENT_SHAPE_H_
