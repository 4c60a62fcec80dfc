#include "tmop/geometry/line_manifold.h"

#include <glog/logging.h>

#include "tmop/geometry/vec3.h"

namespace tmop {

LineManifold::LineManifold(int dim, const double* point, const double* direction) : dim_(dim) {
  CHECK(dim == 2 || dim == 3) << "LineManifold: dim must be 2 or 3";
  for (int i = 0; i < dim; ++i) {
    point_[i] = point[i];
    dir_[i] = direction[i];
  }
  CHECK_GT(vec3::normalize(dir_), 0.0) << "LineManifold: zero direction";
}

void LineManifold::Project(const double* x, double* closest) const {
  double s = 0;
  for (int i = 0; i < dim_; ++i) s += dir_[i] * (x[i] - point_[i]);
  for (int i = 0; i < dim_; ++i) closest[i] = point_[i] + s * dir_[i];
}

bool LineManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  double s = delta[0];
  for (int i = 0; i < dim_; ++i) s += dir_[i] * (x[i] - point_[i]);
  for (int i = 0; i < dim_; ++i) x_plus_delta[i] = point_[i] + s * dir_[i];
  return true;
}

bool LineManifold::PlusJacobian(const double* x, double* jacobian) const {
  for (int i = 0; i < dim_; ++i) jacobian[i] = dir_[i];
  return true;
}

bool LineManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double s = 0;
  for (int i = 0; i < dim_; ++i) s += dir_[i] * (y[i] - x[i]);
  y_minus_x[0] = s;
  return true;
}

bool LineManifold::MinusJacobian(const double* x, double* jacobian) const {
  for (int i = 0; i < dim_; ++i) jacobian[i] = dir_[i];
  return true;
}

}  // namespace tmop
