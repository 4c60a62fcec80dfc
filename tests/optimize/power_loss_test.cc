// PowerLoss (the power objective's Ceres loss) and the stage's power objective: derivatives
// against central differences, the model cutoff changes only rho'', p = 1 is the plain mean, small
// arguments stay accurate, bad parameters are refused, and a stage minimises exactly the objective
// stage.h states.
#include "tmop/optimize/power_loss.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "grid_meshes.h"
#include "tmop/element/ideal_element.h"
#include "tmop/metric/metric.h"
#include "tmop/optimize/stage.h"

namespace tmop {
namespace {

TEST(PowerLoss, DerivativesAgreeWithCentralDifferences) {
  for (double p : {1.0, 1.5, 2.0, 3.0, 4.5})
    for (double m : {1e-3, 0.25, 7.0})
      for (double s : {1e-4, 0.1, 1.0, 30.0}) {
        const PowerLoss loss(p, 0.7, m, INFINITY);  // the exact rho'' everywhere
        double r[3], rp[3], rm[3];
        loss.Evaluate(s, r);
        const double h = 1e-6 * std::max(s, m);
        loss.Evaluate(s + h, rp);
        loss.Evaluate(s - h, rm);
        EXPECT_NEAR(r[1], (rp[0] - rm[0]) / (2 * h), 1e-6 * std::abs(r[1]))
            << "p " << p << " m " << m << " s " << s;
        EXPECT_NEAR(r[2], (rp[1] - rm[1]) / (2 * h), 1e-6 * std::abs(r[2]) + 1e-12)
            << "p " << p << " m " << m << " s " << s;
        EXPECT_GE(r[1], 0.7 * (1 - 1e-15));  // every point counts at least as in the plain mean
        EXPECT_GE(r[2], 0.0);  // convex: Ceres applies its full second-order correction
      }
}

// Beyond s = cutoff x m only the model's curvature changes: rho and rho' are those of the exact
// loss, rho'' is 0; below it all three are the exact loss's.
TEST(PowerLoss, ModelCutoffDropsOnlyTheCurvatureFarOut) {
  for (double p : {1.5, 2.0, 3.0})
    for (double cutoff : {1.0, PowerLoss::kDefaultModelCutoff}) {
      const PowerLoss exact(p, 0.7, 0.2, INFINITY), cut(p, 0.7, 0.2, cutoff);
      EXPECT_EQ(cut.model_cutoff(), cutoff);
      for (double t : {0.0, 0.5, 0.99, 1.01, 10.0, 49.0, 51.0, 1e4}) {
        double re[3], rc[3];
        exact.Evaluate(t * 0.2, re);
        cut.Evaluate(t * 0.2, rc);
        EXPECT_EQ(rc[0], re[0]);
        EXPECT_EQ(rc[1], re[1]);
        EXPECT_EQ(rc[2], t > cutoff ? 0.0 : re[2]) << "p " << p << " t " << t;
      }
    }
  EXPECT_EQ(StageSpec().power_model_cutoff, PowerLoss::kDefaultModelCutoff);
}

TEST(PowerLoss, OrderOneIsThePlainMeanAndSmallArgumentsStayAccurate) {
  const PowerLoss plain(1.0, 2.0, 0.3);
  double r[3];
  plain.Evaluate(5.0, r);
  EXPECT_DOUBLE_EQ(r[0], 10.0);
  EXPECT_DOUBLE_EQ(r[1], 2.0);
  EXPECT_EQ(r[2], 0.0);
  // rho = w (m/p)((1 + s/m)^p - 1) ~ w s (1 + (p-1) s / (2m)) for s << m: no cancellation.
  for (double p : {2.0, 3.0}) {
    const PowerLoss loss(p, 1.0, 1.0);
    const double s = 1e-12;
    loss.Evaluate(s, r);
    EXPECT_NEAR(r[0], s * (1 + (p - 1) * s / 2), 1e-15 * s);
  }
  const PowerLoss loss(2.0, 1.0, 1.0);
  loss.Evaluate(-1.0, r);  // a squared norm cannot be negative: treated as 0
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 1.0);
}

TEST(PowerLoss, RefusesBadParameters) {
  EXPECT_THROW(PowerLoss(0.5, 1, 1), std::invalid_argument);
  EXPECT_THROW(PowerLoss(NAN, 1, 1), std::invalid_argument);
  EXPECT_THROW(PowerLoss(2, -1, 1), std::invalid_argument);
  EXPECT_THROW(PowerLoss(2, 1, 0), std::invalid_argument);
  EXPECT_THROW(PowerLoss(2, 1, INFINITY), std::invalid_argument);
  EXPECT_THROW(PowerLoss(2, 1, 1, 0), std::invalid_argument);
  EXPECT_THROW(PowerLoss(2, 1, 1, NAN), std::invalid_argument);
}

// Per-tet mu_303 of T = A W^-1 (one point per tet, W the regular tet: stage.cc's default).
std::vector<double> tet_values(const Mesh& mesh) {
  const auto metric = make_metric("shape_barrier_3d", 3);
  double W[9], Winv[9];
  ideal_jacobian(CellType::kTet4, W);
  // Inverse through the cofactors.
  const double det = W[0] * (W[4] * W[8] - W[5] * W[7]) - W[1] * (W[3] * W[8] - W[5] * W[6]) +
                     W[2] * (W[3] * W[7] - W[4] * W[6]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      Winv[i * 3 + j] = (W[i1 * 3 + j1] * W[i2 * 3 + j2] - W[i1 * 3 + j2] * W[i2 * 3 + j1]) / det;
    }
  std::vector<double> v;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, 3)) continue;
    const std::int32_t* n = mesh.cell(c);
    double A[9], T[9];
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 3; ++k) A[a * 3 + k] = mesh.vertex(n[k + 1])[a] - mesh.vertex(n[0])[a];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        T[a * 3 + b] = 0;
        for (int k = 0; k < 3; ++k) T[a * 3 + b] += A[a * 3 + k] * Winv[k * 3 + b];
      }
    v.push_back(metric->value(T) - metric->min_value());
  }
  return v;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / v.size();
}

double power_objective(const std::vector<double>& v, double p, double m) {
  double s = 0;
  for (double x : v) s += m / p * (std::pow(1 + x / m, p) - 1);
  return s / v.size();
}

// A mu_303 shape stage of power p run to tight convergence on one thread.
StageSpec converging_shape_spec(double p) {
  StageSpec spec;
  spec.power = p;
  spec.solver.threads = 1;
  spec.solver.objective_tolerance = 1e-12;
  spec.solver.function_tolerance = 1e-14;
  spec.solver.movement_tolerance = 1e-12;
  spec.solver.gradient_tolerance = 1e-12;
  TermSpec term;
  term.metric = std::shared_ptr<const Metric>(make_metric("shape_barrier_3d", 3).release());
  spec.terms.push_back(term);
  return spec;
}

// Each stage minimises its own objective: the p = 2 result has the lower power objective, the
// p = 1 result the lower mean, and the scale is the stated fraction of the input's mean.
TEST(PowerObjective, EachPowerMinimisesItsOwnObjective) {
  const int n = 4;
  Mesh input = testing_grid::grid(CellType::kTet4, n);
  // A bent block: with its boundary fixed no arrangement makes every tet alike, so the two
  // objectives have different minimisers.
  for (int v = 0; v < input.num_vertices(); ++v) {
    double* x = input.vertex(v);
    x[0] += 0.4 * x[1] * x[1] + 0.2 * x[2];
    x[2] *= 1 + 0.8 * x[0];
  }
  std::mt19937 rng(11);
  testing_grid::perturb(&input, n, 0.45, &rng);
  const double input_mean = mean(tet_values(input));
  Mesh results[2] = {input, input};
  double scale = 0;
  for (int k = 0; k < 2; ++k) {
    StageSpec spec = converging_shape_spec(k == 0 ? 1.0 : 2.0);
    StageResult result;
    ASSERT_TRUE(optimize_stage(&results[k], spec, &result).ok());
    EXPECT_EQ(result.inverted_after, 0);
    if (k == 0) {
      EXPECT_EQ(result.power_scale, 0.0);
    } else {
      scale = result.power_scale;
    }
  }
  EXPECT_NEAR(scale, 0.25 * input_mean, 1e-9 * input_mean);
  const std::vector<double> v1 = tet_values(results[0]), v2 = tet_values(results[1]);
  EXPECT_LT(mean(v1), mean(v2));
  EXPECT_LT(power_objective(v2, 2, scale), power_objective(v1, 2, scale));
  // ... and the power pulls the worst element up.
  EXPECT_LT(*std::max_element(v2.begin(), v2.end()), *std::max_element(v1.begin(), v1.end()));
  std::printf("mean mu: p=1 %.6f, p=2 %.6f; worst mu: p=1 %.4f, p=2 %.4f\n", mean(v1), mean(v2),
              *std::max_element(v1.begin(), v1.end()), *std::max_element(v2.begin(), v2.end()));
}

// The model cutoff changes the path, not the objective: from a block whose worst tets start far
// beyond the cutoff, the exact model, the default cutoff and an aggressive one reach the same
// power objective and the same worst element.
TEST(PowerObjective, ModelCutoffChangesTheStepsNotTheMinimiser) {
  // A grid with strongly perturbed interior vertices: the first seed whose worst tet lies beyond
  // the default cutoff, i.e. above 50 m = 12.5 x the mean (deterministic: std::mt19937).
  const int n = 4;
  Mesh input;
  std::vector<double> v0;
  for (unsigned seed = 1; seed <= 50; ++seed) {
    input = testing_grid::grid(CellType::kTet4, n);
    std::mt19937 rng(seed);
    testing_grid::perturb(&input, n, 0.95, &rng);
    v0 = tet_values(input);
    if (*std::max_element(v0.begin(), v0.end()) > 2 * 12.5 * mean(v0)) break;
  }
  double objective[3], worst[3], scale = 0;
  const double cutoffs[3] = {INFINITY, PowerLoss::kDefaultModelCutoff, 1.0};
  for (int k = 0; k < 3; ++k) {
    Mesh mesh = input;
    StageSpec spec = converging_shape_spec(2.0);
    spec.power_model_cutoff = cutoffs[k];
    StageResult result;
    ASSERT_TRUE(optimize_stage(&mesh, spec, &result).ok());
    EXPECT_EQ(result.inverted_after, 0);
    scale = result.power_scale;
    const std::vector<double> v = tet_values(mesh);
    objective[k] = power_objective(v, 2, scale);
    worst[k] = *std::max_element(v.begin(), v.end());
    std::printf("cutoff %g: %d iterations, power objective %.10f, worst mu %.6f\n", cutoffs[k],
                result.iterations, objective[k], worst[k]);
  }
  // The input reaches beyond the default cutoff, so the cutoff is exercised.
  EXPECT_GT(*std::max_element(v0.begin(), v0.end()), PowerLoss::kDefaultModelCutoff * scale);
  for (int k = 1; k < 3; ++k) {
    EXPECT_NEAR(objective[k], objective[0], 1e-7 * objective[0]);
    EXPECT_NEAR(worst[k], worst[0], 1e-4 * worst[0]);
  }
}

// An extra sample point's weight goes into the loss: a bad one is refused with a message (the
// loss would throw) and the mesh is left as it was.
TEST(PowerObjective, RefusesABadExtraPointWeight) {
  const int n = 3;
  Mesh mesh = testing_grid::grid(CellType::kTet4, n);
  std::mt19937 rng(3);
  testing_grid::perturb(&mesh, n, 0.3, &rng);
  const std::vector<double> before = mesh.coords;
  int cell = 0;
  while (!mesh.is_element(cell, 3)) ++cell;
  for (double w : {-1.0, std::nan(""), HUGE_VAL}) {
    StageSpec spec;
    spec.power = 2;
    spec.solver.threads = 1;
    TermSpec term;
    term.metric = std::shared_ptr<const Metric>(make_metric("shape_barrier_3d", 3).release());
    spec.terms.push_back(term);
    const double xi[3] = {0.25, 0.25, 0.25};
    spec.extra_points.add(cell, xi, w);
    StageResult result;
    const Status s = optimize_stage(&mesh, spec, &result);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.message().find("extra sample point 0"), std::string::npos) << s.message();
    EXPECT_EQ(mesh.coords, before);
  }
}

}  // namespace
}  // namespace tmop
