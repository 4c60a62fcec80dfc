#include "tmop/geometry/projected_curve_manifold.h"

#include <algorithm>
#include <cmath>

#include "tmop/geometry/vec3.h"

namespace tmop {

ProjectedCurveManifold::ProjectedCurveManifold(const std::vector<double>& points, bool closed,
                                               const GeometryManifold* surface)
    : polyline_(3, points, closed), closed_(closed), surface_(surface) {
  // The same vertices PolylineManifold keeps: repeated consecutive points dropped.
  const int n = static_cast<int>(points.size() / 3);
  for (int i = 0; i < n; ++i) {
    const double* p = &points[3 * i];
    if (!points_.empty()) {
      double d[3];
      vec3::sub(p, &points_[points_.size() - 3], d);
      if (vec3::norm(d) == 0) continue;
    }
    points_.insert(points_.end(), p, p + 3);
  }
  const int m = static_cast<int>(points_.size() / 3);
  const int segments = closed_ ? m : m - 1;
  cumulative_.assign(1, 0.0);
  for (int i = 0; i < segments; ++i) {
    double d[3];
    vec3::sub(&points_[3 * ((i + 1) % m)], &points_[3 * i], d);
    cumulative_.push_back(cumulative_.back() + vec3::norm(d));
  }
}

double ProjectedCurveManifold::ArcLength(const double* x) const {
  const int m = static_cast<int>(points_.size() / 3);
  const int segments = static_cast<int>(cumulative_.size()) - 1;
  const double total = cumulative_.back();
  double s0 = polyline_.ArcLength(x);
  int seg = static_cast<int>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s0) -
                             cumulative_.begin()) -
            1;
  seg = std::min(std::max(seg, 0), segments - 1);
  double n[3];
  if (!surface_->Normal(x, n)) return s0;
  // Walk to the segment the normal line through x meets within [0, 1] (a few steps at most:
  // the chord's closest segment is that one or a neighbour).
  double best_s = s0;
  for (int step = 0; step < 4; ++step) {
    const double* a = &points_[3 * seg];
    const double* b = &points_[3 * ((seg + 1) % m)];
    double e[3], r[3];
    vec3::sub(b, a, e);
    vec3::sub(a, x, r);
    const double en = vec3::dot(e, n), rn = vec3::dot(r, n);
    for (int i = 0; i < 3; ++i) {
      e[i] -= en * n[i];
      r[i] -= rn * n[i];
    }
    const double ee = vec3::dot(e, e);
    const double t = ee > 0 ? -vec3::dot(r, e) / ee : 0.0;
    const double len = cumulative_[seg + 1] - cumulative_[seg];
    best_s = cumulative_[seg] + std::min(std::max(t, 0.0), 1.0) * len;
    int next = seg;
    if (t < 0) next = seg > 0 ? seg - 1 : (closed_ ? segments - 1 : seg);
    if (t > 1) next = seg + 1 < segments ? seg + 1 : (closed_ ? 0 : seg);
    if (next == seg) break;
    seg = next;
  }
  if (closed_ && best_s >= total) best_s -= total;
  return best_s;
}

void ProjectedCurveManifold::Project(const double* x, double* closest) const {
  double q[3];
  polyline_.PointAt(ArcLength(x), q);
  surface_->Project(q, closest);
}

bool ProjectedCurveManifold::Plus(const double* x, const double* delta,
                                  double* x_plus_delta) const {
  double q[3];
  polyline_.PointAt(ArcLength(x) + delta[0], q);
  surface_->Project(q, x_plus_delta);
  return true;
}

bool ProjectedCurveManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double d = ArcLength(y) - ArcLength(x);
  if (closed_) {
    const double total = cumulative_.back();
    if (d > total / 2) d -= total;
    if (d <= -total / 2) d += total;
  }
  y_minus_x[0] = d;
  return true;
}

bool ProjectedCurveManifold::PlusJacobian(const double* x, double* jacobian) const {
  const double h = 1e-7 * cumulative_.back();
  double a[3], b[3];
  const double dp = h, dn = -h;
  Plus(x, &dp, a);
  Plus(x, &dn, b);
  for (int i = 0; i < 3; ++i) jacobian[i] = (a[i] - b[i]) / (2 * h);
  return true;
}

bool ProjectedCurveManifold::MinusJacobian(const double* x, double* jacobian) const {
  const double h = 1e-7 * cumulative_.back();
  for (int i = 0; i < 3; ++i) {
    double yp[3] = {x[0], x[1], x[2]}, yn[3] = {x[0], x[1], x[2]};
    yp[i] += h;
    yn[i] -= h;
    double dp, dn;
    Minus(yp, x, &dp);
    Minus(yn, x, &dn);
    jacobian[i] = (dp - dn) / (2 * h);
  }
  return true;
}

}  // namespace tmop
