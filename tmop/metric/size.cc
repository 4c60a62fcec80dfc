// tmop/metric/size.cc
// Size metrics mu(det T); see size.h for the formulas and residual forms.
#include "tmop/metric/size.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

constexpr double kSqrtHalf = 0.70710678118654752440;

template <int D>
class SizeMetric final : public FixedMetric {
 public:
  SizeMetric(SizeForm form, std::string name, std::string alias)
      : FixedMetric(std::move(name), std::move(alias), D, MetricClass::kSize,
                    form != SizeForm::kQuadratic, 1),
        form_(form) {}

  double value(const double* T) const override {
    const double tau = small_matrix::det<D>(T);
    switch (form_) {
      case SizeForm::kQuadratic:
        return (tau - 1.0) * (tau - 1.0);
      case SizeForm::kBarrier:
        if (!(tau > 0.0)) return barrier_value(tau);
        return 0.5 * (tau + 1.0 / tau) - 1.0;
      case SizeForm::kBarrierQuadratic:
        if (!(tau > 0.0)) return barrier_value(tau);
        return 0.5 * (tau - 1.0 / tau) * (tau - 1.0 / tau);
    }
    return 0.0;
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    double C[D * D];
    small_matrix::cofactor<D>(T, C);
    const double tau = small_matrix::det_from_cofactor<D>(T, C);
    if (!std::isfinite(tau)) return false;
    double slope;  // dr / dtau
    switch (form_) {
      case SizeForm::kQuadratic:
        r[0] = tau - 1.0;
        slope = 1.0;
        break;
      case SizeForm::kBarrier: {
        if (!(tau > 0.0)) return false;
        // r = (tau - 1)(2 tau)^(-1/2); r' = (tau + 1)(2 tau)^(-3/2).
        const double s = 1.0 / std::sqrt(2.0 * tau);
        r[0] = (tau - 1.0) * s;
        slope = (tau + 1.0) * s * s * s;
        break;
      }
      case SizeForm::kBarrierQuadratic: {
        if (!(tau > 0.0)) return false;
        const double inv = 1.0 / tau;
        r[0] = (tau - inv) * kSqrtHalf;
        slope = (1.0 + inv * inv) * kSqrtHalf;
        break;
      }
      default:
        return false;
    }
    if (!std::isfinite(r[0]) || !std::isfinite(slope)) return false;
    if (dr_dT != nullptr) {
      for (int n = 0; n < D * D; ++n) dr_dT[n] = slope * C[n];
    }
    return true;
  }

 private:
  static double barrier_value(double tau) {
    return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
  }
  SizeForm form_;
};

}  // namespace

std::unique_ptr<Metric> make_size_metric(SizeForm form, int dim) {
  if (dim != 2 && dim != 3) return nullptr;
  const std::string suffix = dim == 2 ? "_2d" : "_3d";
  std::string name, alias;
  switch (form) {
    case SizeForm::kQuadratic:
      name = "size";
      alias = dim == 2 ? "mu_55" : "mu_315";
      break;
    case SizeForm::kBarrier:
      name = "size_barrier";
      alias = dim == 2 ? "mu_56" : "mu_316";
      break;
    case SizeForm::kBarrierQuadratic:
      name = "size_barrier_quadratic";
      alias = dim == 2 ? "mu_77" : "mu_318";
      break;
  }
  if (dim == 2) return std::make_unique<SizeMetric<2>>(form, name + suffix, alias);
  return std::make_unique<SizeMetric<3>>(form, name + suffix, alias);
}

}  // namespace tmop
