#include "tmop/quality/jacobian_certificate.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>
#include <vector>

#include "tmop/element/bezier.h"
#include "tmop/element/shape.h"
#include "tmop/quality/cell_quality.h"

namespace tmop {
namespace {

// min det J over the lattice {i/n} of the reference simplex, through the shape functions.
double dense_min_det(CellType type, const double* x, int n) {
  const int d = cell_dim(type);
  double lo = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int k = 0; i + j + k <= (d == 3 ? n : i + j); ++k) {
        const double xi[3] = {double(i) / n, double(j) / n, double(k) / n};
        double a[9];
        cell_jacobian(type, x, d, xi, a);
        lo = std::min(
            lo, d == 2 ? a[0] * a[3] - a[1] * a[2]
                       : Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(a).determinant());
      }
  return lo;
}

TEST(JacobianCertificate, SubdivisionProvesWhatThePlainBoundCannot) {
  // A valid tri6 (det J >= 0.26 everywhere) with a negative Bernstein coefficient (-0.21).
  const double x[12] = {0, 0, 1, 0, 0, 1, 0.7, 0.24, 0.77, 0.54, -0.25, 0.8};
  double c[kMaxBezierCoefficients];
  const int n = jacobian_bezier_coefficients(CellType::kTri6, x, c);
  EXPECT_LT(*std::min_element(c, c + n), 0);
  EXPECT_GT(dense_min_det(CellType::kTri6, x, 60), 0.25);
  EXPECT_EQ(certify_jacobian(CellType::kTri6, x, 0), JacobianSign::kUnknown);
  EXPECT_EQ(certify_jacobian(CellType::kTri6, x, 3), JacobianSign::kPositive);

  double nodes[18];
  for (int i = 0; i < 6; ++i)
    nodes[3 * i] = x[2 * i], nodes[3 * i + 1] = x[2 * i + 1], nodes[3 * i + 2] = 0;
  const double up[3] = {0, 0, 1};
  EXPECT_FALSE(cell_quality(CellType::kTri6, nodes, up).inverted);
  QualityOptions plain;
  plain.bezier_subdivision = 0;
  EXPECT_TRUE(cell_quality(CellType::kTri6, nodes, up, plain).inverted);
}

TEST(JacobianCertificate, VerdictsAgreeWithDenseSamplingOnRandomTet10) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  int counts[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<double> x;
    for (int i = 0; i < 10; ++i) {
      const double* r = reference_node(CellType::kTet10, i);
      for (int k = 0; k < 3; ++k) x.push_back(r[k] + (i >= 4 ? u(rng) : 0));
    }
    const JacobianSign sign = certify_jacobian(CellType::kTet10, x.data(), 3);
    // The lattice {i/24} contains every corner of the depth-3 children (multiples of 1/8).
    const double dense = dense_min_det(CellType::kTet10, x.data(), 24);
    if (sign == JacobianSign::kPositive) {
      EXPECT_GT(dense, 0);
    }
    if (sign == JacobianSign::kNonPositive) {
      EXPECT_LE(dense, 1e-12);
    }
    ++counts[static_cast<int>(sign)];
  }
  EXPECT_GT(counts[static_cast<int>(JacobianSign::kPositive)], 0);
  EXPECT_GT(counts[static_cast<int>(JacobianSign::kNonPositive)], 0);
}

TEST(JacobianCertificate, OtherTypesAreUnknown) {
  const double x[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  EXPECT_EQ(certify_jacobian(CellType::kQuad4, x, 3), JacobianSign::kUnknown);
}

}  // namespace
}  // namespace tmop
