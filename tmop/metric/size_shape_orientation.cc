// tmop/metric/size_shape_orientation.cc
// |T - I|^2 and |T - I|^2 / (2 tau) (see size_shape_orientation.h).
#include "tmop/metric/size_shape_orientation.h"

#include <cmath>
#include <limits>
#include <string>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

template <int D>
class SizeShapeOrientationMetric final : public FixedMetric {
 public:
  explicit SizeShapeOrientationMetric(bool barrier)
      : FixedMetric(std::string("size_shape_orientation") + (barrier ? "_barrier" : "") +
                        (D == 2 ? "_2d" : "_3d"),
                    !barrier && D == 2 ? "mu_14" : "", D, MetricClass::kShapeSizeOrientation,
                    barrier, D * D) {}

  double value(const double* T) const override {
    double r[D * D];
    if (residuals(T, r, nullptr)) return small_matrix::frobenius2<D>(r);
    const double tau = small_matrix::det<D>(T);
    return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    constexpr int M = D * D;
    for (int n = 0; n < M; ++n) r[n] = T[n];
    for (int i = 0; i < D; ++i) r[(D + 1) * i] -= 1.0;
    if (!barrier()) {
      for (int n = 0; n < M; ++n) {
        if (!std::isfinite(r[n])) return false;
      }
      if (dr_dT != nullptr) {
        for (int n = 0; n < M * M; ++n) dr_dT[n] = 0.0;
        for (int n = 0; n < M; ++n) dr_dT[(M + 1) * n] = 1.0;
      }
      return true;
    }
    double C[M];
    small_matrix::cofactor<D>(T, C);
    const double tau = small_matrix::det_from_cofactor<D>(T, C);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    const double s = 1.0 / std::sqrt(2.0 * tau);
    for (int n = 0; n < M; ++n) {
      r[n] *= s;
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      const double h = -0.5 / tau;
      for (int n = 0; n < M; ++n) {
        const double a = h * r[n];
        double* row = dr_dT + M * n;
        for (int m = 0; m < M; ++m) row[m] = a * C[m];
        row[n] += s;
      }
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<Metric> make_size_shape_orientation_metric(bool barrier, int dim) {
  if (dim == 2) return std::make_unique<SizeShapeOrientationMetric<2>>(barrier);
  if (dim == 3) return std::make_unique<SizeShapeOrientationMetric<3>>(barrier);
  return nullptr;
}

}  // namespace tmop
