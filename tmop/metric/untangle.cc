// tmop/metric/untangle.cc
// Regularised-determinant untangling energy (see untangle.h).
#include "tmop/metric/untangle.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "tmop/metric/small_matrix.h"

namespace tmop {

UntangleMetric::UntangleMetric(int dim, double eps, double theta)
    : FixedMetric(dim == 2 ? "untangle_2d" : "untangle_3d", "", dim, MetricClass::kUntangle, false,
                  dim * dim + 2),
      eps_(eps),
      theta_(theta),
      sqrt_shape_(std::sqrt(1.0 - theta)),
      sqrt_size_(std::sqrt(theta)) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("UntangleMetric: dim must be 2 or 3");
  if (!(eps >= 0.0) || !std::isfinite(eps)) {
    throw std::invalid_argument("UntangleMetric: eps must be finite and >= 0");
  }
  if (!(theta >= 0.0 && theta <= 1.0)) {
    throw std::invalid_argument("UntangleMetric: theta must be in [0, 1]");
  }
}

double UntangleMetric::chi(double tau, double eps) {
  const double q = std::hypot(eps, tau);
  if (tau > 0.0) return 0.5 * (tau + q);
  // (tau + q)/2 = (q^2 - tau^2) / (2 (q - tau)) = eps^2 / (2 (q - tau)); q - tau >= |tau| > 0
  // unless tau = eps = 0.
  const double den = 2.0 * (q - tau);
  return den > 0.0 ? eps * eps / den : 0.0;
}

double UntangleMetric::chi_derivative(double tau, double eps) {
  const double q = std::hypot(eps, tau);
  return q > 0.0 ? chi(tau, eps) / q : 0.5;
}

double UntangleMetric::value(const double* T) const {
  const int d = dim();
  const double tau = d == 2 ? small_matrix::det<2>(T) : small_matrix::det<3>(T);
  const double f2 = d == 2 ? small_matrix::frobenius2<2>(T) : small_matrix::frobenius2<3>(T);
  const double c = chi(tau, eps_);
  if (!(c > 0.0)) return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
  const double shape = f2 / std::pow(c, 2.0 / d);
  return (1.0 - theta_) * shape + theta_ * (1.0 + tau * tau) / c;
}

bool UntangleMetric::residuals(const double* T, double* r, double* dr_dT) const {
  return dim() == 2 ? residuals_d<2>(T, r, dr_dT) : residuals_d<3>(T, r, dr_dT);
}

template <int D>
bool UntangleMetric::residuals_d(const double* T, double* r, double* dr_dT) const {
  constexpr int M = D * D;
  double C[M];
  small_matrix::cofactor<D>(T, C);
  const double tau = small_matrix::det_from_cofactor<D>(T, C);
  if (!std::isfinite(tau)) return false;
  const double q = std::hypot(eps_, tau);
  const double c =
      tau > 0.0 ? 0.5 * (tau + q) : (q - tau > 0.0 ? eps_ * eps_ / (2.0 * (q - tau)) : 0.0);
  if (!(c > 0.0)) return false;
  const double a = D == 2 ? 1.0 / std::sqrt(c) : 1.0 / std::cbrt(c);  // chi^(-1/d)
  const double b = D == 2 ? a : 1.0 / std::sqrt(c);                   // chi^(-1/2)
  const double sa = sqrt_shape_ * a;
  for (int n = 0; n < M; ++n) r[n] = sa * T[n];
  r[M] = sqrt_size_ * b;
  r[M + 1] = sqrt_size_ * tau * b;
  for (int n = 0; n < M + 2; ++n) {
    if (!std::isfinite(r[n])) return false;
  }
  if (dr_dT != nullptr) {
    // d chi^(-k)/dT = -k chi^(-k) / q cof(T), k = 1/d for the shape part, 1/2 for the size part.
    const double inv_q = 1.0 / q;
    const double ka = -sa * inv_q / D;  // d(sqrt(1-theta) a)/dT = ka cof
    for (int n = 0; n < M; ++n) {
      double* row = dr_dT + M * n;
      const double kt = ka * T[n];
      for (int m = 0; m < M; ++m) row[m] = kt * C[m];
      row[n] += sa;
    }
    const double sb = sqrt_size_ * b;
    double* row1 = dr_dT + M * M;
    double* row2 = row1 + M;
    const double k1 = -0.5 * sb * inv_q;               // d(sqrt(theta) b)/dT = k1 cof
    const double k2 = sb * (1.0 - 0.5 * tau * inv_q);  // d(sqrt(theta) tau b)/dT = k2 cof
    for (int m = 0; m < M; ++m) {
      row1[m] = k1 * C[m];
      row2[m] = k2 * C[m];
    }
  }
  return true;
}

}  // namespace tmop
