// tmop/metric/power_mean.cc
// (mu - mu_min)^p through r |r|^(p-1) (see power_mean.h).
#include "tmop/metric/power_mean.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace tmop {
namespace {

const Metric& checked(const std::shared_ptr<const Metric>& m) {
  if (!m) throw std::invalid_argument("PowerMeanMetric: null inner metric");
  return *m;
}

std::string power_name(const std::string& inner, double p) {
  std::ostringstream s;
  s << "power(" << inner << "," << p << ")";
  return s.str();
}

}  // namespace

PowerMeanMetric::PowerMeanMetric(std::shared_ptr<const Metric> inner, double p)
    : FixedMetric(
          power_name(checked(inner).name(), p),
          checked(inner).alias().empty() ? std::string() : power_name(checked(inner).alias(), p),
          checked(inner).dim(), checked(inner).metric_class(), checked(inner).barrier(),
          checked(inner).num_residuals(), checked(inner).exact_residuals()),
      inner_(std::move(inner)),
      p_(p) {
  if (!(p >= 1.0) || !std::isfinite(p)) {
    throw std::invalid_argument("PowerMeanMetric: p must be finite and >= 1");
  }
}

double PowerMeanMetric::value(const double* T) const {
  const double excess = inner_->value(T) - inner_->min_value();
  return std::pow(excess > 0.0 ? excess : 0.0, p_);
}

bool PowerMeanMetric::residuals(const double* T, double* r, double* dr_dT) const {
  if (!inner_->residuals(T, r, dr_dT)) return false;
  const int m = num_residuals();
  const int nt = dim() * dim();
  double rho2 = 0.0;
  for (int i = 0; i < m; ++i) rho2 += r[i] * r[i];
  if (p_ == 1.0) return true;
  if (!(rho2 > 0.0)) {  // r = 0: r_p = 0 and, for p > 1, dr_p/dT = 0
    if (dr_dT != nullptr) {
      for (int n = 0; n < m * nt; ++n) dr_dT[n] = 0.0;
    }
    return true;
  }
  const double g = std::pow(rho2, 0.5 * (p_ - 1.0));  // rho^(p-1)
  if (dr_dT != nullptr) {
    // dr_p = g (dr + (p-1) r (r^t dr) / rho^2), using the unscaled r.
    double rt_dr[9];
    for (int k = 0; k < nt; ++k) {
      double s = 0.0;
      for (int i = 0; i < m; ++i) s += r[i] * dr_dT[i * nt + k];
      rt_dr[k] = (p_ - 1.0) * s / rho2;
    }
    for (int i = 0; i < m; ++i) {
      for (int k = 0; k < nt; ++k) dr_dT[i * nt + k] = g * (dr_dT[i * nt + k] + r[i] * rt_dr[k]);
    }
  }
  for (int i = 0; i < m; ++i) r[i] *= g;
  return true;
}

}  // namespace tmop
