// tmop/geometry/polyline_manifold.h
// PolylineManifold: a polyline curve in 2D or 3D, open or closed, with an arc-length chart
// (ambient = dim, tangent 1). It serves feature curves of volume and surface meshes and the
// boundary polylines of planar meshes.
//
// Chart: s(x) is the arc length of x's closest point on the polyline. Plus(x, d) is the point at
// arc length s(x) + d: it walks across polyline vertices, is clamped to [0, L] on open curves
// and wraps modulo L on closed ones, and lies on a segment exactly (a + t (b - a)). Minus(y, x)
// = s(y) - s(x), on closed curves the shorter way round (in (-L/2, L/2]) - exact. The Jacobians
// are the unit tangent of the segment holding x (one-sided at a polyline vertex).
//
// Locating x is a closest-segment query on a box tree (O(log n), no allocation). Points produced
// by Plus lie on the curve, so a self-approaching curve cannot capture them: their own segment is
// at distance ~0. One object serves all the vertices of its curve; it keeps no per-vertex state.
//
// Construction: points has n * dim values (n >= 2 after dropping repeated consecutive points;
// closed curves need n >= 3). Violations are programmer errors (CHECK).
#ifndef TMOP_GEOMETRY_POLYLINE_MANIFOLD_H_
#define TMOP_GEOMETRY_POLYLINE_MANIFOLD_H_

#include <vector>

#include "tmop/geometry/aabb_tree.h"
#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class PolylineManifold : public GeometryManifold {
 public:
  PolylineManifold(int dim, const std::vector<double>& points, bool closed);

  int AmbientSize() const override { return dim_; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // dim x 1
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 1 x dim

  void Project(const double* x, double* closest) const override;

  // Arc length of x's closest point, in [0, length()).
  double ArcLength(const double* x) const;
  // The point at arc length s (clamped or wrapped as Plus does) -> out[dim].
  void PointAt(double s, double* out) const;
  double length() const { return cumulative_.back(); }
  bool closed() const { return closed_; }
  int num_segments() const { return static_cast<int>(cumulative_.size()) - 1; }

 private:
  // Closest segment to x and the parameter t on it.
  int locate(const double* x, double* t) const;
  const double* point(int i) const { return points_.data() + dim_ * (i == num_points_ ? 0 : i); }

  int dim_;
  bool closed_;
  int num_points_;
  std::vector<double> points_;      // num_points_ * dim_
  std::vector<double> cumulative_;  // arc length at the start of each segment, + total
  std::vector<double> tangent_;     // unit tangent per segment
  AabbTree tree_;
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_POLYLINE_MANIFOLD_H_
