// tools/bench/floor.cc: tmop_bench's point table and hand-written floor pass (floor.h).
#include "tools/bench/floor.h"

#include <cmath>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"

namespace tmop_bench {
namespace {

// A^-1 of a d x d matrix (d = 2 or 3, row-major); false when singular.
bool invert(const double* A, int d, double* Ainv) {
  if (d == 2) {
    const double det = A[0] * A[3] - A[1] * A[2];
    if (!(det != 0)) return false;
    Ainv[0] = A[3] / det, Ainv[1] = -A[1] / det, Ainv[2] = -A[2] / det, Ainv[3] = A[0] / det;
    return true;
  }
  const double c0 = A[4] * A[8] - A[5] * A[7], c1 = A[5] * A[6] - A[3] * A[8],
               c2 = A[3] * A[7] - A[4] * A[6];
  const double det = A[0] * c0 + A[1] * c1 + A[2] * c2;
  if (!(det != 0)) return false;
  Ainv[0] = c0 / det, Ainv[1] = (A[2] * A[7] - A[1] * A[8]) / det;
  Ainv[2] = (A[1] * A[5] - A[2] * A[4]) / det, Ainv[3] = c1 / det;
  Ainv[4] = (A[0] * A[8] - A[2] * A[6]) / det, Ainv[5] = (A[2] * A[3] - A[0] * A[5]) / det;
  Ainv[6] = c2 / det, Ainv[7] = (A[1] * A[6] - A[0] * A[7]) / det;
  Ainv[8] = (A[0] * A[4] - A[1] * A[3]) / det;
  return true;
}

}  // namespace

tmop::Status build_points(const tmop::Mesh& mesh, const tmop::TargetSpec& target,
                          const std::vector<char>& fixed, PointTable* pt) {
  const int d = mesh.dim();
  std::vector<double> W;
  tmop::Status s = tmop::build_targets(mesh, tmop::SampleRule::kDefault, target, &W);
  if (!s.ok()) return s;
  pt->offset.assign(1, 0);
  std::size_t p = 0;
  double grad[tmop::kMaxCellNodes * 3], Winv[9];
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const tmop::CellType type = mesh.cell_type(c);
    const int n = mesh.cell_size(c);
    bool any_free = false;
    for (int i = 0; i < n; ++i) any_free |= !fixed[mesh.cell(c)[i]];
    for (const tmop::SamplePoint& sp : tmop::sample_points(type, tmop::SampleRule::kDefault)) {
      const double* Wp = W.data() + d * d * p++;
      if (!any_free) continue;
      if (!invert(Wp, d, Winv)) return tmop::Status::Failure("singular target");
      tmop::shape_gradients(type, sp.xi, grad);
      for (int i = 0; i < n; ++i)
        for (int b = 0; b < d; ++b) {
          double v = 0;
          for (int c2 = 0; c2 < d; ++c2) v += Winv[c2 * d + b] * grad[i * d + c2];
          pt->G.push_back(v);
        }
      pt->cell.push_back(c);
      pt->offset.push_back(static_cast<std::int64_t>(pt->G.size()));
      pt->weight.push_back(std::sqrt(sp.weight));
    }
  }
  return tmop::Status::Ok();
}

// One residual + gradient pass (the floor). Returns 0.5 |r|^2 like Ceres's cost; false when the
// metric fails (a barrier metric at an inverted point).
bool floor_pass(const tmop::Mesh& mesh, const PointTable& pt, const tmop::Metric& metric,
                std::vector<double>* gradient, double* cost) {
  const int d = mesh.dim(), dd = d * d, m = metric.num_residuals();
  gradient->assign(mesh.coords.size(), 0.0);
  double* g = gradient->data();
  double sum = 0;
  for (std::size_t p = 0; p < pt.cell.size(); ++p) {
    const std::int32_t* nodes = mesh.cell(pt.cell[p]);
    const double* G = pt.G.data() + pt.offset[p];
    const int n = static_cast<int>((pt.offset[p + 1] - pt.offset[p]) / d);
    double T[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < n; ++i) {
      const double* x = mesh.vertex(nodes[i]);
      const double* gi = G + i * d;
      for (int a = 0; a < d; ++a)
        for (int b = 0; b < d; ++b) T[a * d + b] += x[a] * gi[b];
    }
    double r[tmop::kMaxMetricResiduals], dr[tmop::kMaxMetricResiduals * 9];
    if (!metric.residuals(T, r, dr)) return false;
    const double w = pt.weight[p], w2 = w * w;
    double P[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  // dF/dT of 0.5 w^2 |r|^2
    for (int k = 0; k < m; ++k) {
      sum += w2 * r[k] * r[k];
      for (int q = 0; q < dd; ++q) P[q] += w2 * r[k] * dr[k * dd + q];
    }
    for (int i = 0; i < n; ++i) {
      double* gv = g + static_cast<std::size_t>(nodes[i]) * d;
      const double* gi = G + i * d;
      for (int a = 0; a < d; ++a) {
        double v = 0;
        for (int b = 0; b < d; ++b) v += P[a * d + b] * gi[b];
        gv[a] += v;
      }
    }
  }
  *cost = 0.5 * sum;
  return true;
}

}  // namespace tmop_bench
