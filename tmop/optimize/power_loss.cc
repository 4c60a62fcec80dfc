#include "tmop/optimize/power_loss.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tmop {

PowerLoss::PowerLoss(double p, double w, double m, double model_cutoff)
    : p_(p), w_(w), m_(m), cutoff_(model_cutoff) {
  if (!(std::isfinite(p) && p >= 1)) throw std::invalid_argument("PowerLoss: p must be >= 1");
  if (!(std::isfinite(w) && w >= 0)) throw std::invalid_argument("PowerLoss: weight must be >= 0");
  if (!(std::isfinite(m) && m > 0)) throw std::invalid_argument("PowerLoss: scale must be > 0");
  if (!(model_cutoff > 0)) throw std::invalid_argument("PowerLoss: model cutoff must be > 0");
}

void PowerLoss::Evaluate(double s, double rho[3]) const {
  if (p_ == 1) {  // the plain mean, exactly
    rho[0] = w_ * std::max(s, 0.0);
    rho[1] = w_;
    rho[2] = 0;
    return;
  }
  const double t = std::max(s, 0.0) / m_, x = 1 + t;
  // x^(p-2) once: the three values share it (p = 2, the recipes' default, needs no pow).
  const double xp2 = p_ == 2 ? 1.0 : std::pow(x, p_ - 2);
  rho[2] = t > cutoff_ ? 0.0 : w_ * (p_ - 1) / m_ * xp2;
  rho[1] = w_ * xp2 * x;
  // (m/p)(x^p - 1) without cancellation for small t: x^p - 1 = expm1(p log1p(t)).
  rho[0] = w_ * m_ / p_ * (p_ == 2 ? t * (2 + t) : std::expm1(p_ * std::log1p(t)));
}

}  // namespace tmop
