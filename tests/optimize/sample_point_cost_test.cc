// Every metric x every element type: the residual block's analytic Jacobian agrees with central
// differences, and J^T r with the numeric gradient of |r|^2 / 2 (what the solver relies on), on
// random valid elements and random targets; the same for surface cells (2D cells in 3D, reduced
// in a tangent frame) and for the corner guard of centroid-sampled barrier blocks.
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
    std::vector<std::string> names = metric_names(d);
    // Weighted combinations (make_metric's "W1*NAME1+W2*NAME2") stack their parts' residuals.
    names.push_back("0.7*shape_barrier+0.3*size_barrier");
    names.push_back("shape+0.25*size");
    for (const std::string& any_name : names) {
      std::unique_ptr<Metric> metric = make_metric(any_name, d);
      ASSERT_TRUE(metric) << any_name;
      const std::string name = metric->name();
      if (!seen.insert(name).second) continue;
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
        EXPECT_LT(jacobian_error(cost, &x), 1e-6) << cell_name(type) << " " << name;
        EXPECT_LT(gradient_error(cost, &x), 1e-6) << cell_name(type) << " " << name;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// Surface cells: parameter blocks of 3 coordinates, T = F^T A W^-1 with F a 3 x 2 tangent frame;
// the Jacobian with respect to the 3D coordinates (F held fixed) against central differences.
TEST(SamplePointCost, SurfaceCellJacobianMatchesNumeric) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  int checked = 0;
  for (CellType type : {CellType::kTri3, CellType::kQuad4, CellType::kTri6, CellType::kQuad9}) {
    const int n = cell_num_nodes(type);
    // A tilted plane: orthonormal t1, t2 and the frame F = [t1 t2] (row-major 3 x 2).
    const double t1[3] = {0.8, 0.6, 0.0}, t2[3] = {-0.36, 0.48, 0.8};
    double F[6];
    for (int c = 0; c < 3; ++c) {
      F[2 * c] = t1[c];
      F[2 * c + 1] = t2[c];
    }
    std::set<std::string> seen;
    for (const std::string& any_name : metric_names(2)) {
      std::unique_ptr<Metric> metric = make_metric(any_name, 2);
      if (!seen.insert(metric->name()).second) continue;
      double W[4];
      ideal_jacobian(type, W);
      std::vector<double> x(n * 3);
      for (int i = 0; i < n; ++i) {
        const double* r = reference_node(type, i);
        const double p0 = W[0] * r[0] + W[1] * r[1] + 0.3 * u(rng);
        const double p1 = W[2] * r[0] + W[3] * r[1] + 0.3 * u(rng);
        for (int c = 0; c < 3; ++c) x[3 * i + c] = p0 * t1[c] + p1 * t2[c] + 0.2 * u(rng);
      }
      for (const SamplePoint& p : sample_points(type, SampleRule::kDefault)) {
        double grad[kMaxCellNodes * 3], G[kMaxCellNodes * 2];
        shape_gradients(type, p.xi, grad);
        for (int k = 0; k < 2 * n; ++k) G[k] = grad[k];  // W = I
        SamplePointTerm term{metric.get(), G, 0.9};
        SamplePointCost cost(n, 2, 1, &term);
        cost.set_surface_frame(F);
        ASSERT_EQ(cost.parameter_block_sizes()[0], 3);
        std::vector<const double*> params;
        for (int i = 0; i < n; ++i) params.push_back(&x[3 * i]);
        std::vector<double> r(cost.num_residuals());
        if (!cost.Evaluate(params.data(), r.data(), nullptr)) continue;
        EXPECT_LT(jacobian_error(cost, &x), 1e-6) << cell_name(type) << " " << metric->name();
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 40);
}

// The corner guard: a block whose guard points include a folded corner fails, residual-only
// path included, while the same block without the guard evaluates.
TEST(SamplePointCost, CornerGuardRefusesAFoldedCorner) {
  const CellType type = CellType::kQuad4;
  std::unique_ptr<Metric> metric = make_metric("shape_barrier", 2);
  // A dart: corner 2 pulled inside the triangle of the others folds the quad at corner 2 while
  // the centroid is still positively oriented.
  double x[8] = {0, 0, 1, 0, 0.3, 0.3, 0, 1};
  double centre_grad[8], corners[32];
  const double centre[3] = {0, 0, 0};
  shape_gradients(type, centre, centre_grad);
  const auto& pts = sample_points(type, SampleRule::kCorners);
  for (int k = 0; k < 4; ++k) shape_gradients(type, pts[k].xi, corners + 8 * k);
  SamplePointTerm term{metric.get(), centre_grad, 1.0};
  SamplePointCost cost(4, 2, 1, &term);
  const double* params[4] = {x, x + 2, x + 4, x + 6};
  double r[2], J[4][4];
  double* jac[4] = {J[0], J[1], J[2], J[3]};
  ASSERT_TRUE(cost.Evaluate(params, r, nullptr));  // the centroid alone sees nothing wrong
  cost.set_guard(corners, 4);
  EXPECT_FALSE(cost.Evaluate(params, r, nullptr));
  EXPECT_FALSE(cost.Evaluate(params, r, jac));
  x[4] = x[5] = 1;  // the unit square: every corner positive
  EXPECT_TRUE(cost.Evaluate(params, r, jac));
}

}  // namespace
}  // namespace tmop
