// tmop/optimize/sample_point_cost.h
// The Ceres residual block of one sample point (surface cells: see set_surface_frame): for each
// metric term t,
//   T_t = A W_t^-1 = sum_i x_i G_ti^T,  G_ti = W_t^-T grad N_i(xi)   (d-vectors, precomputed),
//   r_t = sqrt(c_t) * metric_t.residuals(T_t),
// stacked. Parameter blocks are the cell's node coordinates (d doubles each, in the mesh's own
// storage). dr/dx_i[a] = sqrt(c_t) sum_b dr/dT_ab G_ti[b], so the Jacobian is exact whenever the
// metric's dr/dT is. Evaluate returns false when any term's metric does (a barrier metric at
// det T <= 0), on the residual-only path too: Ceres then rejects the step.
// The object does not own the metrics or G (they live in the Objective's arena).
#ifndef TMOP_OPTIMIZE_SAMPLE_POINT_COST_H_
#define TMOP_OPTIMIZE_SAMPLE_POINT_COST_H_

#include <ceres/cost_function.h>

#include "tmop/metric/metric.h"

namespace tmop {

constexpr int kMaxTerms = 2;

struct SamplePointTerm {
  const Metric* metric = nullptr;
  const double* G = nullptr;  // num_nodes x d, row-major
  double sqrt_weight = 1.0;
};

class SamplePointCost final : public ceres::CostFunction {
 public:
  SamplePointCost(int num_nodes, int dim, int num_terms, const SamplePointTerm* terms);
  // A surface cell (2D cell in 3D space): parameter blocks have 3 coordinates and
  // T = F^T A W^-1 with F the 3 x 2 tangent frame (row-major, columns t1, t2, t1 x t2 = the
  // geometry's normal), held fixed during a solve (exact derivatives for that F). Not owned.
  void set_surface_frame(const double* F);
  bool Evaluate(double const* const* x, double* residuals, double** jacobians) const override;

  // Validity guard: Evaluate fails unless det(sum_i x_i g_ki^T) > 0 at each of `count` extra
  // points k, g_ki = guard[(k * num_nodes + i) * d ...] (any G = W^-T grad N with det W > 0
  // gives the sign of det A). A barrier stage sampled at centroids or Gauss points sets the
  // cell's corners here on one block per cell, so that it cannot fold a corner. Not owned.
  void set_guard(const double* guard, int count) {
    guard_ = guard;
    guard_count_ = count;
  }

  // Replaces term t's metric by one with the same residual count (the untangler's eps schedule).
  void set_metric(int t, const Metric* metric) { terms_[t].metric = metric; }

 private:
  double const* const* tangent_coordinates(double const* const* x, double* y,
                                           const double** yp) const;
  bool guard_ok(double const* const* x) const;
  template <int D, int N>
  bool EvaluateFixed(double const* const* x, double* residuals, double** jacobians) const;

  int num_nodes_;
  int dim_;
  const double* frame_ = nullptr;
  int num_terms_;
  SamplePointTerm terms_[kMaxTerms];
  const double* guard_ = nullptr;
  int guard_count_ = 0;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_SAMPLE_POINT_COST_H_
