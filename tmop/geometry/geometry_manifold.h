// tmop/geometry/geometry_manifold.h
// GeometryManifold: a ceres::Manifold that is also a piece of boundary geometry (a curve or a
// surface embedded in 2D or 3D space). Besides Ceres's chart (Plus / Minus and their Jacobians)
// it answers the geometric questions the optimizer and the reports ask: the closest point, the
// distance of a point from the geometry, and (surfaces in 3D) the unit normal.
//
// Contract shared by every implementation in this folder:
// - AmbientSize() is the space dimension (2 or 3); Plus(x, delta) is a tangent step followed by
//   an exact projection (analytic geometry) or a walk along the discrete geometry (polylines,
//   triangle meshes), so its result lies on the geometry to round-off.
// - Plus(x, 0) == x and Minus(Plus(x, delta), x) == delta for x on the geometry and small delta.
// - All methods are const and keep no mutable state: one object may serve every vertex of a
//   patch or curve and may be called from several threads at once.
// - Plus / PlusJacobian / Minus / MinusJacobian do not allocate.
#ifndef TMOP_GEOMETRY_GEOMETRY_MANIFOLD_H_
#define TMOP_GEOMETRY_GEOMETRY_MANIFOLD_H_

#include <ceres/manifold.h>

namespace tmop {

class GeometryManifold : public ceres::Manifold {
 public:
  // Closest point of the geometry to x; both have AmbientSize() values. Discrete geometries
  // return the globally closest point (used for points that start off the geometry).
  virtual void Project(const double* x, double* closest) const = 0;
  // Euclidean distance of x from the geometry (>= 0).
  double Distance(const double* x) const;
  // Unit normal of a surface in 3D at (the projection of) x, written to n[3]. Curves have no
  // unique normal: they return false and leave n untouched.
  virtual bool Normal(const double* /*x*/, double* /*n*/) const { return false; }
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_GEOMETRY_MANIFOLD_H_
