#include "tmop/optimize/sample_measures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tmop/element/ideal_element.h"
#include "tmop/element/shape.h"

namespace tmop {

double det_d(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

bool inverse_d(const double* A, int d, double* Ainv) {
  const double det = det_d(A, d);
  if (!(det != 0) || !std::isfinite(det)) return false;
  if (d == 2) {
    Ainv[0] = A[3] / det;
    Ainv[1] = -A[1] / det;
    Ainv[2] = -A[2] / det;
    Ainv[3] = A[0] / det;
    return true;
  }
  Ainv[0] = (A[4] * A[8] - A[5] * A[7]) / det;
  Ainv[1] = (A[2] * A[7] - A[1] * A[8]) / det;
  Ainv[2] = (A[1] * A[5] - A[2] * A[4]) / det;
  Ainv[3] = (A[5] * A[6] - A[3] * A[8]) / det;
  Ainv[4] = (A[0] * A[8] - A[2] * A[6]) / det;
  Ainv[5] = (A[2] * A[3] - A[0] * A[5]) / det;
  Ainv[6] = (A[3] * A[7] - A[4] * A[6]) / det;
  Ainv[7] = (A[1] * A[6] - A[0] * A[7]) / det;
  Ainv[8] = (A[0] * A[4] - A[1] * A[3]) / det;
  return true;
}

// G_i = W^-T g_i for every node i: G[i*d + b] = sum_c Winv[c*d + b] g[i*d + c].
void make_G(int n, int d, const double* grad, const double* Winv, double* G) {
  for (int i = 0; i < n; ++i)
    for (int b = 0; b < d; ++b) {
      double v = 0;
      for (int c = 0; c < d; ++c) v += Winv[c * d + b] * grad[i * d + c];
      G[i * d + b] = v;
    }
}

namespace {

// compute_T of a volume cell with compile-time sizes: the loops unroll.
template <int D, int N>
void compute_T_fixed(const Mesh& mesh, const std::int32_t* nodes, const double* G, double* T) {
  double t[D * D] = {};
  for (int i = 0; i < N; ++i) {
    const double* x = mesh.vertex(nodes[i]);
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) t[a * D + b] += x[a] * G[i * D + b];
  }
  for (int k = 0; k < D * D; ++k) T[k] = t[k];
}

}  // namespace

// T = F^T X G: F (space_dim x d, row-major) is the tangent frame of a surface cell, or null
// when space_dim == d.
void compute_T(int n, int d, const Mesh& mesh, const std::int32_t* nodes, const double* G,
               double* T, const double* F) {
  if (!F) {
    if (d == 3 && n == 4) return compute_T_fixed<3, 4>(mesh, nodes, G, T);
    if (d == 2 && n == 3) return compute_T_fixed<2, 3>(mesh, nodes, G, T);
    if (d == 2 && n == 4) return compute_T_fixed<2, 4>(mesh, nodes, G, T);
    if (d == 3 && n == 8) return compute_T_fixed<3, 8>(mesh, nodes, G, T);
  }
  for (int k = 0; k < d * d; ++k) T[k] = 0;
  for (int i = 0; i < n; ++i) {
    const double* x = mesh.vertex(nodes[i]);
    double y[3];
    if (F) {
      for (int a = 0; a < d; ++a) {
        y[a] = 0;
        for (int c = 0; c < mesh.space_dim; ++c) y[a] += F[c * d + a] * x[c];
      }
      x = y;
    }
    for (int a = 0; a < d; ++a)
      for (int b = 0; b < d; ++b) T[a * d + b] += x[a] * G[i * d + b];
  }
}

void frame_from_normal(const double* n_in, double* F) {
  double n[3] = {n_in[0], n_in[1], n_in[2]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= len;
  // t1: the coordinate axis least aligned with n, made orthogonal to it.
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(n[a]) < std::abs(n[k])) k = a;
  double t1[3] = {0, 0, 0};
  t1[k] = 1;
  const double dot = t1[0] * n[0] + t1[1] * n[1] + t1[2] * n[2];
  for (int a = 0; a < 3; ++a) t1[a] -= dot * n[a];
  const double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
  for (double& v : t1) v /= l1;
  const double t2[3] = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                        n[0] * t1[1] - n[1] * t1[0]};
  for (int c = 0; c < 3; ++c) {
    F[c * 2 + 0] = t1[c];
    F[c * 2 + 1] = t2[c];
  }
}

// Frames from each cell's own corner-polygon (Newell) normal: a surface mesh measured in its
// cells' own planes (no geometry: folds are not visible this way).
void own_frame(const Mesh& mesh, int c, double* F) {
  const int k = cell_info(mesh.cell_type(c)).num_corners;
  double n[3] = {0, 0, 0};
  for (int i = 0; i < k; ++i) {
    const double* a = mesh.vertex(mesh.cell(c)[i]);
    const double* b = mesh.vertex(mesh.cell(c)[(i + 1) % k]);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) n[2] = 1;
  frame_from_normal(n, F);
}

Frames own_frames(const Mesh& mesh) {
  Frames f;
  if (mesh.space_dim != 3 || mesh.dim() != 2) return f;
  f.F.assign(6 * mesh.num_cells(), 0);
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (cell_dim(mesh.cell_type(c)) == 2) own_frame(mesh, c, f.F.data() + 6 * c);
  return f;
}

// min det T over the sample points of term 0, and the cells where it is <= 0.
double min_target_det(const Mesh& mesh, const std::vector<std::int32_t>& point_cell,
                      const GTable& G, std::vector<int>* bad, const Frames& frames) {
  const int d = mesh.dim();
  double worst = std::numeric_limits<double>::infinity();
  if (bad) bad->clear();
  for (std::size_t p = 0; p < point_cell.size(); ++p) {
    const int c = point_cell[p];
    double T[9];
    compute_T(mesh.cell_size(c), d, mesh, mesh.cell(c), G.at(p), T, frames.cell(c));
    const double det = det_d(T, d);
    worst = std::min(worst, det);
    if (bad && !(det > 0) && (bad->empty() || bad->back() != c)) bad->push_back(c);
  }
  if (bad) {  // extra points come after the canonical ones: a cell can appear twice
    std::sort(bad->begin(), bad->end());
    bad->erase(std::unique(bad->begin(), bad->end()), bad->end());
  }
  return worst;
}

// Shape quality of T: d det(T)^(2/d) / |T|^2, negative when det T < 0.
double shape_quality(const double* T, int d) {
  double f = 0;
  for (int k = 0; k < d * d; ++k) f += T[k] * T[k];
  const double det = det_d(T, d);
  if (!(f > 0)) return 0;
  const double mag = d == 2 ? std::abs(det) : std::cbrt(det * det);
  const double q = d * mag / f;
  return det > 0 ? q : -q;
}

IdealTable::IdealTable(SampleRule rule, int d) {
  for (int t = 0; t < kNumCellTypes; ++t) {
    const CellType type = static_cast<CellType>(t);
    if (cell_dim(type) != d) continue;
    double W[9], Winv[9], grad[kMaxCellNodes * 3];
    ideal_jacobian(type, W);
    inverse_d(W, d, Winv);
    const int n = cell_num_nodes(type);
    for (const SamplePoint& p : sample_points(type, rule)) {
      shape_gradients(type, p.xi, grad);
      G[t].resize(G[t].size() + n * d);
      make_G(n, d, grad, Winv, G[t].data() + G[t].size() - n * d);
    }
  }
}

IterationRecord measure(const Mesh& mesh, const IdealTable& table, const Frames& frames) {
  IterationRecord rec;
  const int d = mesh.dim();
  rec.min_quality = std::numeric_limits<double>::infinity();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const CellType t = mesh.cell_type(c);
    const int n = cell_num_nodes(t);
    const std::vector<double>& G = table.G[static_cast<int>(t)];
    bool inverted = false;
    for (std::size_t off = 0; off < G.size(); off += n * d) {
      double T[9];
      compute_T(n, d, mesh, mesh.cell(c), G.data() + off, T, frames.cell(c));
      const double q = shape_quality(T, d);
      if (!(det_d(T, d) > 0)) inverted = true;
      rec.min_quality = std::min(rec.min_quality, q);
    }
    rec.inverted += inverted;
  }
  if (!std::isfinite(rec.min_quality)) rec.min_quality = 0;
  return rec;
}

// The cells measure() counts as inverted.
std::vector<int> inverted_cells(const Mesh& mesh, const IdealTable& table, const Frames& frames) {
  std::vector<int> out;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const CellType t = mesh.cell_type(c);
    const int n = cell_num_nodes(t);
    const std::vector<double>& G = table.G[static_cast<int>(t)];
    for (std::size_t off = 0; off < G.size(); off += n * d) {
      double T[9];
      compute_T(n, d, mesh, mesh.cell(c), G.data() + off, T, frames.cell(c));
      if (!(det_d(T, d) > 0)) {
        out.push_back(c);
        break;
      }
    }
  }
  return out;
}

}  // namespace tmop
