#include "tmop/geometry/sphere_manifold.h"

#include <glog/logging.h>

#include "tmop/geometry/vec3.h"

namespace tmop {

SphereManifold::SphereManifold(const double centre[3], double radius) : radius_(radius) {
  CHECK_GT(radius, 0.0) << "SphereManifold: radius must be positive";
  for (int i = 0; i < 3; ++i) centre_[i] = centre[i];
}

bool SphereManifold::frame(const double* x, double* n, double* u, double* v) const {
  vec3::sub(x, centre_, n);
  if (vec3::normalize(n) == 0) return false;
  vec3::tangent_basis(n, u, v);
  return true;
}

void SphereManifold::Project(const double* x, double* closest) const {
  double n[3];
  vec3::sub(x, centre_, n);
  // The centre is equidistant from every point: any pole will do.
  if (vec3::normalize(n) == 0) n[2] = 1;
  for (int i = 0; i < 3; ++i) closest[i] = centre_[i] + radius_ * n[i];
}

bool SphereManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  double n[3], u[3], v[3];
  if (!frame(x, n, u, v)) return false;
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = x[i] + delta[0] * u[i] + delta[1] * v[i];
  Project(q, x_plus_delta);
  return true;
}

bool SphereManifold::PlusJacobian(const double* x, double* jacobian) const {
  double n[3], u[3], v[3];
  if (!frame(x, n, u, v)) return false;
  // d/d delta of c + r q/|q| at delta = 0 is r/|x - c| (I - n n^T) [u v] = [u v] on the sphere.
  double r[3];
  vec3::sub(x, centre_, r);
  const double s = radius_ / vec3::norm(r);
  for (int i = 0; i < 3; ++i) {
    jacobian[2 * i] = s * u[i];
    jacobian[2 * i + 1] = s * v[i];
  }
  return true;
}

bool SphereManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double n[3], u[3], v[3];
  if (!frame(x, n, u, v)) return false;
  double p[3], r[3];
  vec3::sub(y, centre_, p);
  vec3::sub(x, centre_, r);
  const double pn = vec3::dot(p, n);
  if (pn <= 0) return false;
  const double scale = vec3::norm(r) / pn;
  y_minus_x[0] = scale * vec3::dot(u, p);
  y_minus_x[1] = scale * vec3::dot(v, p);
  return true;
}

bool SphereManifold::MinusJacobian(const double* x, double* jacobian) const {
  double n[3], u[3], v[3];
  if (!frame(x, n, u, v)) return false;
  for (int i = 0; i < 3; ++i) {
    jacobian[i] = u[i];
    jacobian[3 + i] = v[i];
  }
  return true;
}

bool SphereManifold::Normal(const double* x, double* n) const {
  double u[3], v[3];
  return frame(x, n, u, v);
}

}  // namespace tmop
