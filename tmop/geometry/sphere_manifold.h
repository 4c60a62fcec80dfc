// tmop/geometry/sphere_manifold.h
// SphereManifold: the sphere |x - centre| = radius in 3D (ambient 3, tangent 2).
// Chart at x: n = (x - c)/|x - c| and the deterministic tangent pair (u, v) of n (vec3.h);
// Plus(x, d) = c + r q/|q| with q = x - c + d0 u + d1 v (radial projection, exact to round-off).
// Minus inverts that projection exactly: y - c is parallel to q, and q.n = |x - c| fixes the
// scale, so d = [u, v]^T (y - c) |x - c| / ((y - c).n). Minus fails (returns false) when y is
// not in the open hemisphere around x, where the chart does not reach.
// Construction: radius > 0 (CHECK).
#ifndef TMOP_GEOMETRY_SPHERE_MANIFOLD_H_
#define TMOP_GEOMETRY_SPHERE_MANIFOLD_H_

#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class SphereManifold : public GeometryManifold {
 public:
  SphereManifold(const double centre[3], double radius);

  int AmbientSize() const override { return 3; }
  int TangentSize() const override { return 2; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // 3x2 row-major
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 2x3 row-major

  void Project(const double* x, double* closest) const override;
  bool Normal(const double* x, double* n) const override;  // outward

  const double* centre() const { return centre_; }
  double radius() const { return radius_; }

 private:
  // Outward unit normal and tangent pair at x; false at the centre.
  bool frame(const double* x, double* n, double* u, double* v) const;
  double centre_[3], radius_;
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_SPHERE_MANIFOLD_H_
