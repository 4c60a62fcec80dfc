// tests/geometry/manifold_invariants.h
// The invariants of ceres/manifold_test_utils.h (EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD), written
// with plain gtest because the geometry test target does not link gmock:
//   Plus(x, 0) = x, Minus(x, x) = 0, Minus(Plus(x, d), x) = d, Plus(x, Minus(y, x)) = y,
//   PlusJacobian and MinusJacobian against central differences, MinusJacobian * PlusJacobian = I.
// x and y must lie on the manifold, d be small enough for the chart.
#ifndef TMOP_TESTS_GEOMETRY_MANIFOLD_INVARIANTS_H_
#define TMOP_TESTS_GEOMETRY_MANIFOLD_INVARIANTS_H_

#include <ceres/manifold.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace tmop {
namespace testing_util {

inline void ExpectManifoldInvariants(const ceres::Manifold& m, const Eigen::VectorXd& x,
                                     const Eigen::VectorXd& delta, const Eigen::VectorXd& y,
                                     double tolerance) {
  const int a = m.AmbientSize(), t = m.TangentSize();
  ASSERT_EQ(x.size(), a);
  ASSERT_EQ(y.size(), a);
  ASSERT_EQ(delta.size(), t);
  const Eigen::VectorXd zero_t = Eigen::VectorXd::Zero(t);
  Eigen::VectorXd xp(a), d(t), back(a);

  ASSERT_TRUE(m.Plus(x.data(), zero_t.data(), xp.data()));
  EXPECT_LE((xp - x).norm(), tolerance) << "Plus(x, 0) != x";

  ASSERT_TRUE(m.Minus(x.data(), x.data(), d.data()));
  EXPECT_LE(d.norm(), tolerance) << "Minus(x, x) != 0";

  ASSERT_TRUE(m.Plus(x.data(), delta.data(), xp.data()));
  ASSERT_TRUE(m.Minus(xp.data(), x.data(), d.data()));
  EXPECT_LE((d - delta).norm(), tolerance * std::max(1.0, delta.norm()))
      << "Minus(Plus(x, d), x) != d: " << d.transpose() << " vs " << delta.transpose();

  ASSERT_TRUE(m.Minus(y.data(), x.data(), d.data()));
  ASSERT_TRUE(m.Plus(x.data(), d.data(), back.data()));
  EXPECT_LE((back - y).norm(), tolerance * std::max(1.0, y.norm())) << "Plus(x, Minus(y, x)) != y";

  // Jacobians against central differences (step h: truncation ~h^2, round-off ~eps/h).
  const double h = 1e-6;
  Eigen::MatrixXd jp(a, t), jm(t, a);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> buf_p(a, t), buf_m(t, a);
  ASSERT_TRUE(m.PlusJacobian(x.data(), buf_p.data()));
  ASSERT_TRUE(m.MinusJacobian(x.data(), buf_m.data()));
  jp = buf_p;
  jm = buf_m;
  Eigen::MatrixXd np(a, t), nm(t, a);
  for (int j = 0; j < t; ++j) {
    Eigen::VectorXd dp = Eigen::VectorXd::Zero(t), dn = dp, xp1(a), xm1(a);
    dp[j] = h;
    dn[j] = -h;
    ASSERT_TRUE(m.Plus(x.data(), dp.data(), xp1.data()));
    ASSERT_TRUE(m.Plus(x.data(), dn.data(), xm1.data()));
    np.col(j) = (xp1 - xm1) / (2 * h);
  }
  for (int i = 0; i < a; ++i) {
    Eigen::VectorXd yp = x, yn = x, dp(t), dn(t);
    yp[i] += h;
    yn[i] -= h;
    ASSERT_TRUE(m.Minus(yp.data(), x.data(), dp.data()));
    ASSERT_TRUE(m.Minus(yn.data(), x.data(), dn.data()));
    nm.col(i) = (dp - dn) / (2 * h);
  }
  const double jtol = std::max(tolerance, 1e-7);
  EXPECT_LE((jp - np).norm(), jtol) << "PlusJacobian\n" << jp << "\nnumeric\n" << np;
  EXPECT_LE((jm - nm).norm(), jtol) << "MinusJacobian\n" << jm << "\nnumeric\n" << nm;
  EXPECT_LE((jm * jp - Eigen::MatrixXd::Identity(t, t)).norm(), tolerance)
      << "MinusJacobian * PlusJacobian != I";
}

}  // namespace testing_util
}  // namespace tmop

#endif  // TMOP_TESTS_GEOMETRY_MANIFOLD_INVARIANTS_H_
