// tmop/metric/size_shape.cc
// Size+shape metrics |T - T^-t|^2 (barrier) and |T^t T - I|^2 + (tau - 1)^2 (see size_shape.h).
#include "tmop/metric/size_shape.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

template <int D>
class SizeShapeBarrierMetric final : public FixedMetric {
 public:
  SizeShapeBarrierMetric()
      : FixedMetric(D == 2 ? "size_shape_barrier_2d" : "size_shape_barrier_3d",
                    D == 2 ? "mu_7" : "mu_321", D, MetricClass::kShapeSize, true, D * D) {}

  double value(const double* T) const override {
    double r[D * D];
    if (residuals(T, r, nullptr)) return small_matrix::frobenius2<D>(r);
    const double tau = small_matrix::det<D>(T);
    return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    double C[D * D];
    small_matrix::cofactor<D>(T, C);
    const double tau = small_matrix::det_from_cofactor<D>(T, C);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    const double inv_tau = 1.0 / tau;
    double Ti[D * D];  // T^-t = C / tau
    for (int n = 0; n < D * D; ++n) {
      Ti[n] = C[n] * inv_tau;
      r[n] = T[n] - Ti[n];
    }
    for (int n = 0; n < D * D; ++n) {
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      // (T^-1)_jk = Ti[k][j] (Ti holds T^-t): d r_ij / d T_kl = delta + Ti_kj Ti_il.
      constexpr int M = D * D;
      for (int i = 0; i < D; ++i) {
        for (int j = 0; j < D; ++j) {
          double* row = dr_dT + M * (D * i + j);
          for (int k = 0; k < D; ++k) {
            const double a = Ti[D * k + j];
            for (int l = 0; l < D; ++l) row[D * k + l] = a * Ti[D * i + l];
          }
          row[D * i + j] += 1.0;
        }
      }
    }
    return true;
  }
};

template <int D>
class SizeShapeMetric final : public FixedMetric {
 public:
  static constexpr int kM = D * (D + 1) / 2 + 1;
  SizeShapeMetric()
      : FixedMetric(D == 2 ? "size_shape_2d" : "size_shape_3d", "", D, MetricClass::kShapeSize,
                    false, kM) {}

  double value(const double* T) const override {
    double r[kM];
    if (residuals(T, r, nullptr)) {
      double s = 0.0;
      for (int n = 0; n < kM; ++n) s += r[n] * r[n];
      return s;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    constexpr int M = D * D;
    // Residual order: diagonal C_ii, then C_ij for i < j in row order, then tau - 1.
    int n = 0;
    for (int i = 0; i < D; ++i) r[n++] = column_dot(T, i, i) - 1.0;
    for (int i = 0; i < D; ++i) {
      for (int j = i + 1; j < D; ++j) r[n++] = kSqrt2 * column_dot(T, i, j);
    }
    double Cof[M];
    small_matrix::cofactor<D>(T, Cof);
    const double tau = small_matrix::det_from_cofactor<D>(T, Cof);
    r[n] = tau - 1.0;
    for (int m = 0; m < kM; ++m) {
      if (!std::isfinite(r[m])) return false;
    }
    if (dr_dT != nullptr) {
      for (int m = 0; m < kM * M; ++m) dr_dT[m] = 0.0;
      // d C_ij / d T_kl = delta_lj T_ki + delta_li T_kj.
      n = 0;
      for (int i = 0; i < D; ++i, ++n) {
        double* row = dr_dT + M * n;
        for (int k = 0; k < D; ++k) row[D * k + i] = 2.0 * T[D * k + i];
      }
      for (int i = 0; i < D; ++i) {
        for (int j = i + 1; j < D; ++j, ++n) {
          double* row = dr_dT + M * n;
          for (int k = 0; k < D; ++k) {
            row[D * k + j] = kSqrt2 * T[D * k + i];
            row[D * k + i] = kSqrt2 * T[D * k + j];
          }
        }
      }
      double* row = dr_dT + M * n;
      for (int m = 0; m < M; ++m) row[m] = Cof[m];
    }
    return true;
  }

 private:
  // (T^t T)_ij = sum_k T_ki T_kj.
  static double column_dot(const double* T, int i, int j) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += T[D * k + i] * T[D * k + j];
    return s;
  }
};

}  // namespace

std::unique_ptr<Metric> make_size_shape_metric(bool barrier, int dim) {
  if (dim == 2) {
    if (barrier) return std::make_unique<SizeShapeBarrierMetric<2>>();
    return std::make_unique<SizeShapeMetric<2>>();
  }
  if (dim == 3) {
    if (barrier) return std::make_unique<SizeShapeBarrierMetric<3>>();
    return std::make_unique<SizeShapeMetric<3>>();
  }
  return nullptr;
}

}  // namespace tmop
