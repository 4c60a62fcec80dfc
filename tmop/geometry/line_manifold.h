// tmop/geometry/line_manifold.h
// LineManifold: the infinite straight line through `point` with direction `direction`, in 2D or
// 3D (ambient = dim, tangent 1). Chart: arc length along the unit direction a;
// Plus(x, d) = p + (a.(x - p) + d) a (the projection of x moved by d), Minus(y, x) = a.(y - x).
// Both are exact. Construction: dim 2 or 3, non-zero direction (CHECK).
#ifndef TMOP_GEOMETRY_LINE_MANIFOLD_H_
#define TMOP_GEOMETRY_LINE_MANIFOLD_H_

#include "tmop/geometry/geometry_manifold.h"

namespace tmop {

class LineManifold : public GeometryManifold {
 public:
  // point and direction have dim values.
  LineManifold(int dim, const double* point, const double* direction);

  int AmbientSize() const override { return dim_; }
  int TangentSize() const override { return 1; }
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  bool PlusJacobian(const double* x, double* jacobian) const override;  // dim x 1
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  bool MinusJacobian(const double* x, double* jacobian) const override;  // 1 x dim

  void Project(const double* x, double* closest) const override;

 private:
  int dim_;
  double point_[3] = {0, 0, 0}, dir_[3] = {0, 0, 0};
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_LINE_MANIFOLD_H_
