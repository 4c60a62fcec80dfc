#include "tmop/quality/corner_frames.h"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <utility>

#include "tmop/element/ideal_element.h"

namespace tmop {
namespace {

// Fills the ideal-element data of a frame whose corner and ends are set, first swapping two ends
// if needed so that det E_ideal > 0.
void finish_frame(CellType type, int dim, CornerFrame* f) {
  Eigen::Matrix3d e = Eigen::Matrix3d::Identity();
  auto fill = [&] {
    const double* c = ideal_corner(type, f->corner);
    for (int k = 0; k < dim; ++k) {
      const double* x = ideal_corner(type, f->ends[k]);
      for (int i = 0; i < dim; ++i) e(i, k) = x[i] - c[i];
    }
  };
  fill();
  if (e.topLeftCorner(dim, dim).determinant() < 0) {
    std::swap(f->ends[0], f->ends[1]);
    fill();
  }
  double lengths = 1;
  for (int k = 0; k < dim; ++k) lengths *= e.col(k).head(dim).norm();
  if (dim == 2) {
    const Eigen::Matrix2d inv = e.topLeftCorner<2, 2>().inverse();
    f->ideal_det = e.topLeftCorner<2, 2>().determinant();
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) f->ideal_inverse[2 * i + j] = inv(i, j);
  } else {
    const Eigen::Matrix3d inv = e.inverse();
    f->ideal_det = e.determinant();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) f->ideal_inverse[3 * i + j] = inv(i, j);
  }
  f->ideal_scaled = f->ideal_det / lengths;
}

CornerFrames build(CellType type) {
  CornerFrames out;
  const CellInfo& info = cell_info(type);
  if (info.dim < 2) return out;
  out.dim = info.dim;
  for (int c = 0; c < info.num_corners; ++c) {
    std::array<int, 4> ends{};
    int n = 0;
    for (int e = 0; e < info.num_edges; ++e) {
      if (info.edges[e][0] == c) ends[n++] = info.edges[e][1];
      if (info.edges[e][1] == c) ends[n++] = info.edges[e][0];
    }
    if (n == info.dim) {
      CornerFrame& f = out.frame[out.count++];
      f.corner = c;
      for (int k = 0; k < n; ++k) f.ends[k] = ends[k];
      finish_frame(type, info.dim, &f);
    } else {
      // Pyramid apex: its four edges run to base corners 0..3 in cyclic order.
      for (int k = 0; k < 4; ++k) {
        CornerFrame& f = out.frame[out.count++];
        f.corner = c;
        for (int j = 0; j < 3; ++j) f.ends[j] = (k + j) % 4;
        finish_frame(type, 3, &f);
      }
    }
  }
  return out;
}

std::array<CornerFrames, kNumCellTypes> build_all() {
  std::array<CornerFrames, kNumCellTypes> all;
  for (int t = 0; t < kNumCellTypes; ++t) {
    const CellType linear = cell_info(static_cast<CellType>(t)).linear;
    all[t] = build(linear);
  }
  return all;
}

}  // namespace

const CornerFrames& corner_frames(CellType type) {
  static const std::array<CornerFrames, kNumCellTypes> all = build_all();
  return all[static_cast<int>(type)];
}

}  // namespace tmop
