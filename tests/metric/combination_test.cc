// tests/metric/combination_test.cc
// WeightedSumMetric and PowerMeanMetric: stacked / powered residuals are exact, their Jacobians
// match central differences, metadata combines as documented, bad arguments throw.
#include <gtest/gtest.h>

#include <stdexcept>

#include "tests/metric/metric_test_util.h"
#include "tmop/metric/power_mean.h"
#include "tmop/metric/weighted_sum.h"

namespace tmop {
namespace {

using metric_test::central_jacobian;
using metric_test::eval;
using metric_test::Mat;
using metric_test::random_matrix;
using metric_test::scaled_error;

std::shared_ptr<const Metric> get(const std::string& name, int d) {
  return std::shared_ptr<const Metric>(make_metric(name, d));
}

void expect_consistent(const Metric& m, std::mt19937& rng, double p = 1.0,
                       const Metric* inner = nullptr) {
  for (int trial = 0; trial < 20; ++trial) {
    const Mat T = random_matrix(m.dim(), rng);
    Eigen::VectorXd r;
    Mat J;
    ASSERT_TRUE(eval(m, T, &r, &J));
    const double v = m.value(T.data());
    if (m.exact_residuals()) {
      EXPECT_NEAR(r.squaredNorm(), v - m.min_value(), 1e-12 * std::max(1.0, v)) << m.name();
    }
    if (inner != nullptr) {
      Eigen::VectorXd ri;
      ASSERT_TRUE(eval(*inner, T, &ri, nullptr));
      EXPECT_NEAR(r.squaredNorm(), std::pow(ri.squaredNorm(), p), 1e-12 * std::max(1.0, v));
    }
    const Mat Jn = central_jacobian(
        [&](const Mat& X) {
          Eigen::VectorXd rx;
          EXPECT_TRUE(eval(m, X, &rx, nullptr));
          return rx;
        },
        T, m.num_residuals());
    if (m.exact_residuals()) {
      EXPECT_LT(scaled_error(J, Jn), 1e-6) << m.name();
    } else {
      // Equivalent (polar) forms hold R fixed in dr/dT; J^t r is still the exact gradient.
      const Mat g = (J.transpose() * r).transpose();
      const Mat gn = (Jn.transpose() * r).transpose();
      EXPECT_LT(scaled_error(g, gn), 1e-6) << m.name();
    }
  }
}

TEST(WeightedSum, ShapePlusSizeIsAnExactShapeSizeBarrier) {
  std::mt19937 rng(1);
  WeightedSumMetric m(get("shape_barrier_2d", 2), 0.7, get("size_barrier_quadratic_2d", 2), 0.3);
  EXPECT_EQ(m.dim(), 2);
  EXPECT_EQ(m.num_residuals(), 3);
  EXPECT_TRUE(m.barrier());
  EXPECT_TRUE(m.exact_residuals());
  EXPECT_EQ(m.metric_class(), MetricClass::kShapeSize);
  EXPECT_EQ(m.name(), "0.7*shape_barrier_2d+0.3*size_barrier_quadratic_2d");
  EXPECT_EQ(m.alias(), "0.7*mu_2+0.3*mu_77");
  expect_consistent(m, rng);
  const Mat T = random_matrix(2, rng);
  EXPECT_NEAR(m.value(T.data()),
              0.7 * m.part_a().value(T.data()) + 0.3 * m.part_b().value(T.data()), 1e-14);
  const Mat I = Mat::Identity(2, 2);
  EXPECT_NEAR(m.value(I.data()), 0.0, 1e-15);
}

TEST(WeightedSum, ThreeDimensionalPolarPartKeepsItsForm) {
  std::mt19937 rng(2);
  WeightedSumMetric m(get("mu_303", 3), 1.0, get("mu_316", 3), 2.0);
  const int ma = m.part_a().num_residuals();  // 5: the deviatoric form of mu_303
  EXPECT_EQ(ma, 5);
  EXPECT_EQ(m.num_residuals(), ma + 1);
  EXPECT_TRUE(m.exact_residuals());  // both parts are exact sums of squares
  EXPECT_EQ(m.metric_class(), MetricClass::kShapeSize);
  for (int trial = 0; trial < 10; ++trial) {
    const Mat T = random_matrix(3, rng);
    Eigen::VectorXd r;
    Mat J;
    ASSERT_TRUE(eval(m, T, &r, &J));
    Eigen::VectorXd rb;
    ASSERT_TRUE(eval(m.part_b(), T, &rb, nullptr));
    EXPECT_NEAR(r(ma), std::sqrt(2.0) * rb(0), 1e-14);
  }
}

TEST(WeightedSum, RejectsBadParts) {
  EXPECT_THROW(WeightedSumMetric(get("size", 2), 1.0, get("size", 3), 1.0), std::invalid_argument);
  EXPECT_THROW(WeightedSumMetric(nullptr, 1.0, get("size", 3), 1.0), std::invalid_argument);
  EXPECT_THROW(WeightedSumMetric(get("size", 2), -1.0, get("shape", 2), 1.0),
               std::invalid_argument);
  // 9 + 9 residuals exceed kMaxMetricResiduals.
  EXPECT_THROW(WeightedSumMetric(get("size_shape_barrier", 3), 1.0, get("shape_barrier", 3), 1.0),
               std::invalid_argument);
}

TEST(WeightedSum, BarrierPartRefusesInvertedElements) {
  WeightedSumMetric m(get("shape_2d", 2), 1.0, get("size_barrier_2d", 2), 1.0);
  Mat T = Mat::Identity(2, 2);
  T(0, 0) = -1.0;
  double r[3];
  EXPECT_FALSE(m.residuals(T.data(), r, nullptr));
  EXPECT_EQ(m.value(T.data()), std::numeric_limits<double>::infinity());
}

TEST(PowerMean, SquaredResidualIsThePowerOfTheExcess) {
  std::mt19937 rng(4);
  for (double p : {1.0, 1.5, 2.0, 3.0}) {
    for (const char* name : {"shape_barrier_2d", "size_shape_2d"}) {
      auto inner = get(name, 2);
      PowerMeanMetric m(inner, p);
      EXPECT_EQ(m.num_residuals(), inner->num_residuals());
      expect_consistent(m, rng, p, inner.get());
    }
    auto inner = get("condition_barrier_3d", 3);
    PowerMeanMetric m(inner, p);
    EXPECT_TRUE(m.exact_residuals());  // the deviatoric form is exact
    expect_consistent(m, rng, p, inner.get());
  }
}

TEST(PowerMean, ZeroResidualHasZeroJacobian) {
  PowerMeanMetric m(get("size_shape_orientation", 3), 2.0);
  const Mat I = Mat::Identity(3, 3);
  Eigen::VectorXd r;
  Mat J;
  ASSERT_TRUE(eval(m, I, &r, &J));
  EXPECT_EQ(r.norm(), 0.0);
  EXPECT_EQ(J.norm(), 0.0);
  EXPECT_EQ(m.value(I.data()), 0.0);
}

TEST(PowerMean, RejectsBadOrder) {
  EXPECT_THROW(PowerMeanMetric(get("size", 2), 0.5), std::invalid_argument);
  EXPECT_THROW(PowerMeanMetric(nullptr, 2.0), std::invalid_argument);
  PowerMeanMetric m(get("mu_2", 2), 2);
  EXPECT_EQ(m.name(), "power(shape_barrier_2d,2)");
  EXPECT_EQ(m.alias(), "power(mu_2,2)");
}

}  // namespace
}  // namespace tmop
