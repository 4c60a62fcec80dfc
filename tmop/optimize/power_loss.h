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
//
// The model's curvature far out: beyond s = K m (K = model_cutoff) Evaluate reports rho'' = 0,
// so such a block is modelled like the plain mean's, scaled by rho'. rho and rho' stay exact,
// hence so do the objective, its gradient and the minimiser; only the steps change. Why: a
// near-degenerate element's metric is a barrier whose linearised residual already
// underestimates how far it can move, and the full correction (up to 2p - 1 times the curvature
// along r for s >> m) shortened its steps a further 3x at p = 2, so the worst elements improved
// by only 1.6x an iteration and set the iteration count (part 100k tets, p = 2: 14 iterations;
// with K = 50: 9, the same objective and worst element; docs/benchmarks.md). Near the optimum
// every typical point is below K m and the model is the exact one again.
#ifndef TMOP_OPTIMIZE_POWER_LOSS_H_
#define TMOP_OPTIMIZE_POWER_LOSS_H_

#include <ceres/loss_function.h>

namespace tmop {

class PowerLoss final : public ceres::LossFunction {
 public:
  static constexpr double kDefaultModelCutoff = 50;
  // Throws std::invalid_argument unless p >= 1, w >= 0 and m > 0 are finite and model_cutoff > 0
  // (+infinity: the exact second derivative everywhere).
  PowerLoss(double p, double w, double m, double model_cutoff = kDefaultModelCutoff);
  // rho[0..1] = rho, rho' at s (s < 0 is treated as 0: s is a squared norm); rho[2] = rho'' up
  // to s = model_cutoff x m, 0 beyond (see above).
  void Evaluate(double s, double rho[3]) const override;

  double p() const { return p_; }
  double weight() const { return w_; }
  double scale() const { return m_; }
  double model_cutoff() const { return cutoff_; }

 private:
  double p_, w_, m_, cutoff_;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_POWER_LOSS_H_
