// tmop/optimize/coordinate_frame.h
// The frame a stage solves in (docs/architecture.md, data flow step 2), and the element edge
// lengths that set its scale.
#ifndef TMOP_OPTIMIZE_COORDINATE_FRAME_H_
#define TMOP_OPTIMIZE_COORDINATE_FRAME_H_

#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

// The frame a stage solves in: x' = R (x - centre) / length, R a rotation (row-major 3 x 3; the
// leading 2 x 2 block for space_dim 2).
struct CoordinateFrame {
  double centre[3] = {0, 0, 0};
  double length = 1;
  double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};
// What a stage uses by default: the centroid of the vertices, the mean element edge length, and
// for volume and planar meshes (dim == space_dim) the principal axes of the vertex cloud (each
// axis signed by the third moment of the vertices along it, det R = +1). The frame follows the
// mesh when it is translated, scaled or rotated, so the stage sees the same numbers and the
// result follows the transform to round-off (meshes with repeated principal moments, such as
// symmetric grids, leave the axes free: there only translation and scale are exact).
CoordinateFrame normalizing_frame(const Mesh& mesh);
// x' = R (x - centre) / length for every vertex, and back.
void to_frame(const CoordinateFrame& frame, Mesh* mesh);
void from_frame(const CoordinateFrame& frame, Mesh* mesh);

// Mean length over the elements' corner edges (shared edges counted once per cell: good enough
// for a scale; 1 without edges) and, per vertex, the shortest incident edge (+inf if none).
double element_edge_lengths(const Mesh& mesh, std::vector<double>* shortest);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_COORDINATE_FRAME_H_
