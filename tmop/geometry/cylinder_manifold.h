// tmop/geometry/cylinder_manifold.h
// CylinderManifold: the infinite circular cylinder of radius r around the axis through `point`
// with direction `direction` (ambient 3, tangent 2).
// Chart at x: the radial unit vector n (x's offset from the axis, axial part removed), the
// circumferential t = a x n and the axis a. Plus(x, d) = P(x + d0 t + d1 a) where P keeps the
// axial coordinate and scales the radial part to length r (the closest point: exact).
// Minus(y, x) inverts P exactly: d1 = a.(y - x); the radial part of y is parallel to
// rad(x) + d0 t with the scale fixed by its n component. Minus fails (false) when y is on the far
// half of the cylinder, where the chart does not reach; Plus fails for x on the axis.
// Construction: non-zero direction and radius > 0 (CHECK).
#ifndef TMOP_GEOMETRY_CYLINDER_MANIFOLD_H_
#define TMOP_GEOMETRY_CYLINDER_MANIFOLD_H_

#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class CylinderManifold : public GeometryManifold {
 public:
  CylinderManifold(const double point[3], const double direction[3], double radius);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 2; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // 3x2 row-major
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 2x3 row-major

  void Project(const double* x, double* closest) const override;
  bool Normal(const double* x, double* n) const override;  // away from the axis

  const double* point() const { return point_; }
  const double* axis() const { return axis_; }
  double radius() const { return radius_; }

 private:
  // Offset of x from the axis (perpendicular to it) and x's axial coordinate.
  void radial(const double* x, double* rad, double* axial) const;
  // n, t at x and |rad(x)|; false on the axis.
  bool frame(const double* x, double* n, double* t, double* rad_len) const;
  double point_[3], axis_[3], radius_;
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_CYLINDER_MANIFOLD_H_
