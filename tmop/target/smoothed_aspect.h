// tmop/target/smoothed_aspect.h
// The "smooth" aspect source of composed targets: the input's intended stretching without its
// noise. Each element cell's metric tensor is M_c = mean over its sample points of
// det(G)^(1/d) P+^T P+, with P = A W_ideal^-1 the map from the ideal element to the cell (A: the
// space_dim x d Jacobian, so surface cells are measured in 3D), G = P^T P and P+ = G^-1 P^T:
// e^T M e is an edge e's squared length in units of the cell's ideal edges, relative to its size.
// M is dimensionless, frame-independent (rotating the mesh rotates M) and the identity on
// ideal-shaped cells. Vertices
// average the tensors of the cells around them (cells of the same linear type only, so a tet
// beside a boundary-layer wedge does not blur the wedge's aspect), cells average their vertices'
// tensors, `passes` times; at a sample point the vertex tensors are interpolated with the corner
// shape functions to M(x). Column j of the target then has the relative length (u^T M u)^(-1/2),
// u the unit direction of column j of the initial Jacobian there: without averaging, exactly
// the column lengths of an affine cell (as the "initial" aspect); a cell of a smoothly graded
// mesh keeps its edge ratios, a vertex pushed off-centre in an otherwise uniform mesh does not.
#ifndef TMOP_TARGET_SMOOTHED_ASPECT_H_
#define TMOP_TARGET_SMOOTHED_ASPECT_H_

#include <vector>

#include "tmop/core/status.h"

namespace tmop {

class Mesh;

class SmoothedAspect {
 public:
  // Fails (with the cell) when a cell's Jacobian is degenerate or inverted at a sample point.
  Status build(const Mesh& initial, int passes = 1);
  // The d relative column lengths (aspect factor values) at reference point xi of cell c of the
  // mesh given to build.
  void aspect(const Mesh& initial, int c, const double* xi, double* out) const;

 private:
  int sd_ = 3;
  // Per linear cell type present: vertex tensors (sd x sd each, row-major), indexed by vertex.
  std::vector<std::vector<double>> vertex_tensor_;
};

}  // namespace tmop

#endif  // TMOP_TARGET_SMOOTHED_ASPECT_H_
