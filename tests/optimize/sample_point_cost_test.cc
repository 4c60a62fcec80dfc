// Every metric x every element type: the residual block's analytic Jacobian agrees with central
// differences, on random valid elements and random targets. The 3D
// barrier shape metrics use the polar form whose Jacobian holds the rotation fixed
// (metric/shape_3d.h): for them J^T r is checked against the numeric gradient of |r|^2 / 2,
// which is what the solver relies on.
#include "tmop/optimize/sample_point_cost.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "tmop/element/ideal_element.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"

namespace tmop {
namespace {

// max |J - J_numeric| / max(1, |J_numeric|) over all entries, central differences.
double jacobian_error(const SamplePointCost& cost, std::vector<double>* x) {
  const int n = static_cast<int>(cost.parameter_block_sizes().size());
  const int d = cost.parameter_block_sizes()[0];
  const int m = cost.num_residuals();
  std::vector<const double*> params;
  for (int i = 0; i < n; ++i) params.push_back(x->data() + i * d);
  std::vector<double> r(m), J(n * m * d), rp(m), rm(m);
  std::vector<double*> jac;
  for (int i = 0; i < n; ++i) jac.push_back(J.data() + i * m * d);
  EXPECT_TRUE(cost.Evaluate(params.data(), r.data(), jac.data()));
  double worst = 0;
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < d; ++a) {
      double& xi = (*x)[i * d + a];
      const double h = 1e-6, saved = xi;
      xi = saved + h;
      EXPECT_TRUE(cost.Evaluate(params.data(), rp.data(), nullptr));
      xi = saved - h;
      EXPECT_TRUE(cost.Evaluate(params.data(), rm.data(), nullptr));
      xi = saved;
      for (int k = 0; k < m; ++k) {
        const double numeric = (rp[k] - rm[k]) / (2 * h);
        worst = std::max(worst,
                         std::abs(jac[i][k * d + a] - numeric) / std::max(1.0, std::abs(numeric)));
      }
    }
  return worst;
}

// max |J^T r - grad(|r|^2/2)| / max |grad| with the gradient by central differences.
double gradient_error(const SamplePointCost& cost, std::vector<double>* x) {
  const int n = static_cast<int>(cost.parameter_block_sizes().size());
  const int d = cost.parameter_block_sizes()[0];
  const int m = cost.num_residuals();
  std::vector<const double*> params;
  for (int i = 0; i < n; ++i) params.push_back(x->data() + i * d);
  std::vector<double> r(m), J(n * m * d);
  std::vector<double*> jac;
  for (int i = 0; i < n; ++i) jac.push_back(J.data() + i * m * d);
  EXPECT_TRUE(cost.Evaluate(params.data(), r.data(), jac.data()));
  auto half_norm2 = [&]() {
    std::vector<double> rr(m);
    EXPECT_TRUE(cost.Evaluate(params.data(), rr.data(), nullptr));
    double s = 0;
    for (double v : rr) s += v * v;
    return s / 2;
  };
  double worst = 0, scale = 0;
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < d; ++a) {
      double analytic = 0;
      for (int k = 0; k < m; ++k) analytic += jac[i][k * d + a] * r[k];
      double& xi = (*x)[i * d + a];
      const double h = 1e-6, saved = xi;
      xi = saved + h;
      const double fp = half_norm2();
      xi = saved - h;
      const double fm = half_norm2();
      xi = saved;
      const double numeric = (fp - fm) / (2 * h);
      worst = std::max(worst, std::abs(analytic - numeric));
      scale = std::max(scale, std::abs(numeric));
    }
  return worst / std::max(scale, 1e-12);
}

TEST(SamplePointCost, AnalyticJacobianMatchesNumericForEveryMetricAndType) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  int checked = 0;
  for (int t = 0; t < kNumCellTypes; ++t) {
    const CellType type = static_cast<CellType>(t);
    const int d = cell_dim(type);
    if (d < 2) continue;
    const int n = cell_num_nodes(type);
    std::set<std::string> seen;
    for (const std::string& any_name : metric_names(d)) {
      std::unique_ptr<Metric> metric = make_metric(any_name, d);
      ASSERT_TRUE(metric) << any_name;
      const std::string name = metric->name();
      if (!seen.insert(name).second) continue;
      const bool polar =
          d == 3 && metric->barrier() && metric->metric_class() == MetricClass::kShape;
      // element: ideal element (affine image of the reference) plus noise
      double W[9];
      ideal_jacobian(type, W);
      std::vector<double> x(n * d);
      for (int i = 0; i < n; ++i) {
        const double* r = reference_node(type, i);
        for (int a = 0; a < d; ++a) {
          double v = 0;
          for (int b = 0; b < d; ++b) v += W[a * d + b] * r[b];
          x[i * d + a] = v + 0.3 * u(rng);
        }
      }
      // target: a random well-conditioned matrix
      double Winv[9];
      for (int k = 0; k < d * d; ++k) Winv[k] = (k % (d + 1) == 0 ? 1.0 : 0.0) + u(rng);
      for (const SamplePoint& p : sample_points(type, SampleRule::kDefault)) {
        double grad[kMaxCellNodes * 3], G[kMaxCellNodes * 3];
        shape_gradients(type, p.xi, grad);
        for (int i = 0; i < n; ++i)
          for (int b = 0; b < d; ++b) {
            double v = 0;
            for (int c = 0; c < d; ++c) v += Winv[c * d + b] * grad[i * d + c];
            G[i * d + b] = v;
          }
        SamplePointTerm term{metric.get(), G, 0.7};
        SamplePointCost cost(n, d, 1, &term);
        std::vector<const double*> params;
        for (int i = 0; i < n; ++i) params.push_back(&x[i * d]);
        // barrier metrics are undefined on inverted points: skip those points
        std::vector<double> r(cost.num_residuals());
        if (!cost.Evaluate(params.data(), r.data(), nullptr)) continue;
        if (polar) {
          EXPECT_LT(gradient_error(cost, &x), 1e-6) << cell_name(type) << " " << name;
        } else {
          EXPECT_LT(jacobian_error(cost, &x), 1e-6) << cell_name(type) << " " << name;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace tmop
