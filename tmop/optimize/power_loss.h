// tmop/optimize/power_loss.h
// PowerLoss: the Ceres loss that turns a sample point's squared residual norm s = |r|^2 (the
// metric's excess mu - mu_min for metrics with exact residuals, Metric::exact_residuals; an
// equivalent surrogate otherwise) into its term of the power objective of order p
// (StageSpec::power):
//   rho(s) = w (m / p) ((1 + s / m)^p - 1),   p >= 1, w >= 0 the point weight, m > 0 a scale.
// rho'(s) = w (1 + s/m)^(p-1) >= w: a point at or below the scale counts as in the plain mean
// (none is neglected), one far above it as w (s/m)^(p-1) times that, so the worst points weigh
// most. p = 1 is the plain mean; for p = 2, rho = w (s + s^2 / (2 m)).
//
// Why a loss: Ceres models a block with a loss by the corrected Gauss-Newton Hessian
// J^t (rho' I + 2 rho'' r r^t) J (Triggs et al., "Bundle adjustment - a modern synthesis",
// section 4.3), which for rho'' >= 0 (here always) is the exact Gauss-Newton model of rho(mu):
// the metric's own model scaled by rho', plus the power's curvature. One Ceres solve then
// minimises the power objective with step ratios near 1. A residual r |r|^(p-1) has the same
// gradient but not that model (100k tets, p = 2: step ratios 0.03-0.28 and Levenberg-Marquardt
// crawled); iteratively reweighted solves need several Ceres solves (docs/benchmarks.md).
#ifndef TMOP_OPTIMIZE_POWER_LOSS_H_
#define TMOP_OPTIMIZE_POWER_LOSS_H_

#include <ceres/loss_function.h>

namespace tmop {

class PowerLoss final : public ceres::LossFunction {
 public:
  // Throws std::invalid_argument unless p >= 1, w >= 0 and m > 0 are finite.
  PowerLoss(double p, double w, double m);
  // rho[0..2] = rho, rho', rho'' at s (s < 0 is treated as 0: s is a squared norm).
  void Evaluate(double s, double rho[3]) const override;

  double p() const { return p_; }
  double weight() const { return w_; }
  double scale() const { return m_; }

 private:
  double p_, w_, m_;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_POWER_LOSS_H_
