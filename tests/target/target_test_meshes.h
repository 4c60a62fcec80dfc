// Small hand-made meshes with known Jacobians, and helpers to read targets, shared by the tests
// in tests/target/.
#ifndef TMOP_TESTS_TARGET_TARGET_TEST_MESHES_H_
#define TMOP_TESTS_TARGET_TARGET_TEST_MESHES_H_

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "tmop/element/ideal_element.h"
#include "tmop/element/shape.h"
#include "tmop/mesh/mesh.h"
#include "tmop/target/target.h"

namespace tmop {
namespace testing_targets {

constexpr double kSqrt3 = 1.7320508075688772;

// d x d row-major matrix product C = A B.
inline std::vector<double> mul(const std::vector<double>& A, const std::vector<double>& B, int d) {
  std::vector<double> C(d * d, 0);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j)
      for (int k = 0; k < d; ++k) C[i * d + j] += A[i * d + k] * B[k * d + j];
  return C;
}

inline std::vector<double> transpose(const std::vector<double>& A, int d) {
  std::vector<double> T(d * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) T[j * d + i] = A[i * d + j];
  return T;
}

inline double det(const std::vector<double>& A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

// Column j of a d x d matrix, its length, and the angle (degrees) between columns i and j.
inline double column_length(const std::vector<double>& A, int d, int j) {
  double s = 0;
  for (int i = 0; i < d; ++i) s += A[i * d + j] * A[i * d + j];
  return std::sqrt(s);
}
inline double column_angle(const std::vector<double>& A, int d, int i, int j) {
  double dot = 0;
  for (int r = 0; r < d; ++r) dot += A[r * d + i] * A[r * d + j];
  return std::acos(dot / (column_length(A, d, i) * column_length(A, d, j))) * 180 /
         3.14159265358979323846;
}

inline double max_abs_diff(const double* a, const double* b, int n) {
  double m = 0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// One cell of `type` whose nodes are x = M xi + b for the reference nodes xi: an affine cell
// with Jacobian M (d x d) at every point.
inline Mesh affine_cell(CellType type, const std::vector<double>& M,
                        const std::vector<double>& b = {0.3, -0.2, 0.1}) {
  Mesh m;
  const int d = cell_dim(type);
  m.space_dim = d;
  std::vector<std::int32_t> nodes;
  for (int i = 0; i < cell_num_nodes(type); ++i) {
    const double* xi = reference_node(type, i);
    double x[3];
    for (int r = 0; r < d; ++r) {
      x[r] = b[r];
      for (int c = 0; c < d; ++c) x[r] += M[r * d + c] * xi[c];
    }
    nodes.push_back(m.add_vertex(x));
  }
  m.add_cell(type, nodes.data());
  return m;
}

// The ideal element of `type` itself, scaled by h (corners from ideal_element.h).
inline Mesh ideal_cell(CellType type, double h) {
  Mesh m;
  m.space_dim = cell_dim(type);
  std::vector<std::int32_t> nodes;
  for (int i = 0; i < cell_info(type).num_corners; ++i) {
    const double* p = ideal_corner(type, i);
    const double x[3] = {h * p[0], h * p[1], h * p[2]};
    nodes.push_back(m.add_vertex(x));
  }
  m.add_cell(type, nodes.data());
  return m;
}

// A non-affine cell: the affine cell of M with every node moved by a fixed pseudo-random
// offset of relative size `amount` (still valid for small amounts).
inline Mesh distorted_cell(CellType type, const std::vector<double>& M, double amount) {
  Mesh m = affine_cell(type, M);
  for (int v = 0; v < m.num_vertices(); ++v)
    for (int a = 0; a < m.space_dim; ++a)
      m.vertex(v)[a] += amount * std::sin(1.7 * v + 2.3 * a + 0.5);
  return m;
}

// A general 2D / 3D matrix with det > 0, no symmetry.
inline std::vector<double> general_matrix(int d) {
  if (d == 2) return {1.3, 0.4, -0.2, 0.9};
  return {1.2, 0.3, -0.1, 0.2, 0.8, 0.25, -0.15, 0.1, 1.1};
}

// The targets of `spec` at the canonical points of `rule`; fails the test on an error.
inline std::vector<double> targets(const Mesh& mesh, const TargetSpec& spec,
                                   SampleRule rule = SampleRule::kDefault) {
  std::vector<double> W;
  const Status s = build_targets(mesh, rule, spec, &W);
  EXPECT_TRUE(s.ok()) << s.message();
  return W;
}

// Target number p (d x d).
inline std::vector<double> at(const std::vector<double>& W, int d, std::size_t p) {
  return std::vector<double>(W.begin() + p * d * d, W.begin() + (p + 1) * d * d);
}

// The Jacobian of cell c at canonical point p of `rule` (the points of that cell).
inline std::vector<double> jacobian_at(const Mesh& mesh, std::size_t p,
                                       SampleRule rule = SampleRule::kDefault) {
  const SampleSet set = canonical_sample_set(mesh, rule);
  const int d = mesh.dim();
  std::vector<double> A(d * d);
  target_jacobian(mesh, set.cell[p], &set.xi[3 * p], A.data());
  return A;
}

}  // namespace testing_targets
}  // namespace tmop

#endif  // TMOP_TESTS_TARGET_TARGET_TEST_MESHES_H_
