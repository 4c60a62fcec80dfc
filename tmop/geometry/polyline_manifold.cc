#include "tmop/geometry/polyline_manifold.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>

#include "tmop/geometry/closest_point.h"

namespace tmop {

PolylineManifold::PolylineManifold(int dim, const std::vector<double>& points, bool closed)
    : dim_(dim), closed_(closed) {
  CHECK(dim == 2 || dim == 3);
  const int n = static_cast<int>(points.size()) / dim;
  // Repeated points would make zero-length segments without a tangent.
  for (int i = 0; i < n; ++i) {
    const double* p = points.data() + i * dim;
    if (!points_.empty() && std::equal(p, p + dim, points_.end() - dim)) continue;
    points_.insert(points_.end(), p, p + dim);
  }
  num_points_ = static_cast<int>(points_.size()) / dim;
  if (closed_ && num_points_ > 1 &&
      std::equal(points_.begin(), points_.begin() + dim, points_.end() - dim)) {
    points_.resize(points_.size() - dim);
    --num_points_;
  }
  CHECK_GE(num_points_, closed_ ? 3 : 2) << "PolylineManifold: too few distinct points";
  const int segments = closed_ ? num_points_ : num_points_ - 1;
  cumulative_.assign(1, 0.0);
  tangent_.resize(segments * dim);
  std::vector<double> lo(segments * dim), hi(segments * dim);
  for (int s = 0; s < segments; ++s) {
    const double* a = point(s);
    const double* b = point(s + 1);
    double len2 = 0;
    for (int i = 0; i < dim; ++i) len2 += (b[i] - a[i]) * (b[i] - a[i]);
    const double len = std::sqrt(len2);
    for (int i = 0; i < dim; ++i) {
      tangent_[s * dim + i] = (b[i] - a[i]) / len;
      lo[s * dim + i] = std::min(a[i], b[i]);
      hi[s * dim + i] = std::max(a[i], b[i]);
    }
    cumulative_.push_back(cumulative_.back() + len);
  }
  tree_.Build(dim, lo, hi);
}

int PolylineManifold::locate(const double* x, double* t) const {
  double d2;
  double p[3];
  const int seg = tree_.Nearest(
      x, std::numeric_limits<double>::infinity(),
      [&](int s) { return closest_point_segment(dim_, x, point(s), point(s + 1), p, t); }, &d2);
  // The lambda's last call was not necessarily for the winning segment: recompute t.
  closest_point_segment(dim_, x, point(seg), point(seg + 1), p, t);
  return seg;
}

double PolylineManifold::ArcLength(const double* x) const {
  double t;
  const int seg = locate(x, &t);
  const double s = cumulative_[seg] + t * (cumulative_[seg + 1] - cumulative_[seg]);
  return closed_ && s >= length() ? s - length() : s;
}

void PolylineManifold::PointAt(double s, double* out) const {
  const double total = length();
  if (closed_) {
    s = std::fmod(s, total);
    if (s < 0) s += total;
  } else {
    s = std::min(std::max(s, 0.0), total);
  }
  // The segment whose arc-length interval holds s.
  int seg = static_cast<int>(std::upper_bound(cumulative_.begin(), cumulative_.end(), s) -
                             cumulative_.begin()) -
            1;
  seg = std::min(std::max(seg, 0), num_segments() - 1);
  const double len = cumulative_[seg + 1] - cumulative_[seg];
  const double t = std::min(std::max((s - cumulative_[seg]) / len, 0.0), 1.0);
  const double* a = point(seg);
  const double* b = point(seg + 1);
  for (int i = 0; i < dim_; ++i) out[i] = a[i] + t * (b[i] - a[i]);
}

void PolylineManifold::Project(const double* x, double* closest) const {
  double t;
  const int seg = locate(x, &t);
  const double* a = point(seg);
  const double* b = point(seg + 1);
  for (int i = 0; i < dim_; ++i) closest[i] = a[i] + t * (b[i] - a[i]);
}

bool PolylineManifold::Plus(const double* x, const double* delta, double* x_plus_delta) const {
  PointAt(ArcLength(x) + delta[0], x_plus_delta);
  return true;
}

bool PolylineManifold::PlusJacobian(const double* x, double* jacobian) const {
  double t;
  const int seg = locate(x, &t);
  for (int i = 0; i < dim_; ++i) jacobian[i] = tangent_[seg * dim_ + i];
  return true;
}

bool PolylineManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double d = ArcLength(y) - ArcLength(x);
  if (closed_) {
    const double total = length();
    if (d > 0.5 * total) d -= total;
    if (d <= -0.5 * total) d += total;
  }
  y_minus_x[0] = d;
  return true;
}

bool PolylineManifold::MinusJacobian(const double* x, double* jacobian) const {
  return PlusJacobian(x, jacobian);
}

}  // namespace tmop
