#include "tmop/quality/jacobian_certificate.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "tmop/element/bezier.h"
#include "tmop/element/shape.h"

namespace tmop {
namespace {

// A sub-simplex of the reference element: its d + 1 corners in reference coordinates.
struct Simplex {
  double corner[4][3];
};

// Which coefficients sit at the corners of the reference element (their value is det J there).
struct CornerCoefficients {
  int count = 0;
  int index[4];
};

CornerCoefficients find_corner_coefficients(CellType type) {
  CornerCoefficients out;
  const CellInfo& info = cell_info(type);
  for (int k = 0; k < jacobian_bezier_count(type); ++k) {
    double xi[3];
    jacobian_bezier_point(type, k, xi);
    for (int c = 0; c < info.num_corners; ++c) {
      const double* r = reference_node(type, c);
      if (xi[0] == r[0] && xi[1] == r[1] && xi[2] == r[2]) out.index[out.count++] = k;
    }
  }
  return out;
}

double signed_volume(const Simplex& s, int d) {
  double e[3][3];
  for (int k = 0; k < d; ++k)
    for (int i = 0; i < 3; ++i) e[k][i] = s.corner[k + 1][i] - s.corner[0][i];
  if (d == 2) return e[0][0] * e[1][1] - e[0][1] * e[1][0];
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

// The children of s: 4 for a triangle, 8 for a tet, each oriented like s.
int children(const Simplex& s, int d, Simplex* out) {
  double mid[4][4][3];
  for (int a = 0; a <= d; ++a)
    for (int b = 0; b <= d; ++b)
      for (int i = 0; i < 3; ++i) mid[a][b][i] = 0.5 * (s.corner[a][i] + s.corner[b][i]);
  auto set = [&](Simplex* c, std::array<const double*, 4> p) {
    for (int k = 0; k <= d; ++k)
      for (int i = 0; i < 3; ++i) c->corner[k][i] = p[k][i];
  };
  int n = 0;
  if (d == 2) {
    set(&out[n++], {s.corner[0], mid[0][1], mid[0][2], nullptr});
    set(&out[n++], {mid[0][1], s.corner[1], mid[1][2], nullptr});
    set(&out[n++], {mid[0][2], mid[1][2], s.corner[2], nullptr});
    set(&out[n++], {mid[1][2], mid[0][2], mid[0][1], nullptr});
  } else {
    set(&out[n++], {s.corner[0], mid[0][1], mid[0][2], mid[0][3]});
    set(&out[n++], {mid[0][1], s.corner[1], mid[1][2], mid[1][3]});
    set(&out[n++], {mid[0][2], mid[1][2], s.corner[2], mid[2][3]});
    set(&out[n++], {mid[0][3], mid[1][3], mid[2][3], s.corner[3]});
    // The octahedron left in the middle, split around its diagonal m02-m13; the ring m01, m12,
    // m23, m03 is cyclic (neighbours share a corner index).
    const double* ring[4] = {mid[0][1], mid[1][2], mid[2][3], mid[0][3]};
    for (int k = 0; k < 4; ++k) set(&out[n++], {mid[0][2], mid[1][3], ring[k], ring[(k + 1) % 4]});
  }
  const double parent = signed_volume(s, d);
  for (int c = 0; c < n; ++c) {
    if ((signed_volume(out[c], d) > 0) != (parent > 0)) {
      for (int i = 0; i < 3; ++i) std::swap(out[c].corner[0][i], out[c].corner[1][i]);
    }
  }
  return n;
}

// Node coordinates of the cell restricted to s: the original map evaluated at the reference
// nodes of `type` mapped into s (barycentric coordinates of the reference simplex).
void child_nodes(CellType type, const double* nodes, int d, const Simplex& s, double* out) {
  const int nn = cell_num_nodes(type);
  double n_values[kMaxCellNodes];
  for (int k = 0; k < nn; ++k) {
    const double* r = reference_node(type, k);
    double lambda[4] = {1 - r[0] - r[1] - (d == 3 ? r[2] : 0), r[0], r[1], r[2]};
    double xi[3] = {0, 0, 0};
    for (int c = 0; c <= d; ++c)
      for (int i = 0; i < d; ++i) xi[i] += lambda[c] * s.corner[c][i];
    shape_values(type, xi, n_values);
    for (int i = 0; i < d; ++i) {
      double x = 0;
      for (int j = 0; j < nn; ++j) x += n_values[j] * nodes[d * j + i];
      out[d * k + i] = x;
    }
  }
}

}  // namespace

JacobianSign certify_jacobian(CellType type, const double* nodes, int max_depth) {
  if (type != CellType::kTri6 && type != CellType::kTet10) return JacobianSign::kUnknown;
  static const CornerCoefficients corners[2] = {find_corner_coefficients(CellType::kTri6),
                                                find_corner_coefficients(CellType::kTet10)};
  const CornerCoefficients& corner = corners[type == CellType::kTet10];
  const int d = cell_dim(type);
  const int branching = d == 2 ? 4 : 8;

  // Depth-first with an explicit stack: at most branching - 1 pending siblings per level.
  constexpr int kMaxDepth = 8;
  max_depth = std::clamp(max_depth, 0, kMaxDepth);
  Simplex stack[1 + kMaxDepth * 7];
  int depth_of[1 + kMaxDepth * 7];
  int top = 0;
  Simplex& root = stack[top];
  for (int c = 0; c <= d; ++c)
    for (int i = 0; i < 3; ++i) root.corner[c][i] = reference_node(type, c)[i];
  depth_of[top++] = 0;

  bool unknown = false;
  double sub_nodes[kMaxCellNodes * 3];
  double coefficients[kMaxBezierCoefficients];
  while (top > 0) {
    --top;
    const Simplex s = stack[top];
    const int depth = depth_of[top];
    const double* x = nodes;
    if (depth > 0) {
      child_nodes(type, nodes, d, s, sub_nodes);
      x = sub_nodes;
    }
    const int n = jacobian_bezier_coefficients(type, x, coefficients);
    for (int k = 0; k < corner.count; ++k)
      if (!(coefficients[corner.index[k]] > 0)) return JacobianSign::kNonPositive;
    if (std::all_of(coefficients, coefficients + n, [](double c) { return c > 0; })) continue;
    if (depth == max_depth) {
      unknown = true;  // keep looking: another part may still prove det J <= 0
      continue;
    }
    Simplex kids[8];
    children(s, d, kids);
    for (int c = 0; c < branching; ++c) {
      stack[top] = kids[c];
      depth_of[top++] = depth + 1;
    }
  }
  return unknown ? JacobianSign::kUnknown : JacobianSign::kPositive;
}

}  // namespace tmop
