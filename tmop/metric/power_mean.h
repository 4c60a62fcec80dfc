// tmop/metric/power_mean.h
// PowerMeanMetric: raises a metric's excess over its minimum to the power p >= 1,
//   mu_p(T) = (mu(T) - min_value)^p,
// so that summing over sample points gives the power mean of order p of the quality (p > 1
// punishes the worst points more).
//
// Residuals: with r the inner residuals and rho = |r|, r_p = r rho^(p-1), hence
//   |r_p|^2 = rho^(2p) = (mu - min)^p exactly when the inner form is exact (equivalent otherwise),
//   dr_p/dT = rho^(p-1) (I + (p-1) r r^t / rho^2) dr/dT   (rho > 0; 0 for p > 1 at rho = 0).
// min_value() = 0; class, barrier, dimension and residual count are the inner metric's.
#ifndef TMOP_METRIC_POWER_MEAN_H_
#define TMOP_METRIC_POWER_MEAN_H_

#include <memory>

#include "tmop/metric/metric_base.h"

namespace tmop {

class PowerMeanMetric final : public FixedMetric {
 public:
  // Throws std::invalid_argument when inner is null or p is not finite or p < 1.
  PowerMeanMetric(std::shared_ptr<const Metric> inner, double p);

  const Metric& inner() const { return *inner_; }
  double p() const { return p_; }

  double value(const double* T) const override;
  bool residuals(const double* T, double* r, double* dr_dT) const override;

 private:
  std::shared_ptr<const Metric> inner_;
  double p_;
};

}  // namespace tmop

#endif  // TMOP_METRIC_POWER_MEAN_H_
