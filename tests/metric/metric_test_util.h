// tests/metric/metric_test_util.h
// Helpers shared by the metric tests: random matrices with controlled determinant sign and
// conditioning, rotations, central-difference Jacobians and the list of metrics under test.
#ifndef TMOP_TESTS_METRIC_METRIC_TEST_UTIL_H_
#define TMOP_TESTS_METRIC_METRIC_TEST_UTIL_H_

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "tmop/metric/metric.h"

namespace tmop {
namespace metric_test {

using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Canonical names (no dimension-free names, no aliases) of every registered metric of dim d.
inline std::vector<std::string> canonical_names(int d) {
  std::vector<std::string> out;
  for (const std::string& n : metric_names(d)) {
    std::unique_ptr<Metric> m = make_metric(n, d);
    if (m && m->name() == n) out.push_back(n);
  }
  return out;
}

// A uniformly random rotation (det +1) of size d.
inline Mat random_rotation(int d, std::mt19937& rng) {
  std::normal_distribution<double> g;
  Mat A(d, d);
  for (int i = 0; i < d * d; ++i) A.data()[i] = g(rng);
  Eigen::HouseholderQR<Mat> qr(A);
  Mat Q = qr.householderQ();
  Mat R = qr.matrixQR().triangularView<Eigen::Upper>();
  for (int j = 0; j < d; ++j) {
    if (R(j, j) < 0) Q.col(j) *= -1.0;
  }
  if (Q.determinant() < 0) Q.col(0) *= -1.0;
  return Q;
}

// Q1 diag(s) Q2 with singular values in [lo, hi]; det < 0 when negative is set.
inline Mat random_matrix(int d, std::mt19937& rng, bool negative = false, double lo = 0.3,
                         double hi = 3.0) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  Mat S = Mat::Zero(d, d);
  for (int i = 0; i < d; ++i) S(i, i) = std::exp(u(rng));
  if (negative) S(d - 1, d - 1) *= -1.0;
  return random_rotation(d, rng) * S * random_rotation(d, rng);
}

// Residuals and analytic Jacobian; returns false when the metric refuses T.
inline bool eval(const Metric& m, const Mat& T, Eigen::VectorXd* r, Mat* J) {
  const int d = m.dim();
  r->resize(m.num_residuals());
  if (J == nullptr) return m.residuals(T.data(), r->data(), nullptr);
  J->resize(m.num_residuals(), d * d);
  return m.residuals(T.data(), r->data(), J->data());
}

// Central differences of f: R^(d*d) -> R^m at T, step h relative to max(1, |T_kl|).
template <typename F>
Mat central_jacobian(const F& f, const Mat& T, int m, double h = 1e-6) {
  const int n = static_cast<int>(T.size());
  Mat J(m, n);
  for (int k = 0; k < n; ++k) {
    const double step = h * std::max(1.0, std::abs(T.data()[k]));
    Mat Tp = T, Tm = T;
    Tp.data()[k] += step;
    Tm.data()[k] -= step;
    Eigen::VectorXd rp = f(Tp), rm = f(Tm);
    J.col(k) = (rp - rm) / (2.0 * step);
  }
  return J;
}

// max |A - B| / max(1, max |A|).
inline double scaled_error(const Mat& A, const Mat& B) {
  return (A - B).cwiseAbs().maxCoeff() / std::max(1.0, A.cwiseAbs().maxCoeff());
}

}  // namespace metric_test
}  // namespace tmop

#endif  // TMOP_TESTS_METRIC_METRIC_TEST_UTIL_H_
