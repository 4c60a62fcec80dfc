#include "tmop/geometry/cylinder_manifold.h"

#include <glog/logging.h>

#include "tmop/geometry/vec3.h"

namespace tmop {

CylinderManifold::CylinderManifold(const double point[3], const double direction[3], double radius)
    : radius_(radius) {
  CHECK_GT(radius, 0.0) << "CylinderManifold: radius must be positive";
  for (int i = 0; i < 3; ++i) {
    point_[i] = point[i];
    axis_[i] = direction[i];
  }
  CHECK_GT(vec3::normalize(axis_), 0.0) << "CylinderManifold: zero axis direction";
}

void CylinderManifold::radial(const double* x, double* rad, double* axial) const {
  double r[3];
  vec3::sub(x, point_, r);
  *axial = vec3::dot(r, axis_);
  for (int i = 0; i < 3; ++i) rad[i] = r[i] - *axial * axis_[i];
}

bool CylinderManifold::frame(const double* x, double* n, double* t, double* rad_len) const {
  double axial;
  radial(x, n, &axial);
  *rad_len = vec3::normalize(n);
  if (*rad_len == 0) return false;
  vec3::cross(axis_, n, t);
  return true;
}

void CylinderManifold::Project(const double* x, double* closest) const {
  double rad[3], axial;
  radial(x, rad, &axial);
  if (vec3::normalize(rad) == 0) {
    // On the axis every point of the circle is closest; pick a fixed one.
    double u[3];
    vec3::tangent_basis(axis_, rad, u);
  }
  for (int i = 0; i < 3; ++i) closest[i] = point_[i] + axial * axis_[i] + radius_ * rad[i];
}

bool CylinderManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  double n[3], t[3], len;
  if (!frame(x, n, t, &len)) return false;
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = x[i] + delta[0] * t[i] + delta[1] * axis_[i];
  Project(q, x_plus_delta);
  return true;
}

bool CylinderManifold::PlusJacobian(const double* x, double* jacobian) const {
  double n[3], t[3], len;
  if (!frame(x, n, t, &len)) return false;
  // The radial projection scales circumferential motion by r/|rad(x)| (1 on the cylinder).
  const double s = radius_ / len;
  for (int i = 0; i < 3; ++i) {
    jacobian[2 * i] = s * t[i];
    jacobian[2 * i + 1] = axis_[i];
  }
  return true;
}

bool CylinderManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double n[3], t[3], len;
  if (!frame(x, n, t, &len)) return false;
  double rad_y[3], axial_y, rad_x[3], axial_x;
  radial(y, rad_y, &axial_y);
  radial(x, rad_x, &axial_x);
  const double yn = vec3::dot(rad_y, n);
  if (yn <= 0) return false;
  y_minus_x[0] = len * vec3::dot(rad_y, t) / yn;
  y_minus_x[1] = axial_y - axial_x;
  return true;
}

bool CylinderManifold::MinusJacobian(const double* x, double* jacobian) const {
  double n[3], t[3], len;
  if (!frame(x, n, t, &len)) return false;
  for (int i = 0; i < 3; ++i) {
    jacobian[i] = t[i];
    jacobian[3 + i] = axis_[i];
  }
  return true;
}

bool CylinderManifold::Normal(const double* x, double* n) const {
  double t[3], len;
  return frame(x, n, t, &len);
}

}  // namespace tmop
