// The factorisation W = h R (v_t / det Q)^(1/d) Q D (target_factors.h).
#include "tmop/target/target_factors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "target_test_meshes.h"
#include "tmop/element/ideal_element.h"

namespace tmop {
namespace {

using namespace testing_targets;

constexpr double kPi = 3.14159265358979323846;

// The d x d block of a factor stored 3 x 3.
std::vector<double> block(const double* m9, int d) {
  std::vector<double> b(d * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) b[i * d + j] = m9[i * 3 + j];
  return b;
}

std::vector<double> compose(CellType t, const TargetFactors& f) {
  const int d = cell_dim(t);
  std::vector<double> W(d * d);
  compose_factors(t, f, W.data());
  return W;
}

const CellType kTypes[] = {CellType::kTri3, CellType::kQuad4,  CellType::kTet4,
                           CellType::kHex8, CellType::kWedge6, CellType::kPyramid5,
                           CellType::kTri6, CellType::kHex27};

TEST(IdealFactors, UnitSizeIdentityAndTheTypesShape) {
  for (CellType t : kTypes) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const TargetFactors f = ideal_factors(t);
    EXPECT_EQ(f.size, 1.0);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(f.orientation[i], i % 4 == 0 ? 1.0 : 0.0);
    const std::vector<double> W = compose(t, f);
    EXPECT_LT(max_abs_diff(W.data(), ideal_jacobian(t), d * d), 1e-15);
  }
  const TargetFactors tri = ideal_factors(CellType::kTri3);
  EXPECT_NEAR(tri.skew[1], 0.5, 3e-16);
  EXPECT_NEAR(tri.skew[4], kSqrt3 / 2, 3e-16);
  EXPECT_NEAR(tri.aspect[0], 1.0, 3e-16);
  EXPECT_NEAR(tri.aspect[1], 1.0, 3e-16);
  const TargetFactors quad = ideal_factors(CellType::kQuad4);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(quad.skew[i], i % 4 == 0 ? 1.0 : 0.0);
  // The wedge's third column (half its unit height) is half as long as the others.
  const TargetFactors wedge = ideal_factors(CellType::kWedge6);
  EXPECT_NEAR(wedge.aspect[0] / wedge.aspect[2], 2, 1e-15);
  EXPECT_NEAR(wedge.aspect[0] * wedge.aspect[1] * wedge.aspect[2], 1, 1e-15);
}

TEST(FactorJacobian, RecomposesAnyPositiveMatrix) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (CellType t : kTypes) {
    const int d = cell_dim(t);
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<double> A(d * d);
      for (double& a : A) a = u(rng);
      if (det(A, d) < 0)
        for (int i = 0; i < d; ++i) A[i * d] = -A[i * d];  // flip the first column
      if (!(std::abs(det(A, d)) > 1e-3)) continue;
      ASSERT_GT(det(A, d), 0);
      TargetFactors f;
      ASSERT_TRUE(factor_jacobian(t, A.data(), &f));
      const std::vector<double> W = compose(t, f);
      double scale = 0;
      for (double a : A) scale = std::max(scale, std::abs(a));
      EXPECT_LT(max_abs_diff(W.data(), A.data(), d * d), 1e-13 * scale) << cell_name(t);
      // The factors are what they claim: a rotation, unit-column upper triangular, unit product.
      const std::vector<double> R = block(f.orientation, d), Q = block(f.skew, d);
      const std::vector<double> RtR = mul(transpose(R, d), R, d);
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) EXPECT_NEAR(RtR[i * d + j], i == j, 1e-14);
      EXPECT_NEAR(det(R, d), 1, 1e-14);
      double product = 1;
      for (int j = 0; j < d; ++j) {
        EXPECT_NEAR(column_length(Q, d, j), 1, 1e-14);
        EXPECT_GT(Q[j * d + j], 0);
        for (int i = j + 1; i < d; ++i) EXPECT_EQ(Q[i * d + j], 0);
        product *= f.aspect[j];
      }
      EXPECT_NEAR(product, 1, 1e-14);
      // Size: det A = h^d det(W_ideal).
      EXPECT_NEAR(std::pow(f.size, d) *
                      det(std::vector<double>(ideal_jacobian(t), ideal_jacobian(t) + d * d), d),
                  det(A, d), 1e-13);
    }
  }
}

TEST(FactorJacobian, RefusesNonPositiveOrNonFinite) {
  TargetFactors f;
  f.size = 42;
  const double reflect[4] = {1, 0, 0, -1}, flat[4] = {1, 2, 2, 4};
  const double nan[4] = {1, 0, 0, std::nan("")};
  EXPECT_FALSE(factor_jacobian(CellType::kTri3, reflect, &f));
  EXPECT_FALSE(factor_jacobian(CellType::kTri3, flat, &f));
  EXPECT_FALSE(factor_jacobian(CellType::kTri3, nan, &f));
  EXPECT_EQ(f.size, 42);  // unchanged
}

TEST(ComposeFactors, TwoDimensionalClosedForm) {
  // The documented 2D convention: W = h sqrt(v / sin phi) R(theta) [[sqrt rho, cos phi /
  // sqrt rho], [0, sin phi / sqrt rho]], rho = the ratio of the column lengths.
  for (CellType t : {CellType::kTri3, CellType::kQuad4}) {
    const double h = 1.7, theta = 0.4, phi_deg = 72, rho = 2.5;
    const double phi = phi_deg * kPi / 180;
    TargetFactors f;
    f.size = h;
    const double axis[2] = {std::cos(theta), std::sin(theta)}, lengths[2] = {rho, 1};
    ASSERT_TRUE(orientation_from_axes(2, axis, f.orientation));
    ASSERT_TRUE(skew_from_angles(2, &phi_deg, f.skew));
    ASSERT_TRUE(aspect_from_lengths(2, lengths, f.aspect));
    const double v = det(std::vector<double>(ideal_jacobian(t), ideal_jacobian(t) + 4), 2);
    const double s = h * std::sqrt(v / std::sin(phi)), r = std::sqrt(rho);
    const std::vector<double> R = {std::cos(theta), -std::sin(theta), std::sin(theta),
                                   std::cos(theta)};
    const std::vector<double> want =
        mul(R, {s * r, s * std::cos(phi) / r, 0, s * std::sin(phi) / r}, 2);
    const std::vector<double> W = compose(t, f);
    EXPECT_LT(max_abs_diff(W.data(), want.data(), 4), 1e-14) << cell_name(t);
    EXPECT_NEAR(det(W, 2), h * h * v, 1e-14);
  }
}

TEST(SkewFromAngles, ColumnsAtTheGivenAngles) {
  double Q[9];
  const double right = 90;
  ASSERT_TRUE(skew_from_angles(2, &right, Q));
  for (int i = 0; i < 9; ++i) EXPECT_EQ(Q[i], i % 4 == 0 ? 1.0 : 0.0);
  const double cube[3] = {90, 90, 90};
  ASSERT_TRUE(skew_from_angles(3, cube, Q));
  for (int i = 0; i < 9; ++i) EXPECT_EQ(Q[i], i % 4 == 0 ? 1.0 : 0.0);
  const double angles[3] = {70, 80, 100};
  ASSERT_TRUE(skew_from_angles(3, angles, Q));
  const std::vector<double> q(Q, Q + 9);
  EXPECT_NEAR(column_angle(q, 3, 0, 1), 70, 1e-12);
  EXPECT_NEAR(column_angle(q, 3, 0, 2), 80, 1e-12);
  EXPECT_NEAR(column_angle(q, 3, 1, 2), 100, 1e-12);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(column_length(q, 3, j), 1, 1e-15);
  EXPECT_EQ(Q[3], 0);
  EXPECT_EQ(Q[6], 0);
  EXPECT_EQ(Q[7], 0);
  EXPECT_GT(Q[8], 0);
  // The regular tet's 60 degree trihedron is its ideal skew.
  const double tet[3] = {60, 60, 60};
  ASSERT_TRUE(skew_from_angles(3, tet, Q));
  const TargetFactors ideal = ideal_factors(CellType::kTet4);
  EXPECT_LT(max_abs_diff(Q, ideal.skew, 9), 1e-15);
}

TEST(SkewFromAngles, RefusesImpossibleAngles) {
  double Q[9];
  for (double a : {0.0, 180.0, -10.0, 200.0, std::nan("")})
    EXPECT_FALSE(skew_from_angles(2, &a, Q));
  const double flat[3] = {60, 60, 120};  // q3 in the plane of q1, q2: no volume
  const double impossible[3] = {10, 10, 90};
  const double out_of_range[3] = {90, 90, 180};
  EXPECT_FALSE(skew_from_angles(3, flat, Q));
  EXPECT_FALSE(skew_from_angles(3, impossible, Q));
  EXPECT_FALSE(skew_from_angles(3, out_of_range, Q));
}

TEST(OrientationFromAxes, RotationWithTheGivenFirstAxes) {
  double R[9];
  const double axis2[2] = {0, 3};  // 90 degrees, length irrelevant
  ASSERT_TRUE(orientation_from_axes(2, axis2, R));
  const double rot90[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_LT(max_abs_diff(R, rot90, 9), 3e-16);
  const double axes[6] = {1, 1, 0, 0, 1, 2};  // e1 along (1,1,0); e2 in its plane with (0,1,2)
  ASSERT_TRUE(orientation_from_axes(3, axes, R));
  const std::vector<double> r(R, R + 9);
  const std::vector<double> RtR = mul(transpose(r, 3), r, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(RtR[i * 3 + j], i == j, 1e-15);
  EXPECT_NEAR(det(r, 3), 1, 1e-15);
  EXPECT_NEAR(R[0], std::sqrt(0.5), 3e-16);
  EXPECT_NEAR(R[3], std::sqrt(0.5), 3e-16);
  EXPECT_EQ(R[6], 0);
  // e2 is (0,1,2) minus its e1 part, normalised: (-1, 1, 4) / sqrt(18).
  EXPECT_NEAR(R[1], -1 / std::sqrt(18.0), 1e-15);
  EXPECT_NEAR(R[4], 1 / std::sqrt(18.0), 1e-15);
  EXPECT_NEAR(R[7], 4 / std::sqrt(18.0), 1e-15);
}

TEST(OrientationFromAxes, RefusesZeroAndParallelAxes) {
  double R[9];
  const double zero2[2] = {0, 0}, zero3[6] = {0, 0, 0, 1, 0, 0}, parallel[6] = {1, 2, 3, 2, 4, 6};
  EXPECT_FALSE(orientation_from_axes(2, zero2, R));
  EXPECT_FALSE(orientation_from_axes(3, zero3, R));
  EXPECT_FALSE(orientation_from_axes(3, parallel, R));
}

TEST(AspectFromLengths, UnitProductSameRatios) {
  double D[3];
  const double l[3] = {1, 2, 4};
  ASSERT_TRUE(aspect_from_lengths(3, l, D));
  EXPECT_NEAR(D[0] * D[1] * D[2], 1, 1e-15);
  EXPECT_NEAR(D[1] / D[0], 2, 1e-15);
  EXPECT_NEAR(D[2] / D[0], 4, 1e-15);
  const double bad[2] = {1, 0}, negative[2] = {-1, 2};
  EXPECT_FALSE(aspect_from_lengths(2, bad, D));
  EXPECT_FALSE(aspect_from_lengths(2, negative, D));
}

}  // namespace
}  // namespace tmop
