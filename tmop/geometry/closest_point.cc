#include "tmop/geometry/closest_point.h"

#include "tmop/geometry/vec3.h"

namespace tmop {

double closest_point_segment(int dim, const double* q, const double* a, const double* b,
                             double* out, double* t) {
  double ab2 = 0, aq_ab = 0;
  for (int i = 0; i < dim; ++i) {
    ab2 += (b[i] - a[i]) * (b[i] - a[i]);
    aq_ab += (q[i] - a[i]) * (b[i] - a[i]);
  }
  double s = ab2 > 0 ? aq_ab / ab2 : 0.0;
  s = s < 0 ? 0.0 : (s > 1 ? 1.0 : s);
  double d2 = 0;
  for (int i = 0; i < dim; ++i) {
    out[i] = a[i] + s * (b[i] - a[i]);
    d2 += (q[i] - out[i]) * (q[i] - out[i]);
  }
  *t = s;
  return d2;
}

double closest_point_triangle(const double* q, const double* a, const double* b, const double* c,
                              double* out) {
  // If the orthogonal projection of q onto the triangle's plane has non-negative barycentric
  // coordinates it is the answer; otherwise the nearest point lies on the boundary, i.e. on the
  // nearest of the three edges (the squared distance is convex, so its minimum over the
  // triangle is at the interior critical point or on the boundary).
  double e1[3], e2[3], r[3];
  vec3::sub(b, a, e1);
  vec3::sub(c, a, e2);
  vec3::sub(q, a, r);
  const double g11 = vec3::dot(e1, e1), g12 = vec3::dot(e1, e2), g22 = vec3::dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  if (det > 1e-30 * g11 * g22) {
    const double r1 = vec3::dot(r, e1), r2 = vec3::dot(r, e2);
    const double s = (g22 * r1 - g12 * r2) / det;
    const double t = (g11 * r2 - g12 * r1) / det;
    if (s >= 0 && t >= 0 && s + t <= 1) {
      double d2 = 0;
      for (int i = 0; i < 3; ++i) {
        out[i] = a[i] + s * e1[i] + t * e2[i];
        d2 += (q[i] - out[i]) * (q[i] - out[i]);
      }
      return d2;
    }
  }
  double p[3], tp;
  double best = closest_point_segment(3, q, a, b, out, &tp);
  const double* ends[2][2] = {{b, c}, {c, a}};
  for (int k = 0; k < 2; ++k) {
    const double d2 = closest_point_segment(3, q, ends[k][0], ends[k][1], p, &tp);
    if (d2 < best) {
      best = d2;
      out[0] = p[0];
      out[1] = p[1];
      out[2] = p[2];
    }
  }
  return best;
}

}  // namespace tmop
