// tmop/geometry/plane_manifold.h
// PlaneManifold: the plane through `point` with normal `normal` in 3D (ambient 3, tangent 2).
// Chart: a fixed orthonormal tangent pair (u, v); Plus(x, d) = P(x + d0 u + d1 v) with P the
// orthogonal projection onto the plane, Minus(y, x) = [u.(y - x), v.(y - x)] (exact inverse).
// Construction: normal of any non-zero length (CHECK-fails on a zero normal: programmer error).
#ifndef TMOP_GEOMETRY_PLANE_MANIFOLD_H_
#define TMOP_GEOMETRY_PLANE_MANIFOLD_H_

#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class PlaneManifold : public GeometryManifold {
 public:
  PlaneManifold(const double point[3], const double normal[3]);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 2; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // 3x2 row-major
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 2x3 row-major

  void Project(const double* x, double* closest) const override;
  bool Normal(const double* x, double* n) const override;

  const double* point() const { return point_; }
  const double* normal() const { return normal_; }

 private:
  double point_[3], normal_[3], u_[3], v_[3];
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_PLANE_MANIFOLD_H_
