#include "tmop/optimize/sample_point_cost.h"

#include <cmath>

namespace tmop {

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

bool SamplePointCost::Evaluate(double const* const* x, double* residuals,
                               double** jacobians) const {
  const int d = dim_, dd = d * d, n = num_nodes_;
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
    const double s = term.sqrt_weight * sqrt_multiplier_;
    for (int k = 0; k < m; ++k) r[k] *= s;
    if (jacobians) {
      for (int i = 0; i < n; ++i) {
        double* J = jacobians[i];
        if (!J) continue;
        const double* g = G + i * d;
        for (int k = 0; k < m; ++k) {
          const double* drk = dr + k * dd;
          double* Jrow = J + (row + k) * d;
          for (int a = 0; a < d; ++a) {
            double v = 0;
            for (int b = 0; b < d; ++b) v += drk[a * d + b] * g[b];
            Jrow[a] = s * v;
          }
        }
      }
    }
    row += m;
  }
  (void)m_total;
  return true;
}

void SamplePointCost::set_weight_multiplier(double m) { sqrt_multiplier_ = std::sqrt(m); }

double SamplePointCost::value(double const* const* x) const {
  const int d = dim_, n = num_nodes_;
  double sum = 0;
  for (int t = 0; t < num_terms_; ++t) {
    const SamplePointTerm& term = terms_[t];
    double T[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) T[a * d + b] += x[i][a] * term.G[i * d + b];
    sum += term.sqrt_weight * term.sqrt_weight * (term.metric->value(T) - term.metric->min_value());
  }
  return sum;
}

}  // namespace tmop
