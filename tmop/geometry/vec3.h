// tmop/geometry/vec3.h
// Tiny inline helpers on double[3] used by the geometry code's per-point paths, where Eigen
// temporaries would obscure the math and fixed arrays keep everything on the stack.
#ifndef TMOP_GEOMETRY_VEC3_H_
#define TMOP_GEOMETRY_VEC3_H_

#include <cmath>

namespace tmop {
namespace vec3 {

inline double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double norm(const double* a) { return std::sqrt(dot(a, a)); }
inline void sub(const double* a, const double* b, double* out) {
  out[0] = a[0] - b[0];
  out[1] = a[1] - b[1];
  out[2] = a[2] - b[2];
}
inline void cross(const double* a, const double* b, double* out) {
  const double x = a[1] * b[2] - a[2] * b[1];
  const double y = a[2] * b[0] - a[0] * b[2];
  const double z = a[0] * b[1] - a[1] * b[0];
  out[0] = x;
  out[1] = y;
  out[2] = z;
}
// Scales a to unit length; returns the old length (a untouched when it is 0).
inline double normalize(double* a) {
  const double n = norm(a);
  if (n > 0) {
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
  }
  return n;
}

// An orthonormal pair (u, v) with u x v = n for a unit normal n. Deterministic in n, so a chart
// built from it at a point gives the same tangent coordinates every time it is asked.
inline void tangent_basis(const double* n, double* u, double* v) {
  // Start from the coordinate axis least aligned with n: the cross product is then well
  // conditioned (|n x e| >= sqrt(2/3)).
  const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
  double e[3] = {0, 0, 0};
  if (ax <= ay && ax <= az) {
    e[0] = 1;
  } else if (ay <= az) {
    e[1] = 1;
  } else {
    e[2] = 1;
  }
  cross(e, n, u);
  normalize(u);
  cross(n, u, v);
}

}  // namespace vec3
}  // namespace tmop

#endif  // TMOP_GEOMETRY_VEC3_H_
