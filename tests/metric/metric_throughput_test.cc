// tests/metric/metric_throughput_test.cc
// Sample points per second for residuals + Jacobian of every metric (the Ceres hot path).
// Disabled by default (timing is not a correctness test); run with
//   tmop_metric_tests --gtest_also_run_disabled_tests --gtest_filter='*Throughput*'
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "tests/metric/metric_test_util.h"
#include "tmop/metric/shape_3d.h"

namespace tmop {
namespace {

using metric_test::Mat;

TEST(MetricThroughput, DISABLED_ResidualsAndJacobianPerSecond) {
  std::mt19937 rng(99);
  for (int d = 2; d <= 3; ++d) {
    // A pool of mildly distorted valid T, as in a mesh being optimised.
    constexpr int kPool = 1024;
    std::vector<double> pool(kPool * d * d);
    for (int k = 0; k < kPool; ++k) {
      const Mat T = metric_test::random_matrix(d, rng, false, 0.5, 2.0);
      for (int n = 0; n < d * d; ++n) pool[k * d * d + n] = T.data()[n];
    }
    std::vector<std::pair<std::string, std::unique_ptr<Metric>>> metrics;
    for (const std::string& name : metric_test::canonical_names(d)) {
      metrics.emplace_back(name, make_metric(name, d));
    }
    if (d == 3) {
      metrics.emplace_back("shape_barrier_3d (cofactor form)",
                           make_shape_3d_metric(Shape3dForm::kBarrier, Shape3dResidual::kCofactor));
      metrics.emplace_back(
          "shape_barrier_3d (rotation-fixed J)",
          make_shape_3d_metric(Shape3dForm::kBarrier, Shape3dResidual::kPolarRotationFixed));
    }
    for (const auto& [name, m] : metrics) {
      double r[kMaxMetricResiduals], J[kMaxMetricResiduals * 9];
      double sink = 0.0;
      const int n = 2000000;
      const auto t0 = std::chrono::steady_clock::now();
      for (int i = 0; i < n; ++i) {
        m->residuals(&pool[(i % kPool) * d * d], r, J);
        sink += r[0] + J[1];
      }
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("[ metric   ] %-34s %6.1f M points/s (residuals + Jacobian)  %g\n", name.c_str(),
                  n / s * 1e-6, sink * 0.0);
    }
  }
}

}  // namespace
}  // namespace tmop
