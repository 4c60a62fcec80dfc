// tmop/geometry/projected_curve_manifold.h
// ProjectedCurveManifold: a boundary curve that lies on a user's analytic surface (the rim of an
// open spherical cap given --geometry=sphere:...), as the curve's polyline projected onto the
// surface: vertices slide on the surface, not on the chords between the input's vertices.
//
// Chart: x's parameter is the arc length s(x) of its pre-image q on the polyline, the point of a
// segment where the surface's normal line through x meets it (closest approach of the two
// lines: exact for the analytic surfaces, whose projection moves a point along the normal at its
// image); Plus(x, d) = surface.Project(polyline.PointAt(s(x) + d)), clamped at open ends and
// wrapped on closed curves as PolylineManifold does; Minus(y, x) = s(y) - s(x) (the shorter way
// round on closed curves). The Jacobians are central differences of Plus and Minus (step 1e-7 x
// the curve's length): the surface's projection has no derivative in GeometryManifold.
// Plus(x, 0) = x to round-off for x on the projected curve.
//
// The surface is not owned and must outlive the object (BoundaryConstraints owns both).
// Construction: as PolylineManifold (3D points only).
#ifndef TMOP_GEOMETRY_PROJECTED_CURVE_MANIFOLD_H_
#define TMOP_GEOMETRY_PROJECTED_CURVE_MANIFOLD_H_

#include <vector>

#include "tmop/geometry/geometry_manifold.h"
#include "tmop/geometry/polyline_manifold.h"

namespace tmop {

class ProjectedCurveManifold : public GeometryManifold {
 public:
  ProjectedCurveManifold(const std::vector<double>& points, bool closed,
                         const GeometryManifold* surface);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // 3 x 1
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 1 x 3

  void Project(const double* x, double* closest) const override;

  // Arc length of x's pre-image on the polyline.
  double ArcLength(const double* x) const;

 private:
  PolylineManifold polyline_;
  std::vector<double> points_;      // the polyline's vertices (closed: first not repeated)
  std::vector<double> cumulative_;  // arc length at each vertex, + total
  bool closed_;
  const GeometryManifold* surface_;
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_PROJECTED_CURVE_MANIFOLD_H_
