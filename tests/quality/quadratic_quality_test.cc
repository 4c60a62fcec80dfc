// Quadratic cells: with straight edges (an affine map) their Jacobian measures must equal those of
// their corner cell, computed by the other route (corner edges, edge-length formulas); curved
// cells are checked against a dense sampling of det J through the shape functions.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tmop/element/shape.h"
#include "tmop/quality/cell_quality.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;

// Node coordinates (num_nodes x 3) of `type` under the affine map x -> a x + b of the reference
// element, via the shape functions' own reference nodes.
std::vector<double> affine_cell(CellType type, const Eigen::Matrix3d& a, const Vec3& b) {
  std::vector<double> out;
  for (int i = 0; i < cell_num_nodes(type); ++i) {
    const double* r = reference_node(type, i);
    const Vec3 x = a * Vec3(r[0], r[1], r[2]) + b;
    out.insert(out.end(), {x.x(), x.y(), x.z()});
  }
  return out;
}

void expect_rel(double expected, double actual, double tol = 1e-9) {
  EXPECT_NEAR(actual, expected, tol * std::max(1.0, std::abs(expected)));
}

TEST(QuadraticQuality, AffineCellsMatchTheirCornerCells) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  const CellType pairs[4][2] = {{CellType::kTri6, CellType::kTri3},
                                {CellType::kTet10, CellType::kTet4},
                                {CellType::kQuad9, CellType::kQuad4},
                                {CellType::kHex27, CellType::kHex8}};
  for (const auto& pair : pairs) {
    SCOPED_TRACE(cell_name(pair[0]));
    const bool planar = cell_dim(pair[0]) == 2;
    for (int trial = 0; trial < 30; ++trial) {
      Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a(i, j) += u(rng);
      if (planar) a.row(2).setZero(), a.col(2).setZero();
      if (planar ? a.topLeftCorner<2, 2>().determinant() <= 0.1 : a.determinant() <= 0.1) continue;
      const Vec3 b(u(rng), u(rng), planar ? 0 : u(rng));
      const double up[3] = {0, 0, 1};
      const std::vector<double> quadratic = affine_cell(pair[0], a, b);
      const std::vector<double> linear = affine_cell(pair[1], a, b);
      const CellQuality q = cell_quality(pair[0], quadratic.data(), up);
      const CellQuality l = cell_quality(pair[1], linear.data(), up);
      EXPECT_FALSE(q.inverted);
      expect_rel(l.min_det, q.min_det);
      expect_rel(l.condition_number, q.condition_number);
      expect_rel(l.scaled_jacobian, q.scaled_jacobian);
      if (pair[0] == CellType::kTri6 || pair[0] == CellType::kTet10) {
        expect_rel(l.mean_ratio, q.mean_ratio);
        EXPECT_EQ(q.certified, 1);
      }
    }
  }
}

// min det J over a dense lattice of the reference tet.
double dense_min_det(const std::vector<double>& nodes) {
  double lo = 1e300;
  const int n = 24;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int k = 0; i + j + k <= n; ++k) {
        const double xi[3] = {double(i) / n, double(j) / n, double(k) / n};
        double a[9];
        cell_jacobian(CellType::kTet10, nodes.data(), 3, xi, a);
        lo =
            std::min(lo, Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(a).determinant());
      }
  return lo;
}

TEST(QuadraticQuality, CurvedTet10InversionAgreesWithDenseSampling) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-0.35, 0.35);
  int inverted = 0, valid = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> x =
        affine_cell(CellType::kTet10, Eigen::Matrix3d::Identity(), Vec3::Zero());
    for (int i = 4; i < 10; ++i)
      for (int k = 0; k < 3; ++k) x[3 * i + k] += u(rng);
    const CellQuality q = cell_quality(CellType::kTet10, x.data(), nullptr);
    const double dense = dense_min_det(x);
    // A negative det anywhere must be reported; a certified cell must be valid everywhere.
    if (dense < 0) {
      EXPECT_TRUE(q.inverted);
    }
    if (q.certified == 1) {
      EXPECT_GT(dense, 0);
    }
    EXPECT_LE(q.mean_ratio, 1);
    inverted += q.inverted;
    valid += !q.inverted;
  }
  EXPECT_GT(inverted, 0);  // the perturbation range exercises both outcomes
  EXPECT_GT(valid, 0);
}

TEST(QuadraticQuality, GaussRuleAlsoVisitsTheCorners) {
  // A tri6 whose det J is smallest at corner 0: the Gauss points alone would miss the minimum.
  const std::vector<double> x = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.6, 0.1, 0, 0.5, 0.5, 0, 0.1, 0.6, 0};
  QualityOptions gauss;
  gauss.sample_rule = SampleRule::kGauss;
  const double up[3] = {0, 0, 1};
  const CellQuality a = cell_quality(CellType::kTri6, x.data(), up, gauss);
  QualityOptions corners;
  corners.sample_rule = SampleRule::kCorners;
  const CellQuality b = cell_quality(CellType::kTri6, x.data(), up, corners);
  EXPECT_LE(a.min_det, b.min_det);
}

}  // namespace
}  // namespace tmop
