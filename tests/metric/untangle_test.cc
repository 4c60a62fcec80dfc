// tests/metric/untangle_test.cc
// UntangleMetric: the two branches of chi agree, chi' is right, the energy is finite and smooth
// through det T = 0 for eps > 0, exact residuals with exact Jacobian on both sides of 0.
#include "tmop/metric/untangle.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "tests/metric/metric_test_util.h"

namespace tmop {
namespace {

using metric_test::central_jacobian;
using metric_test::eval;
using metric_test::Mat;
using metric_test::random_rotation;
using metric_test::scaled_error;

double naive_chi(double tau, double eps) { return 0.5 * (tau + std::sqrt(eps * eps + tau * tau)); }

// diag(1, ..., 1, t) between two fixed rotations: det = t.
Mat through_zero(int d, double t, std::mt19937& rng) {
  std::mt19937 local = rng;  // same rotations for every t
  Mat D = Mat::Identity(d, d);
  D(d - 1, d - 1) = t;
  return random_rotation(d, local) * D * random_rotation(d, local);
}

TEST(Untangle, ChiBranchesAgreeNearZero) {
  for (double eps : {1.0, 0.1, 1e-3}) {
    for (int k = -100; k <= 100; ++k) {
      const double tau = eps * k / 100.0;
      const double chi = UntangleMetric::chi(tau, eps);
      EXPECT_NEAR(chi, naive_chi(tau, eps), 1e-13 * naive_chi(tau, eps)) << tau;
      EXPECT_GT(chi, 0.0);
    }
    EXPECT_DOUBLE_EQ(UntangleMetric::chi(0.0, eps), 0.5 * eps);
    // Continuous across tau = 0 from both sides.
    EXPECT_NEAR(UntangleMetric::chi(-1e-14, eps), UntangleMetric::chi(1e-14, eps), 1e-13);
  }
}

TEST(Untangle, ChiStableBranchForLargeNegativeTau) {
  const double eps = 0.1;
  for (double tau : {-1e3, -1e6, -1e9}) {
    const double chi = UntangleMetric::chi(tau, eps);
    // chi ~ eps^2 / (4 |tau|) where the naive formula cancels to 0.
    EXPECT_NEAR(chi, eps * eps / (4.0 * -tau), 1e-6 * eps * eps / (4.0 * -tau));
  }
  EXPECT_EQ(naive_chi(-1e9, eps), 0.0);  // why the stable branch exists
}

TEST(Untangle, ChiDerivativeMatchesCentralDifferences) {
  for (double eps : {1.0, 0.1, 1e-2}) {
    for (double tau : {-3.0, -0.5, -0.01, 0.0, 0.01, 0.5, 3.0}) {
      const double h = 1e-7;
      const double numeric =
          (UntangleMetric::chi(tau + h, eps) - UntangleMetric::chi(tau - h, eps)) / (2 * h);
      EXPECT_NEAR(UntangleMetric::chi_derivative(tau, eps), numeric, 1e-6) << tau << " " << eps;
    }
  }
}

TEST(Untangle, FiniteAndSmoothThroughZeroDeterminant) {
  std::mt19937 rng(7);
  for (int d = 2; d <= 3; ++d) {
    for (double eps : {0.5, 0.05}) {
      UntangleMetric m(d, eps, 0.3);
      for (int k = -40; k <= 40; ++k) {
        const double t = k / 20.0;  // det from -2 to 2, 0 included
        const Mat T = through_zero(d, t, rng);
        Eigen::VectorXd r;
        Mat J;
        ASSERT_TRUE(eval(m, T, &r, &J)) << t;
        ASSERT_TRUE(r.allFinite() && J.allFinite());
        const double v = m.value(T.data());
        ASSERT_TRUE(std::isfinite(v));
        EXPECT_NEAR(r.squaredNorm(), v, 1e-12 * v);
        const Mat Jn = central_jacobian(
            [&](const Mat& X) {
              Eigen::VectorXd rx;
              EXPECT_TRUE(eval(m, X, &rx, nullptr));
              return rx;
            },
            T, m.num_residuals());
        EXPECT_LT(scaled_error(J, Jn), 1e-6) << "d=" << d << " eps=" << eps << " t=" << t;
      }
      // Continuity of the value across det = 0.
      const double below = m.value(through_zero(d, -1e-12, rng).data());
      const double above = m.value(through_zero(d, 1e-12, rng).data());
      EXPECT_NEAR(below, above, 1e-9 * above);
    }
  }
}

TEST(Untangle, ValueMatchesTheNaiveFormulaWhereItIsAccurate) {
  std::mt19937 rng(3);
  for (int d = 2; d <= 3; ++d) {
    const double eps = 0.2, theta = 0.4;
    UntangleMetric m(d, eps, theta);
    for (double t : {-0.2, -0.05, 0.0, 0.05, 0.2, 1.0}) {
      const Mat T = through_zero(d, t, rng);
      const double tau = T.determinant();
      const double chi = naive_chi(tau, eps);
      const double expected =
          (1 - theta) * T.squaredNorm() / std::pow(chi, 2.0 / d) + theta * (1 + tau * tau) / chi;
      EXPECT_NEAR(m.value(T.data()), expected, 1e-12 * expected) << t;
    }
  }
}

TEST(Untangle, PrefersValidElements) {
  for (int d = 2; d <= 3; ++d) {
    UntangleMetric m(d, 1e-3, 0.5);
    const Mat I = Mat::Identity(d, d);
    Mat flipped = I;
    flipped(0, 0) = -1.0;
    EXPECT_NEAR(m.value(I.data()), d * 0.5 + 2 * 0.5, 1e-5);
    EXPECT_GT(m.value(flipped.data()), 1e5 * m.value(I.data()));
    for (double s : {0.8, 1.25}) {
      const Mat X = s * I;
      EXPECT_GT(m.value(X.data()), m.value(I.data()));
    }
  }
}

TEST(Untangle, ZeroEpsIsABarrier) {
  UntangleMetric m(2, 0.0, 0.5);
  Mat T = Mat::Identity(2, 2);
  T(1, 1) = -0.5;
  double r[6], J[24];
  EXPECT_FALSE(m.residuals(T.data(), r, J));
  EXPECT_EQ(m.value(T.data()), std::numeric_limits<double>::infinity());
  T(1, 1) = 0.5;
  EXPECT_TRUE(m.residuals(T.data(), r, J));
}

TEST(Untangle, ConstructionChecksItsParameters) {
  EXPECT_THROW(UntangleMetric(4), std::invalid_argument);
  EXPECT_THROW(UntangleMetric(2, -1.0), std::invalid_argument);
  EXPECT_THROW(UntangleMetric(2, 0.1, 1.5), std::invalid_argument);
  UntangleMetric m(3, 0.25, 0.75);
  EXPECT_EQ(m.name(), "untangle_3d");
  EXPECT_EQ(m.num_residuals(), 11);
  EXPECT_EQ(m.metric_class(), MetricClass::kUntangle);
  EXPECT_DOUBLE_EQ(m.eps(), 0.25);
  EXPECT_DOUBLE_EQ(m.theta(), 0.75);
  EXPECT_FALSE(m.barrier());
}

}  // namespace
}  // namespace tmop
