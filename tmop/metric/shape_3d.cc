// tmop/metric/shape_3d.cc
// 3D shape metrics: polar residual form for the barrier ones, cofactor form for mu_360
// (see shape_3d.h for the derivations).
#include "tmop/metric/shape_3d.h"

#include <cmath>
#include <limits>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

constexpr double kSqrt3 = 1.73205080756887729353;

double nan_or_inf(double tau) {
  return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
}

// F(X) = vec(cof X - n X) / (2 sqrt(n)), n = |X| / sqrt(3): the cofactor form of mu_360
// (shape_3d.h), and dF/dX when J is not null.
bool conformal_residual(const double* X, double* F, double* J) {
  const double f2 = small_matrix::frobenius2<3>(X);
  if (!std::isfinite(f2)) return false;
  const double n = std::sqrt(f2 / 3.0);
  if (!(n > 1e-150)) {  // X = 0 (a minimiser): F -> 0 and dF/dX -> 0 like |X|^(3/2), |X|^(1/2)
    for (int m = 0; m < 9; ++m) F[m] = 0.0;
    if (J != nullptr) {
      for (int m = 0; m < 81; ++m) J[m] = 0.0;
    }
    return true;
  }
  double C[9];
  small_matrix::cofactor<3>(X, C);
  const double sn = std::sqrt(n);
  const double u = 0.5 / sn;  // F = u cof - v X
  const double v = 0.5 * sn;
  for (int m = 0; m < 9; ++m) F[m] = u * C[m] - v * X[m];
  if (J != nullptr) {
    // dF = u dcof - v I - cof (x) X / (12 n^(5/2)) - X (x) X / (12 n^(3/2)).
    small_matrix::cofactor_derivative_3(X, J);
    const double p = 1.0 / (12.0 * n * n * sn);
    const double q = n * p;
    for (int i = 0; i < 9; ++i) {
      double* row = J + 9 * i;
      const double ai = -(p * C[i] + q * X[i]);
      for (int m = 0; m < 9; ++m) row[m] = u * row[m] + ai * X[m];
      row[i] -= v;
    }
  }
  return true;
}

class BarrierShapeMetric final : public FixedMetric {
 public:
  BarrierShapeMetric(Shape3dForm form, const char* name, const char* alias, double c2,
                     Shape3dResidual residual)
      : FixedMetric(name, alias, 3, MetricClass::kShape, true, 9, false),
        form_(form),
        c_(std::sqrt(c2)),
        residual_(residual) {}

  double value(const double* T) const override {
    double C[9];
    small_matrix::cofactor<3>(T, C);
    const double tau = small_matrix::det_from_cofactor<3>(T, C);
    if (!(tau > 0.0)) return nan_or_inf(tau);
    const double f2 = small_matrix::frobenius2<3>(T);
    switch (form_) {
      case Shape3dForm::kBarrier: {
        const double t13 = std::cbrt(tau);
        return f2 / (3.0 * t13 * t13) - 1.0;
      }
      case Shape3dForm::kCubicBarrier:
        return f2 * std::sqrt(f2) / (3.0 * kSqrt3 * tau) - 1.0;
      case Shape3dForm::kConditionBarrier:  // |T^-1| = |cof T| / tau
        return std::sqrt(f2 * small_matrix::frobenius2<3>(C)) / (3.0 * tau) - 1.0;
      case Shape3dForm::kConditionSquaredBarrier:
        return f2 * small_matrix::frobenius2<3>(C) / (9.0 * tau * tau) - 1.0;
      default:
        return std::numeric_limits<double>::quiet_NaN();
    }
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    double C[9];
    small_matrix::cofactor<3>(T, C);
    const double tau = small_matrix::det_from_cofactor<3>(T, C);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    const double a = 1.0 / std::cbrt(tau);
    double S[9], R[9];
    for (int n = 0; n < 9; ++n) S[n] = a * T[n];
    if (residual_ == Shape3dResidual::kCofactor) return cofactor_residuals(a, tau, S, C, r, dr_dT);
    if (!small_matrix::polar_rotation_unit_det_3(S, R)) return false;
    const double ca = c_ * a;
    for (int n = 0; n < 9; ++n) {
      r[n] = c_ * (S[n] - R[n]);
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      // dS/dT = a (I - vec(T) vec(T^-t)^t / 3), T^-t = C / tau. With R held fixed dr/dT = c dS/dT;
      // the exact Jacobian is c (I - L) dS/dT with L = dR/dS.
      const double b = 1.0 / (3.0 * tau);
      if (residual_ == Shape3dResidual::kPolarRotationFixed) {
        for (int n = 0; n < 9; ++n) {
          double* row = dr_dT + 9 * n;
          const double bt = -ca * b * T[n];
          for (int m = 0; m < 9; ++m) row[m] = bt * C[m];
          row[n] += ca;
        }
        return true;
      }
      double L[81];
      small_matrix::polar_rotation_derivative_3(S, R, L);
      // (I - L)(I - t g^t / 3) = I - L - t g^t / 3, since L t = 0: A t = axial(R^t T - T^t R)
      // vanishes because R^t T = P / a is symmetric.
      const double cb = -ca * b;
      for (int n = 0; n < 9; ++n) {
        double* row = dr_dT + 9 * n;
        const double* l = L + 9 * n;
        const double bt = cb * T[n];
        for (int m = 0; m < 9; ++m) row[m] = bt * C[m] - ca * l[m];
        row[n] += ca;
      }
    }
    return true;
  }

 private:
  // r = c F(S); dr/dT = c dF/dS a (I - vec(T) g^t / 3) with g = T^-t = C / tau. F is homogeneous
  // of degree 3/2, so (dF/dS) vec(S) = (3/2) F and dr/dT = c (a dF/dS - F g^t / 2).
  bool cofactor_residuals(double a, double tau, const double* S, const double* C, double* r,
                          double* dr_dT) const {
    double F[9];
    if (!conformal_residual(S, F, dr_dT)) return false;
    for (int n = 0; n < 9; ++n) {
      r[n] = c_ * F[n];
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      const double ca = c_ * a, h = -0.5 * c_ / tau;
      for (int i = 0; i < 9; ++i) {
        double* row = dr_dT + 9 * i;
        const double hf = h * F[i];
        for (int m = 0; m < 9; ++m) row[m] = ca * row[m] + hf * C[m];
      }
    }
    return true;
  }

  Shape3dForm form_;
  double c_;
  Shape3dResidual residual_;
};

class ConformalShapeMetric final : public FixedMetric {
 public:
  ConformalShapeMetric()
      : FixedMetric("shape_3d", "mu_360", 3, MetricClass::kShape, false, 9, false) {}

  double value(const double* T) const override {
    const double f2 = small_matrix::frobenius2<3>(T);
    return f2 * std::sqrt(f2) / (3.0 * kSqrt3) - small_matrix::det<3>(T);
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    return conformal_residual(T, r, dr_dT);
  }
};

}  // namespace

std::unique_ptr<Metric> make_shape_3d_metric(Shape3dForm form, Shape3dResidual residual) {
  switch (form) {
    case Shape3dForm::kNonBarrier:
      return std::make_unique<ConformalShapeMetric>();
    case Shape3dForm::kBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "shape_barrier_3d", "mu_303", 2.0 / 3.0,
                                                  residual);
    case Shape3dForm::kCubicBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "shape_cubic_barrier_3d", "mu_304", 1.0,
                                                  residual);
    case Shape3dForm::kConditionBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "condition_barrier_3d", "mu_301", 2.0 / 3.0,
                                                  residual);
    case Shape3dForm::kConditionSquaredBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "condition_squared_barrier_3d", "mu_302",
                                                  4.0 / 3.0, residual);
  }
  return nullptr;
}

}  // namespace tmop
