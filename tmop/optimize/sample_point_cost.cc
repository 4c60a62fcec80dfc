#include "tmop/optimize/sample_point_cost.h"

#include <cmath>

namespace tmop {

// Surface cells have at most 9 nodes (quad9).
constexpr int kMaxSurfaceNodes = 9;

SamplePointCost::SamplePointCost(int num_nodes, int dim, int num_terms,
                                 const SamplePointTerm* terms)
    : num_nodes_(num_nodes), dim_(dim), num_terms_(num_terms) {
  int m = 0;
  for (int t = 0; t < num_terms; ++t) {
    terms_[t] = terms[t];
    m += terms[t].metric->num_residuals();
  }
  set_num_residuals(m);
  mutable_parameter_block_sizes()->assign(num_nodes, dim);
}

// Surface cells work on the tangent coordinates y_i = F^T x_i (2 per node).
double const* const* SamplePointCost::tangent_coordinates(double const* const* x, double* y,
                                                          const double** yp) const {
  for (int i = 0; i < num_nodes_; ++i) {
    for (int a = 0; a < 2; ++a)
      y[2 * i + a] = frame_[a] * x[i][0] + frame_[2 + a] * x[i][1] + frame_[4 + a] * x[i][2];
    yp[i] = y + 2 * i;
  }
  return yp;
}

void SamplePointCost::set_surface_frame(const double* F) {
  frame_ = F;
  mutable_parameter_block_sizes()->assign(num_nodes_, 3);
}

namespace {

// J_i[k][a] = sum_b dr[k][a b] sg_i[b] for the m residuals of one term, written at rows
// row..row+m-1 of each present block. sg (the weighted G) is a local copy, so the compiler
// knows the stores into J cannot change it; a compile-time M > 0 unrolls the residual loop
// (M = 0: m at run time).
template <int D, int N, int M>
void chain_rule(int m, const double* dr, const double* sg, int row, double** jacobians) {
  constexpr int DD = D * D;
  const int mm = M > 0 ? M : m;
  for (int i = 0; i < N; ++i) {
    double* J = jacobians[i];
    if (!J) continue;
    const double* g = sg + i * D;
    J += row * D;
    for (int k = 0; k < mm; ++k) {
      const double* drk = dr + k * DD;
      for (int a = 0; a < D; ++a) {
        double v = 0;
        for (int b = 0; b < D; ++b) v += drk[a * D + b] * g[b];
        J[k * D + a] = v;
      }
    }
  }
}

template <int D, int N>
void chain_rule_any(int m, const double* dr, const double* sg, int row, double** jacobians) {
  switch (m) {
    case 2:
      return chain_rule<D, N, 2>(m, dr, sg, row, jacobians);
    case 3:
      return chain_rule<D, N, 3>(m, dr, sg, row, jacobians);
    case 4:
      return chain_rule<D, N, 4>(m, dr, sg, row, jacobians);
    case 5:
      return chain_rule<D, N, 5>(m, dr, sg, row, jacobians);
    case 9:
      return chain_rule<D, N, 9>(m, dr, sg, row, jacobians);
    default:
      return chain_rule<D, N, 0>(m, dr, sg, row, jacobians);
  }
}

}  // namespace

// Volume cells of the common sizes with compile-time D (dimension) and N (nodes): the loops
// unroll (the generic path below costs ~2x on a tet, docs/benchmarks.md). The weight is applied
// to G (N D products) rather than to dr/dT (m D^2).
template <int D, int N>
bool SamplePointCost::EvaluateFixed(double const* const* x, double* residuals,
                                    double** jacobians) const {
  constexpr int DD = D * D;
  int row = 0;
  for (int t = 0; t < num_terms_; ++t) {
    const SamplePointTerm& term = terms_[t];
    const double* G = term.G;
    double T[DD] = {};
    for (int i = 0; i < N; ++i)
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) T[a * D + b] += x[i][a] * G[i * D + b];
    const int m = term.metric->num_residuals();
    double dr[kMaxMetricResiduals * DD];
    double* r = residuals + row;
    if (!term.metric->residuals(T, r, jacobians ? dr : nullptr)) return false;
    const double s = term.sqrt_weight;
    for (int k = 0; k < m; ++k) r[k] *= s;
    if (jacobians) {
      double sg[N * D];
      for (int q = 0; q < N * D; ++q) sg[q] = s * G[q];
      chain_rule_any<D, N>(m, dr, sg, row, jacobians);
    }
    row += m;
  }
  return true;
}

bool SamplePointCost::guard_ok(double const* const* x_in) const {
  const int d = dim_, n = num_nodes_;
  double y[kMaxSurfaceNodes * 2];
  const double* yp[kMaxSurfaceNodes];
  double const* const* x = frame_ ? tangent_coordinates(x_in, y, yp) : x_in;
  for (int k = 0; k < guard_count_; ++k) {
    const double* G = guard_ + k * n * d;
    double A[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) A[a * d + b] += x[i][a] * G[i * d + b];
    const double det = d == 2 ? A[0] * A[3] - A[1] * A[2]
                              : A[0] * (A[4] * A[8] - A[5] * A[7]) -
                                    A[1] * (A[3] * A[8] - A[5] * A[6]) +
                                    A[2] * (A[3] * A[7] - A[4] * A[6]);
    if (!(det > 0)) return false;
  }
  return true;
}

bool SamplePointCost::Evaluate(double const* const* x_in, double* residuals,
                               double** jacobians) const {
  if (guard_ && !guard_ok(x_in)) return false;
  if (!frame_) {
    if (dim_ == 3) {
      if (num_nodes_ == 4) return EvaluateFixed<3, 4>(x_in, residuals, jacobians);
      if (num_nodes_ == 8) return EvaluateFixed<3, 8>(x_in, residuals, jacobians);
      if (num_nodes_ == 6) return EvaluateFixed<3, 6>(x_in, residuals, jacobians);
      if (num_nodes_ == 10) return EvaluateFixed<3, 10>(x_in, residuals, jacobians);
    } else {
      if (num_nodes_ == 3) return EvaluateFixed<2, 3>(x_in, residuals, jacobians);
      if (num_nodes_ == 4) return EvaluateFixed<2, 4>(x_in, residuals, jacobians);
      if (num_nodes_ == 6) return EvaluateFixed<2, 6>(x_in, residuals, jacobians);
    }
  }
  const int d = dim_, dd = d * d, n = num_nodes_;
  // Surface cells: work on the tangent coordinates y_i = F^T x_i.
  double y[kMaxSurfaceNodes * 2];
  const double* yp[kMaxSurfaceNodes];
  double const* const* x = frame_ ? tangent_coordinates(x_in, y, yp) : x_in;
  const int m_total = num_residuals();
  int row = 0;
  for (int t = 0; t < num_terms_; ++t) {
    const SamplePointTerm& term = terms_[t];
    const double* G = term.G;
    double T[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
      const double* xi = x[i];
      const double* g = G + i * d;
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) T[a * d + b] += xi[a] * g[b];
    }
    const int m = term.metric->num_residuals();
    double dr[kMaxMetricResiduals * 9];
    double* r = residuals + row;
    if (!term.metric->residuals(T, r, jacobians ? dr : nullptr)) return false;
    const double s = term.sqrt_weight;
    for (int k = 0; k < m; ++k) r[k] *= s;
    if (jacobians) {
      for (int i = 0; i < n; ++i) {
        double* J = jacobians[i];
        if (!J) continue;
        const double* g = G + i * d;
        for (int k = 0; k < m; ++k) {
          const double* drk = dr + k * dd;
          double v[3];
          for (int a = 0; a < d; ++a) {
            v[a] = 0;
            for (int b = 0; b < d; ++b) v[a] += drk[a * d + b] * g[b];
          }
          if (frame_) {  // d/dx_c = sum_a d/dy_a F_ca
            double* Jrow = J + (row + k) * 3;
            for (int c = 0; c < 3; ++c)
              Jrow[c] = s * (frame_[2 * c] * v[0] + frame_[2 * c + 1] * v[1]);
          } else {
            double* Jrow = J + (row + k) * d;
            for (int a = 0; a < d; ++a) Jrow[a] = s * v[a];
          }
        }
      }
    }
    row += m;
  }
  (void)m_total;
  return true;
}

}  // namespace tmop
