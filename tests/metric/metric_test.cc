// tests/metric/metric_test.cc
// Every registered metric in 2D and 3D: analytic dr/dT against central differences, exactness
// of |r|^2 (or second-order agreement for the equivalent forms), invariances of its class,
// minimum on the invariance set, barrier behaviour, non-finite input.
#include "tmop/metric/metric.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdio>
#include <limits>
#include <set>

#include "tests/metric/metric_test_util.h"

namespace tmop {
namespace {

using metric_test::central_jacobian;
using metric_test::eval;
using metric_test::Mat;
using metric_test::random_matrix;
using metric_test::random_rotation;
using metric_test::scaled_error;

struct Case {
  int dim;
  std::string name;
};

// Readable test parameters in gtest and ctest output.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (int d = 2; d <= 3; ++d) {
    for (const std::string& n : metric_test::canonical_names(d)) cases.push_back({d, n});
    // A weighted combination (make_metric's "W1*NAME1+W2*NAME2"): shape + size is shape+size.
    cases.push_back({d, "0.7*shape_barrier+0.3*size_barrier"});
  }
  return cases;
}

class MetricTest : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    metric_ = make_metric(GetParam().name, GetParam().dim);
    ASSERT_NE(metric_, nullptr);
    d_ = GetParam().dim;
  }
  // The 3D polar forms: their residual holds a polar rotation computed iteratively.
  bool polar() const { return d_ == 3 && metric_->barrier() && !metric_->exact_residuals(); }
  // Random T of the kind the metric accepts: det > 0, or det < 0 when negative.
  Mat sample(bool negative, double lo = 0.3, double hi = 3.0) {
    return random_matrix(d_, rng_, negative, lo, hi);
  }
  Eigen::VectorXd r_of(const Mat& T) const {
    Eigen::VectorXd r;
    EXPECT_TRUE(eval(*metric_, T, &r, nullptr));
    return r;
  }

  std::unique_ptr<Metric> metric_;
  int d_ = 0;
  std::mt19937 rng_{12345};
};

TEST_P(MetricTest, JacobianMatchesCentralDifferences) {
  const Metric& m = *metric_;
  double worst = 0.0;
  for (int sign = 0; sign < 2; ++sign) {
    const bool negative = sign == 1;
    if (negative && m.barrier()) continue;
    for (int trial = 0; trial < 40; ++trial) {
      const Mat T = trial < 30 ? sample(negative) : sample(negative, 0.1, 10.0);
      Eigen::VectorXd r;
      Mat J;
      ASSERT_TRUE(eval(m, T, &r, &J)) << T;
      const Mat Jn = central_jacobian([&](const Mat& X) { return r_of(X); }, T, m.num_residuals());
      const double err = scaled_error(J, Jn);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-6) << m.name() << " T=\n" << T << "\nJ=\n" << J << "\nJn=\n" << Jn;
    }
  }
  std::printf("[ metric   ] %-32s max |dr/dT - central| (scaled) = %.2e\n", m.name().c_str(),
              worst);
}

TEST_P(MetricTest, JtRIsTheGradientOfHalfTheSquaredResidual) {
  const Metric& m = *metric_;
  for (int trial = 0; trial < 20; ++trial) {
    const Mat T = sample(!m.barrier() && trial % 2 == 1);
    Eigen::VectorXd r;
    Mat J;
    ASSERT_TRUE(eval(m, T, &r, &J));
    const Mat g = (J.transpose() * r).transpose();
    const Mat gn = central_jacobian(
        [&](const Mat& X) {
          Eigen::VectorXd v(1);
          v(0) = 0.5 * r_of(X).squaredNorm();
          return v;
        },
        T, 1);
    EXPECT_LT(scaled_error(g, gn), 1e-6) << m.name() << "\n" << g << "\n" << gn;
  }
}

TEST_P(MetricTest, SquaredResidualIsValueMinusMinimum) {
  const Metric& m = *metric_;
  for (int trial = 0; trial < 50; ++trial) {
    const Mat T = sample(!m.barrier() && trial % 2 == 1);
    Eigen::VectorXd r;
    ASSERT_TRUE(eval(m, T, &r, nullptr));
    const double v = m.value(T.data());
    ASSERT_TRUE(std::isfinite(v));
    EXPECT_GE(v - m.min_value(), -1e-12 * std::max(1.0, std::abs(v)));
    if (m.exact_residuals()) {
      EXPECT_NEAR(r.squaredNorm(), v - m.min_value(), 1e-12 * std::max(1.0, std::abs(v)))
          << m.name();
    } else {
      EXPECT_GT(r.squaredNorm(), 0.0);  // off the minimiser set (almost surely)
    }
  }
}

TEST_P(MetricTest, EquivalentFormsAgreeToSecondOrderAtTheMinimum) {
  const Metric& m = *metric_;
  if (m.exact_residuals()) GTEST_SKIP() << "exact form";
  for (int trial = 0; trial < 20; ++trial) {
    // T = s Q1 (I + eps E) Q2: a small distortion of a point of the minimiser set s R.
    const double s = trial % 2 == 0 ? 1.0 : 2.5;
    Mat E = Mat::Random(d_, d_);
    const Mat Q1 = random_rotation(d_, rng_), Q2 = random_rotation(d_, rng_);
    for (double eps : {1e-3, 1e-4}) {
      const Mat T = s * Q1 * (Mat::Identity(d_, d_) + eps * E) * Q2;
      const double excess = m.value(T.data()) - m.min_value();
      const double rr = r_of(T).squaredNorm();
      ASSERT_GT(rr, 0.0);
      EXPECT_NEAR(excess / rr, 1.0, 20 * eps) << m.name() << " eps=" << eps;
    }
  }
}

TEST_P(MetricTest, InvariancesOfItsClass) {
  const Metric& m = *metric_;
  const MetricClass c = m.metric_class();
  for (int trial = 0; trial < 20; ++trial) {
    const Mat T = sample(false);
    const double v = m.value(T.data());
    const double rr = r_of(T).squaredNorm();
    const double tol = 1e-10 * std::max(1.0, std::abs(v));
    const Mat Q1 = random_rotation(d_, rng_), Q2 = random_rotation(d_, rng_);
    if (c == MetricClass::kShape || c == MetricClass::kShapeSize || c == MetricClass::kUntangle) {
      for (const Mat& X : {Mat(Q1 * T), Mat(T * Q2), Mat(Q1 * T * Q2)}) {
        EXPECT_NEAR(m.value(X.data()), v, tol) << m.name();
        EXPECT_NEAR(r_of(X).squaredNorm(), rr, tol) << m.name();
      }
    }
    if (c == MetricClass::kShape) {
      // Barrier shape metrics are scale invariant; the non-barrier ones are homogeneous of
      // degree d (their minimiser set s R is scale invariant).
      const double k = m.barrier() ? 0.0 : d_;
      for (double s : {0.25, 3.0}) {
        const Mat X = s * T;
        EXPECT_NEAR(m.value(X.data()), std::pow(s, k) * v, std::pow(s, k) * tol) << m.name();
        EXPECT_NEAR(r_of(X).squaredNorm(), std::pow(s, k) * rr, std::pow(s, k) * tol);
      }
    }
    if (c == MetricClass::kSize) {
      // Any volume-preserving change: T M with det M = 1.
      Mat M = random_matrix(d_, rng_);
      M /= std::pow(M.determinant(), 1.0 / d_);
      const Mat X = T * M;
      EXPECT_NEAR(m.value(X.data()), v, tol) << m.name();
      EXPECT_NEAR(r_of(X).squaredNorm(), rr, tol) << m.name();
    }
  }
}

TEST_P(MetricTest, MinimumExactlyOnTheInvarianceSet) {
  const Metric& m = *metric_;
  const MetricClass c = m.metric_class();
  if (c == MetricClass::kUntangle) GTEST_SKIP() << "regularised energy, tested in untangle_test";
  const double tol = polar() ? 1e-10 : 1e-12;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat R = random_rotation(d_, rng_);
    std::vector<Mat> minimisers;
    switch (c) {
      case MetricClass::kShape:
        minimisers = {R, Mat(0.5 * R), Mat(4.0 * R)};
        break;
      case MetricClass::kSize: {
        Mat M = random_matrix(d_, rng_);
        minimisers = {Mat(M / std::pow(M.determinant(), 1.0 / d_)), R};
        break;
      }
      case MetricClass::kShapeSize:
        minimisers = {R};
        break;
      default:
        minimisers = {Mat::Identity(d_, d_)};
        break;
    }
    for (const Mat& X : minimisers) {
      const double scale = c == MetricClass::kShape && !m.barrier() ? std::pow(X.norm(), d_) : 1.0;
      EXPECT_NEAR(m.value(X.data()), m.min_value(), 1e-12 * std::max(1.0, scale)) << m.name();
      EXPECT_LT(r_of(X).norm(), tol * std::max(1.0, scale)) << m.name() << "\n" << X;
    }
    // Off the set the metric is strictly above its minimum.
    const Mat off = R * (Mat::Identity(d_, d_) + 0.1 * Mat::Random(d_, d_)) * 1.3;
    EXPECT_GT(m.value(off.data()), m.min_value() + 1e-8) << m.name();
    EXPECT_GT(r_of(off).norm(), 1e-6) << m.name();
  }
}

TEST_P(MetricTest, BarrierRefusesNonPositiveDeterminant) {
  const Metric& m = *metric_;
  Eigen::VectorXd r(m.num_residuals());
  Mat J(m.num_residuals(), d_ * d_);
  Mat singular = Mat::Identity(d_, d_);
  singular(d_ - 1, d_ - 1) = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat T = trial == 0 ? singular : sample(true);
    if (m.barrier()) {
      EXPECT_FALSE(m.residuals(T.data(), r.data(), J.data())) << m.name();
      EXPECT_FALSE(m.residuals(T.data(), r.data(), nullptr)) << m.name();
      EXPECT_EQ(m.value(T.data()), std::numeric_limits<double>::infinity()) << m.name();
    } else {
      EXPECT_TRUE(m.residuals(T.data(), r.data(), J.data())) << m.name();
      EXPECT_TRUE(std::isfinite(m.value(T.data()))) << m.name();
      EXPECT_TRUE(r.allFinite() && J.allFinite()) << m.name();
    }
  }
}

TEST_P(MetricTest, BarrierValueGrowsWithoutBoundAsDeterminantVanishes) {
  const Metric& m = *metric_;
  if (!m.barrier()) GTEST_SKIP() << "not a barrier";
  const Mat Q1 = random_rotation(d_, rng_), Q2 = random_rotation(d_, rng_);
  double previous = 0.0, previous_rr = 0.0;
  for (double delta : {1e-1, 1e-2, 1e-4, 1e-6, 1e-8}) {
    Mat D = Mat::Identity(d_, d_);
    D(d_ - 1, d_ - 1) = delta;
    const Mat T = Q1 * D * Q2;
    const double v = m.value(T.data());
    EXPECT_GT(v, previous) << m.name() << " delta=" << delta;
    previous = v;
    // The least-squares form is a barrier too (Ceres minimises |r|^2, not value()).
    Eigen::VectorXd r;
    ASSERT_TRUE(eval(m, T, &r, nullptr));
    EXPECT_TRUE(r.allFinite());
    EXPECT_GT(r.squaredNorm(), previous_rr) << m.name() << " delta=" << delta;
    previous_rr = r.squaredNorm();
  }
  EXPECT_GT(previous, 1e4) << m.name();
  EXPECT_GT(previous_rr, 1e4) << m.name();
}

TEST_P(MetricTest, NonFiniteInputIsRefused) {
  const Metric& m = *metric_;
  Eigen::VectorXd r(m.num_residuals());
  Mat J(m.num_residuals(), d_ * d_);
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mat T = Mat::Identity(d_, d_);
    T(0, d_ - 1) = bad;
    EXPECT_FALSE(m.residuals(T.data(), r.data(), J.data())) << m.name() << " " << bad;
  }
}

INSTANTIATE_TEST_SUITE_P(AllMetrics, MetricTest, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.name;  // gtest: [A-Za-z0-9_] only
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name + (name.find("_2d") == std::string::npos &&
                                                  name.find("_3d") == std::string::npos
                                              ? "_" + std::to_string(info.param.dim) + "d"
                                              : std::string());
                         });

}  // namespace
}  // namespace tmop
