// tmop/metric/weighted_sum.cc
// w_a mu_a + w_b mu_b by stacking sqrt-weighted residuals (see weighted_sum.h).
#include "tmop/metric/weighted_sum.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace tmop {
namespace {

const Metric& checked(const std::shared_ptr<const Metric>& m) {
  if (!m) throw std::invalid_argument("WeightedSumMetric: null part");
  return *m;
}

std::string weighted_name(const std::string& a, double wa, const std::string& b, double wb) {
  std::ostringstream s;
  s << wa << "*" << a << "+" << wb << "*" << b;
  return s.str();
}

int rank(MetricClass c) {
  switch (c) {
    case MetricClass::kShape:
    case MetricClass::kSize:
      return 0;
    case MetricClass::kShapeSize:
      return 1;
    case MetricClass::kShapeSizeOrientation:
      return 2;
    case MetricClass::kUntangle:
      return 3;
  }
  return 3;
}

MetricClass combined_class(MetricClass a, MetricClass b) {
  if (a == b) return a;
  if (rank(a) == 0 && rank(b) == 0) return MetricClass::kShapeSize;  // shape + size
  if (rank(a) == 0 && b == MetricClass::kShapeSize) return b;
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace

WeightedSumMetric::WeightedSumMetric(std::shared_ptr<const Metric> a, double weight_a,
                                     std::shared_ptr<const Metric> b, double weight_b)
    : FixedMetric(weighted_name(checked(a).name(), weight_a, checked(b).name(), weight_b),
                  checked(a).alias().empty() || checked(b).alias().empty()
                      ? std::string()
                      : weighted_name(checked(a).alias(), weight_a, checked(b).alias(), weight_b),
                  checked(a).dim(),
                  combined_class(checked(a).metric_class(), checked(b).metric_class()),
                  checked(a).barrier() || checked(b).barrier(),
                  checked(a).num_residuals() + checked(b).num_residuals(),
                  checked(a).exact_residuals() && checked(b).exact_residuals()),
      a_(std::move(a)),
      b_(std::move(b)),
      wa_(weight_a),
      wb_(weight_b),
      sqrt_wa_(std::sqrt(weight_a)),
      sqrt_wb_(std::sqrt(weight_b)),
      ma_(a_->num_residuals()),
      mb_(b_->num_residuals()),
      min_value_(weight_a * a_->min_value() + weight_b * b_->min_value()) {
  if (a_->dim() != b_->dim()) throw std::invalid_argument("WeightedSumMetric: dimensions differ");
  if (!(wa_ >= 0.0) || !(wb_ >= 0.0) || !std::isfinite(wa_) || !std::isfinite(wb_)) {
    throw std::invalid_argument("WeightedSumMetric: weights must be finite and >= 0");
  }
  if (ma_ + mb_ > kMaxMetricResiduals) {
    throw std::invalid_argument("WeightedSumMetric: " + name() + " needs " +
                                std::to_string(ma_ + mb_) + " residuals, more than " +
                                std::to_string(kMaxMetricResiduals));
  }
}

double WeightedSumMetric::value(const double* T) const {
  const double va = wa_ == 0.0 ? 0.0 : wa_ * a_->value(T);
  const double vb = wb_ == 0.0 ? 0.0 : wb_ * b_->value(T);
  return va + vb;
}

bool WeightedSumMetric::residuals(const double* T, double* r, double* dr_dT) const {
  const int nt = dim() * dim();
  if (!a_->residuals(T, r, dr_dT)) return false;
  if (!b_->residuals(T, r + ma_, dr_dT == nullptr ? nullptr : dr_dT + ma_ * nt)) return false;
  for (int n = 0; n < ma_; ++n) r[n] *= sqrt_wa_;
  for (int n = ma_; n < ma_ + mb_; ++n) r[n] *= sqrt_wb_;
  if (dr_dT != nullptr) {
    for (int n = 0; n < ma_ * nt; ++n) dr_dT[n] *= sqrt_wa_;
    for (int n = ma_ * nt; n < (ma_ + mb_) * nt; ++n) dr_dT[n] *= sqrt_wb_;
  }
  return true;
}

}  // namespace tmop
