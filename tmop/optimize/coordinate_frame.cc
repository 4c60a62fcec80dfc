#include "tmop/optimize/coordinate_frame.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tmop {
namespace {

// The frame that makes the problem dimensionless: x' = R (x - centre) / length.
struct Normalization {
  CoordinateFrame f;
  void apply(Mesh* m) const {
    const int sd = m->space_dim;
    for (int v = 0; v < m->num_vertices(); ++v) {
      double* x = m->vertex(v);
      double y[3];
      for (int a = 0; a < sd; ++a) {
        y[a] = 0;
        for (int b = 0; b < sd; ++b) y[a] += f.rotation[3 * a + b] * (x[b] - f.centre[b]);
      }
      for (int a = 0; a < sd; ++a) x[a] = y[a] / f.length;
    }
  }
  void undo(Mesh* m) const {
    const int sd = m->space_dim;
    for (int v = 0; v < m->num_vertices(); ++v) {
      double* x = m->vertex(v);
      double y[3];
      for (int a = 0; a < sd; ++a) {
        y[a] = 0;
        for (int b = 0; b < sd; ++b) y[a] += f.rotation[3 * b + a] * x[b];
      }
      for (int a = 0; a < sd; ++a) x[a] = f.centre[a] + f.length * y[a];
    }
  }
};

double edge_length(const Mesh& m, int a, int b) {
  double s = 0;
  for (int k = 0; k < m.space_dim; ++k) {
    const double t = m.vertex(a)[k] - m.vertex(b)[k];
    s += t * t;
  }
  return std::sqrt(s);
}

}  // namespace

double element_edge_lengths(const Mesh& m, std::vector<double>* shortest) {
  shortest->assign(m.num_vertices(), std::numeric_limits<double>::infinity());
  double sum = 0;
  long count = 0;
  const int d = m.dim();
  for (int c = 0; c < m.num_cells(); ++c) {
    if (!m.is_element(c, d)) continue;
    const CellInfo& info = cell_info(m.cell_type(c));
    const std::int32_t* nodes = m.cell(c);
    for (int e = 0; e < info.num_edges; ++e) {
      const int a = nodes[info.edges[e][0]], b = nodes[info.edges[e][1]];
      const double l = edge_length(m, a, b);
      sum += l;
      ++count;
      (*shortest)[a] = std::min((*shortest)[a], l);
      (*shortest)[b] = std::min((*shortest)[b], l);
    }
  }
  return count ? sum / count : 1.0;
}

CoordinateFrame normalizing_frame(const Mesh& mesh) {
  CoordinateFrame f;
  const int nv = mesh.num_vertices(), sd = mesh.space_dim;
  for (int v = 0; v < nv; ++v)
    for (int a = 0; a < sd; ++a) f.centre[a] += mesh.vertex(v)[a] / nv;
  std::vector<double> shortest;
  f.length = element_edge_lengths(mesh, &shortest);
  if (mesh.dim() != sd || nv < sd + 1 || !(f.length > 0)) return f;
  // Principal axes of the vertices (in units of the mean edge length, for conditioning).
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (int v = 0; v < nv; ++v) {
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (int a = 0; a < sd; ++a) y[a] = (mesh.vertex(v)[a] - f.centre[a]) / f.length;
    C += y * y.transpose();
  }
  const Eigen::MatrixXd Cs = C.topLeftCorner(sd, sd);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Cs);
  if (eig.info() != Eigen::Success) return f;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  // Axes by decreasing moment; each signed so that the third moment along it is positive.
  for (int k = 0; k < sd; ++k) {
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    axis.head(sd) = eig.eigenvectors().col(sd - 1 - k);
    double m3 = 0;
    for (int v = 0; v < nv; ++v) {
      double t = 0;
      for (int a = 0; a < sd; ++a) t += axis[a] * (mesh.vertex(v)[a] - f.centre[a]) / f.length;
      m3 += t * t * t;
    }
    if (m3 < 0) axis = -axis;
    R.row(k) = axis.transpose();
  }
  if (R.topLeftCorner(sd, sd).determinant() < 0) R.row(sd - 1) *= -1;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) f.rotation[3 * a + b] = R(a, b);
  return f;
}

void to_frame(const CoordinateFrame& frame, Mesh* mesh) { Normalization{frame}.apply(mesh); }

void from_frame(const CoordinateFrame& frame, Mesh* mesh) { Normalization{frame}.undo(mesh); }

}  // namespace tmop
