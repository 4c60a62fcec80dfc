// tmop/metric/untangle.h
// UntangleMetric: the regularised-determinant energy of Garanzha et al. (2021), finite for every
// T (inverted included) when eps > 0, used to untangle a mesh before a barrier stage
// (DESIGN.md section 7).
//
//   chi(tau, eps) = (tau + sqrt(eps^2 + tau^2)) / 2 > 0
//       evaluated as eps^2 / (2 (sqrt(eps^2 + tau^2) - tau)) for tau <= 0 (same value, no
//       cancellation); chi -> tau for tau >> eps and -> eps^2 / (4 |tau|) for tau << -eps.
//       d chi / d tau = chi / sqrt(eps^2 + tau^2) (smooth, > 0).
//   mu = (1 - theta) |T|^2 / chi^(2/d) + theta (1 + tau^2) / chi
//       the first term is a shape energy (d when T = s R and eps -> 0), the second a size energy
//       (2 at tau = 1 when eps -> 0).
//   residuals (exact: |r|^2 = mu, min_value() = 0), m = d*d + 2:
//       r = [ sqrt(1 - theta) vec(T) / chi^(1/d),  sqrt(theta) / sqrt(chi),
//             sqrt(theta) tau / sqrt(chi) ]
//   dr/dT is exact including d chi / d tau: with q = sqrt(eps^2 + tau^2),
//       d chi^(-k) / dT = -k chi^(-k) / q cof(T).
//
// The energy is not zero at its minimum (about d (1 - theta) + 2 theta at T = I for small eps);
// min_value() is 0 so that |r|^2 = value() - min_value() holds exactly. Not a barrier: residuals()
// succeeds for every finite T when eps > 0. With eps = 0 it behaves as a barrier and residuals()
// returns false for tau <= 0 (value() +infinity).
//
// eps is dimensionless (tau is); the optimizer lowers it between solves according to min tau,
// building a new metric each time (metrics are immutable). theta in [0, 1] weighs size
// against shape.
#ifndef TMOP_METRIC_UNTANGLE_H_
#define TMOP_METRIC_UNTANGLE_H_

#include "tmop/metric/metric_base.h"

namespace tmop {

class UntangleMetric final : public FixedMetric {
 public:
  static constexpr double kDefaultEps = 0.1;
  static constexpr double kDefaultTheta = 0.5;

  // dim: 2 or 3. eps >= 0: regularisation of the determinant (default 0.1). theta in [0, 1]:
  // weight of the size term (default 0.5). Throws std::invalid_argument on bad arguments.
  explicit UntangleMetric(int dim, double eps = kDefaultEps, double theta = kDefaultTheta);

  double eps() const { return eps_; }
  double theta() const { return theta_; }

  // The regularised determinant chi(tau, eps) and its derivative, stable for all tau.
  static double chi(double tau, double eps);
  static double chi_derivative(double tau, double eps);

  double value(const double* T) const override;
  bool residuals(const double* T, double* r, double* dr_dT) const override;

 private:
  template <int D>
  bool residuals_d(const double* T, double* r, double* dr_dT) const;

  double eps_;
  double theta_;
  double sqrt_shape_;  // sqrt(1 - theta)
  double sqrt_size_;   // sqrt(theta)
};

}  // namespace tmop

#endif  // TMOP_METRIC_UNTANGLE_H_
