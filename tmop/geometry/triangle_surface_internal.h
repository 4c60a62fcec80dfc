// tmop/geometry/triangle_surface_internal.h
// Helpers shared by triangle_surface_manifold.cc (the flat triangles, walks, charts) and
// triangle_surface_smooth.cc (the smooth patches over them). Not part of the API.
#ifndef TMOP_GEOMETRY_TRIANGLE_SURFACE_INTERNAL_H_
#define TMOP_GEOMETRY_TRIANGLE_SURFACE_INTERNAL_H_

#include <limits>

#include "tmop/geometry/vec3.h"

namespace tmop {
namespace surface_internal {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Barycentric coordinates of the in-plane point p and of the in-plane direction w in triangle
// (a, b, c): lam(p + t w) = lam + t dlam.
inline void barycentric(const double* a, const double* b, const double* c, const double* p,
                        const double* w, double* lam, double* dlam) {
  double e1[3], e2[3], r[3];
  vec3::sub(b, a, e1);
  vec3::sub(c, a, e2);
  vec3::sub(p, a, r);
  const double g11 = vec3::dot(e1, e1), g12 = vec3::dot(e1, e2), g22 = vec3::dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  const double r1 = vec3::dot(r, e1), r2 = vec3::dot(r, e2);
  const double w1 = vec3::dot(w, e1), w2 = vec3::dot(w, e2);
  const double s = (g22 * r1 - g12 * r2) / det, t = (g11 * r2 - g12 * r1) / det;
  const double ds = (g22 * w1 - g12 * w2) / det, dt = (g11 * w2 - g12 * w1) / det;
  lam[0] = 1 - s - t;
  lam[1] = s;
  lam[2] = t;
  dlam[0] = -ds - dt;
  dlam[1] = ds;
  dlam[2] = dt;
}

// lam clamped onto the triangle (negative coordinates to 0, renormalised).
inline void clamp_barycentric(double* lam) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    lam[k] = std::max(lam[k], 0.0);
    sum += lam[k];
  }
  for (int k = 0; k < 3; ++k) lam[k] = sum > 0 ? lam[k] / sum : 1.0 / 3;
}

}  // namespace surface_internal
}  // namespace tmop

#endif  // TMOP_GEOMETRY_TRIANGLE_SURFACE_INTERNAL_H_
