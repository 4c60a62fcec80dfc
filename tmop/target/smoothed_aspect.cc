// tmop/target/smoothed_aspect.cc
#include "tmop/target/smoothed_aspect.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tmop/element/cell_type.h"
#include "tmop/element/ideal_element.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

namespace {

// Inverse of a d x d row-major matrix (d = 2, 3); false when singular.
bool invert(int d, const double* M, double* inv) {
  if (d == 2) {
    const double det = M[0] * M[3] - M[1] * M[2];
    if (det == 0 || !std::isfinite(det)) return false;
    inv[0] = M[3] / det, inv[1] = -M[1] / det, inv[2] = -M[2] / det, inv[3] = M[0] / det;
    return true;
  }
  const double c00 = M[4] * M[8] - M[5] * M[7], c01 = M[5] * M[6] - M[3] * M[8],
               c02 = M[3] * M[7] - M[4] * M[6];
  const double det = M[0] * c00 + M[1] * c01 + M[2] * c02;
  if (det == 0 || !std::isfinite(det)) return false;
  inv[0] = c00 / det, inv[1] = (M[2] * M[7] - M[1] * M[8]) / det;
  inv[2] = (M[1] * M[5] - M[2] * M[4]) / det, inv[3] = c01 / det;
  inv[4] = (M[0] * M[8] - M[2] * M[6]) / det, inv[5] = (M[2] * M[3] - M[0] * M[5]) / det;
  inv[6] = c02 / det, inv[7] = (M[1] * M[6] - M[0] * M[7]) / det;
  inv[8] = (M[0] * M[4] - M[1] * M[3]) / det;
  return true;
}

double det_small(int d, const double* G) {
  if (d == 2) return G[0] * G[3] - G[1] * G[2];
  return G[0] * (G[4] * G[8] - G[5] * G[7]) - G[1] * (G[3] * G[8] - G[5] * G[6]) +
         G[2] * (G[3] * G[7] - G[4] * G[6]);
}

}  // namespace

Status SmoothedAspect::build(const Mesh& mesh, int passes) {
  const int d = mesh.dim(), sd = mesh.space_dim, nv = mesh.num_vertices();
  const int n2 = sd * sd;
  sd_ = sd;
  vertex_tensor_.assign(kNumCellTypes, {});
  std::vector<std::vector<int>> count(kNumCellTypes);
  std::vector<double> cell_tensor(std::size_t(mesh.num_cells()) * n2, 0.0);
  double coords[kMaxCellNodes * 3], J[9], Winv[9], P[9], G[9];
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const CellType t = mesh.cell_type(c);
    const int lin = static_cast<int>(cell_info(t).linear);
    if (vertex_tensor_[lin].empty()) {
      vertex_tensor_[lin].assign(std::size_t(nv) * n2, 0.0);
      count[lin].assign(nv, 0);
    }
    for (int i = 0; i < mesh.cell_size(c); ++i)
      std::copy_n(mesh.vertex(mesh.cell(c)[i]), sd, coords + i * sd);
    invert(d, ideal_jacobian(t), Winv);
    double* S = &cell_tensor[std::size_t(c) * n2];
    const auto& points = sample_points(t, SampleRule::kDefault);
    for (const SamplePoint& p : points) {
      cell_jacobian(t, coords, sd, p.xi, J);
      for (int a = 0; a < sd; ++a)
        for (int j = 0; j < d; ++j) {
          double s = 0;
          for (int k = 0; k < d; ++k) s += J[a * d + k] * Winv[k * d + j];
          P[a * d + j] = s;
        }
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          double s = 0;
          for (int a = 0; a < sd; ++a) s += P[a * d + i] * P[a * d + j];
          G[i * d + j] = s;
        }
      const double g = det_small(d, G);
      double Ginv[9], Q[9];
      if (!(g > 0) || !std::isfinite(g) || !invert(d, G, Ginv))
        return Status::Failure("smooth aspect: cell " + std::to_string(c) +
                               " is degenerate at a sample point");
      // M = P+^T P+ with P+ = G^-1 P^T (the inverse of P on the cell's tangent space): an edge
      // e of the cell has |P+ e|^2 = e^T M e, 1 for the images of the ideal element's edges.
      for (int a = 0; a < sd; ++a)
        for (int j = 0; j < d; ++j) {
          double q = 0;
          for (int k = 0; k < d; ++k) q += P[a * d + k] * Ginv[k * d + j];
          Q[a * d + j] = q;
        }
      const double scale = std::pow(g, 1.0 / d) / points.size();
      for (int a = 0; a < sd; ++a)
        for (int b = 0; b < sd; ++b) {
          double m = 0;
          for (int j = 0; j < d; ++j) m += Q[a * d + j] * Q[b * d + j];
          S[a * sd + b] += m * scale;
        }
    }
  }
  // cell -> vertex averages, then (passes - 1) times vertex -> cell -> vertex.
  for (int pass = 0; pass < std::max(passes, 1); ++pass) {
    if (pass > 0)
      for (int c = 0; c < mesh.num_cells(); ++c) {
        if (!mesh.is_element(c, d)) continue;
        const CellType t = mesh.cell_type(c);
        const int lin = static_cast<int>(cell_info(t).linear);
        const int nc = cell_info(t).num_corners;
        double* S = &cell_tensor[std::size_t(c) * n2];
        std::fill_n(S, n2, 0.0);
        for (int i = 0; i < nc; ++i) {
          const double* V = &vertex_tensor_[lin][std::size_t(mesh.cell(c)[i]) * n2];
          for (int k = 0; k < n2; ++k) S[k] += V[k] / nc;
        }
      }
    for (int lin = 0; lin < kNumCellTypes; ++lin) {
      std::fill(vertex_tensor_[lin].begin(), vertex_tensor_[lin].end(), 0.0);
      std::fill(count[lin].begin(), count[lin].end(), 0);
    }
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (!mesh.is_element(c, d)) continue;
      const CellType t = mesh.cell_type(c);
      const int lin = static_cast<int>(cell_info(t).linear);
      const double* S = &cell_tensor[std::size_t(c) * n2];
      for (int i = 0; i < cell_info(t).num_corners; ++i) {
        const int v = mesh.cell(c)[i];
        double* V = &vertex_tensor_[lin][std::size_t(v) * n2];
        for (int k = 0; k < n2; ++k) V[k] += S[k];
        ++count[lin][v];
      }
    }
    for (int lin = 0; lin < kNumCellTypes; ++lin)
      for (int v = 0; v < static_cast<int>(count[lin].size()); ++v)
        if (count[lin][v] > 1)
          for (int k = 0; k < n2; ++k)
            vertex_tensor_[lin][std::size_t(v) * n2 + k] /= count[lin][v];
  }
  return Status::Ok();
}

void SmoothedAspect::aspect(const Mesh& mesh, int c, const double* xi, double* out) const {
  const int d = mesh.dim(), sd = sd_, n2 = sd * sd;
  const CellType t = mesh.cell_type(c);
  const CellType lin = cell_info(t).linear;
  const std::vector<double>& tensors = vertex_tensor_[static_cast<int>(lin)];
  double N[kMaxCellNodes], S[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  shape_values(lin, xi, N);
  for (int i = 0; i < cell_info(t).num_corners; ++i) {
    const double* V = &tensors[std::size_t(mesh.cell(c)[i]) * n2];
    for (int k = 0; k < n2; ++k) S[k] += N[i] * V[k];
  }
  double coords[kMaxCellNodes * 3], J[9];
  for (int i = 0; i < mesh.cell_size(c); ++i)
    std::copy_n(mesh.vertex(mesh.cell(c)[i]), sd, coords + i * sd);
  cell_jacobian(t, coords, sd, xi, J);
  const double* W = ideal_jacobian(t);
  for (int j = 0; j < d; ++j) {
    // On an affine cell P+ a_j = c w_j (w_j: the ideal element's column j, c the size), so
    // |w_j| sqrt(len2 / q) = |a_j| / c: the column lengths the aspect factor holds.
    double len2 = 0, q = 0, w2 = 0;
    for (int k = 0; k < d; ++k) w2 += W[k * d + j] * W[k * d + j];
    for (int a = 0; a < sd; ++a) len2 += J[a * d + j] * J[a * d + j];
    for (int a = 0; a < sd; ++a)
      for (int b = 0; b < sd; ++b) q += J[a * d + j] * S[a * sd + b] * J[b * d + j];
    out[j] = len2 > 0 && q > 0 ? std::sqrt(w2 * len2 / q) : std::sqrt(w2);
  }
}

}  // namespace tmop
