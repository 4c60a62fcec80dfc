// tmop/metric/shape_2d.cc
// 2D shape metrics mu_4 and mu_2 in their exact Cauchy-Riemann sum-of-squares form
// (see shape_2d.h).
#include "tmop/metric/shape_2d.h"

#include <cmath>
#include <limits>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

class Shape2dMetric final : public FixedMetric {
 public:
  explicit Shape2dMetric(bool barrier)
      : FixedMetric(barrier ? "shape_barrier_2d" : "shape_2d", barrier ? "mu_2" : "mu_4", 2,
                    MetricClass::kShape, barrier, 2) {}

  double value(const double* T) const override {
    const double tau = small_matrix::det<2>(T);
    const double f2 = small_matrix::frobenius2<2>(T);
    if (!barrier()) return f2 - 2.0 * tau;
    if (!(tau > 0.0)) return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
    return f2 / (2.0 * tau) - 1.0;
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    const double q0 = T[0] - T[3];
    const double q1 = T[1] + T[2];
    if (!barrier()) {
      if (!std::isfinite(q0) || !std::isfinite(q1)) return false;
      r[0] = q0;
      r[1] = q1;
      if (dr_dT != nullptr) {
        static constexpr double kJ[8] = {1, 0, 0, -1, 0, 1, 1, 0};
        for (int n = 0; n < 8; ++n) dr_dT[n] = kJ[n];
      }
      return true;
    }
    const double tau = small_matrix::det<2>(T);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    // r = q s, s = (2 tau)^(-1/2), ds/dT = -s / (2 tau) cof(T).
    const double s = 1.0 / std::sqrt(2.0 * tau);
    r[0] = q0 * s;
    r[1] = q1 * s;
    if (!std::isfinite(r[0]) || !std::isfinite(r[1])) return false;
    if (dr_dT != nullptr) {
      double C[4];
      small_matrix::cofactor<2>(T, C);
      const double h = 0.5 / tau;
      const double a0 = -r[0] * h, a1 = -r[1] * h;
      for (int n = 0; n < 4; ++n) {
        dr_dT[n] = a0 * C[n];
        dr_dT[4 + n] = a1 * C[n];
      }
      dr_dT[0] += s;
      dr_dT[3] -= s;
      dr_dT[5] += s;
      dr_dT[6] += s;
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<Metric> make_shape_2d_metric(bool barrier) {
  return std::make_unique<Shape2dMetric>(barrier);
}

}  // namespace tmop
