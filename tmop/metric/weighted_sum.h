// tmop/metric/weighted_sum.h
// WeightedSumMetric: mu = w_a mu_a + w_b mu_b (w_a, w_b >= 0) of two metrics of the same
// dimension, e.g. the shape+size blends (1 - g) shape + g size of the literature
// (MFEM's mu_80 = (1 - g) mu_2 + g mu_77).
//
// Residuals: the stacked [sqrt(w_a) r_a, sqrt(w_b) r_b], so
//   |r|^2 = w_a (mu_a - min_a) + w_b (mu_b - min_b) = mu - min_value(),
// exact whenever both parts are (and equivalent when a part is). min_value() = w_a min_a +
// w_b min_b. Barrier if either part is; residuals() fails where either part fails.
// Class: the common class when both agree; shape with size gives shape+size; otherwise the more
// restrictive one (untangle > shape+size+orientation > shape+size).
//
// The parts are shared (immutable metrics are thread-safe), so one part may appear in several
// sums. num_residuals() = m_a + m_b must not exceed kMaxMetricResiduals.
#ifndef TMOP_METRIC_WEIGHTED_SUM_H_
#define TMOP_METRIC_WEIGHTED_SUM_H_

#include <memory>

#include "tmop/metric/metric_base.h"

namespace tmop {

class WeightedSumMetric final : public FixedMetric {
 public:
  // Throws std::invalid_argument when a part is null, the dimensions differ, a weight is
  // negative or not finite, or m_a + m_b > kMaxMetricResiduals.
  WeightedSumMetric(std::shared_ptr<const Metric> a, double weight_a,
                    std::shared_ptr<const Metric> b, double weight_b);

  const Metric& part_a() const { return *a_; }
  const Metric& part_b() const { return *b_; }
  double weight_a() const { return wa_; }
  double weight_b() const { return wb_; }

  double value(const double* T) const override;
  double min_value() const override { return min_value_; }
  bool residuals(const double* T, double* r, double* dr_dT) const override;

 private:
  std::shared_ptr<const Metric> a_, b_;
  double wa_, wb_;
  double sqrt_wa_, sqrt_wb_;
  int ma_, mb_;
  double min_value_;
};

}  // namespace tmop

#endif  // TMOP_METRIC_WEIGHTED_SUM_H_
