#include "tmop/geometry/plane_manifold.h"

#include <glog/logging.h>

#include "tmop/geometry/vec3.h"

namespace tmop {

PlaneManifold::PlaneManifold(const double point[3], const double normal[3]) {
  for (int i = 0; i < 3; ++i) {
    point_[i] = point[i];
    normal_[i] = normal[i];
  }
  CHECK_GT(vec3::normalize(normal_), 0.0) << "PlaneManifold: zero normal";
  vec3::tangent_basis(normal_, u_, v_);
}

void PlaneManifold::Project(const double* x, double* closest) const {
  double r[3];
  vec3::sub(x, point_, r);
  const double h = vec3::dot(r, normal_);
  for (int i = 0; i < 3; ++i) closest[i] = x[i] - h * normal_[i];
}

bool PlaneManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = x[i] + delta[0] * u_[i] + delta[1] * v_[i];
  Project(q, x_plus_delta);
  return true;
}

bool PlaneManifold::PlusJacobian(const double* x, double* jacobian) const {
  for (int i = 0; i < 3; ++i) {
    jacobian[2 * i] = u_[i];
    jacobian[2 * i + 1] = v_[i];
  }
  return true;
}

bool PlaneManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double r[3];
  vec3::sub(y, x, r);
  y_minus_x[0] = vec3::dot(u_, r);
  y_minus_x[1] = vec3::dot(v_, r);
  return true;
}

bool PlaneManifold::MinusJacobian(const double* x, double* jacobian) const {
  for (int i = 0; i < 3; ++i) {
    jacobian[i] = u_[i];
    jacobian[3 + i] = v_[i];
  }
  return true;
}

bool PlaneManifold::Normal(const double* x, double* n) const {
  for (int i = 0; i < 3; ++i) n[i] = normal_[i];
  return true;
}

}  // namespace tmop
