// tmop/geometry/geometry_frame.h
// GeometryFrame: the normalised coordinates the optimizer solves in. Its own header so that
// public headers can name it without pulling in the Ceres-facing manifold declarations.
#ifndef TMOP_GEOMETRY_GEOMETRY_FRAME_H_
#define TMOP_GEOMETRY_GEOMETRY_FRAME_H_

namespace tmop {

// The geometry in the coordinates x' = R (x - centre) / length (centre[3], length > 0, R a
// rotation, row-major) of a mesh that the optimizer normalised; the spec's numbers and the file
// are in the user's units.
struct GeometryFrame {
  double centre[3] = {0, 0, 0};
  double length = 1;
  double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_GEOMETRY_FRAME_H_
