// Tests of tmop/element/bezier.h: the coefficients, put back into a Bernstein basis written here
// from its textbook definition, reproduce det J computed directly from the shape functions.
#include "tmop/element/bezier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tmop/element/shape.h"

namespace tmop {
namespace {

double Binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

double DetJ(CellType t, const double* X, const double* xi) {
  double A[9];
  const int d = cell_dim(t);
  cell_jacobian(t, X, d, xi, A);
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

// Evaluates sum_k c_k B_k(xi) in the order documented in bezier.h, independently of bezier.cc.
// Simplex part of dimension sd and degree p: B = p!/(a0! a1! a2! a3!) L0^a0 xi^a1 eta^a2 zeta^a3;
// tensor axes: B = C(q, m) ((1 - t)/2)^(q - m) ((1 + t)/2)^m.
double EvalBernstein(int sd, int p, int td, int q, const double* c, const double* xi) {
  std::vector<std::vector<int>> simplex;
  for (int k = 0; k <= (sd == 3 ? p : 0); ++k)
    for (int j = 0; j <= (sd >= 2 ? p - k : 0); ++j)
      for (int i = 0; i <= p - j - k; ++i) simplex.push_back({i, j, k});
  const int tn = static_cast<int>(std::pow(q + 1, td));
  double sum = 0;
  int idx = 0;
  for (int t = 0; t < tn; ++t) {
    double bt = 1;
    for (int a = 0, rest = t; a < td; ++a, rest /= q + 1) {
      const int m = rest % (q + 1);
      const double x = xi[sd + a];
      bt *= Binomial(q, m) * std::pow((1 - x) / 2, q - m) * std::pow((1 + x) / 2, m);
    }
    for (const std::vector<int>& a : simplex) {
      double bs = 1;
      if (sd > 0) {
        double l0 = 1;
        int a0 = p, rest = p;
        for (int d = 0; d < sd; ++d) {
          l0 -= xi[d];
          a0 -= a[d];
        }
        // multinomial p! / (a0! a1! ...) as a product of binomials
        double mult = 1;
        for (int d = 0; d < sd; ++d) {
          mult *= Binomial(rest, a[d]);
          rest -= a[d];
        }
        bs = mult * std::pow(l0, a0);
        for (int d = 0; d < sd; ++d) bs *= std::pow(xi[d], a[d]);
      }
      sum += c[idx++] * bs * bt;
    }
  }
  return sum;
}

struct Case {
  CellType type;
  int sd, p, td, q, count;
};
const Case kCases[] = {
    {CellType::kTri3, 2, 0, 0, 0, 1},  {CellType::kTri6, 2, 2, 0, 0, 6},
    {CellType::kTet4, 3, 0, 0, 0, 1},  {CellType::kTet10, 3, 3, 0, 0, 20},
    {CellType::kQuad4, 0, 0, 2, 1, 4}, {CellType::kQuad9, 0, 0, 2, 3, 16},
    {CellType::kHex8, 0, 0, 3, 2, 27}, {CellType::kWedge6, 2, 1, 1, 2, 9},
};

void RandomPoint(CellType t, std::mt19937* rng, double* xi) {
  std::uniform_real_distribution<double> u(0, 1), s(-1, 1);
  xi[0] = xi[1] = xi[2] = 0;
  const CellType lin = cell_info(t).linear;
  if (lin == CellType::kQuad4 || lin == CellType::kHex8) {
    for (int j = 0; j < cell_dim(t); ++j) xi[j] = s(*rng);
    return;
  }
  const int sd = lin == CellType::kTet4 ? 3 : 2;
  do {
    for (int j = 0; j < sd; ++j) xi[j] = u(*rng);
  } while (xi[0] + xi[1] + (sd == 3 ? xi[2] : 0) > 1);
  if (lin == CellType::kWedge6) xi[2] = s(*rng);
}

// Reference nodes moved randomly: a curved, generally valid cell with non-constant det J.
std::vector<double> PerturbedNodes(CellType t, std::mt19937* rng, double amount) {
  std::uniform_real_distribution<double> u(-amount, amount);
  const int n = cell_num_nodes(t), d = cell_dim(t);
  std::vector<double> X(n * d);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) X[i * d + j] = reference_node(t, i)[j] + u(*rng);
  return X;
}

TEST(Bezier, CountsMatchTheHeader) {
  for (const Case& c : kCases)
    EXPECT_EQ(jacobian_bezier_count(c.type), c.count) << cell_name(c.type);
  EXPECT_EQ(jacobian_bezier_count(CellType::kPyramid5), 0);
  EXPECT_EQ(jacobian_bezier_count(CellType::kHex27), 0);
  EXPECT_EQ(jacobian_bezier_count(CellType::kLine2), 0);
}

TEST(Bezier, BernsteinPolynomialReproducesDetJ) {
  std::mt19937 rng(23);
  for (const Case& c : kCases) {
    for (int cell = 0; cell < 5; ++cell) {
      const std::vector<double> X = PerturbedNodes(c.type, &rng, 0.2);
      double coef[kMaxBezierCoefficients];
      ASSERT_EQ(jacobian_bezier_coefficients(c.type, X.data(), coef), c.count);
      const double scale = *std::max_element(
          coef, coef + c.count, [](double a, double b) { return std::abs(a) < std::abs(b); });
      for (int trial = 0; trial < 20; ++trial) {
        double xi[3];
        RandomPoint(c.type, &rng, xi);
        const double direct = DetJ(c.type, X.data(), xi);
        const double bern = EvalBernstein(c.sd, c.p, c.td, c.q, coef, xi);
        EXPECT_NEAR(bern, direct, 1e-12 * std::abs(scale)) << cell_name(c.type);
        // The convex-hull property the certificate relies on.
        EXPECT_GE(direct, *std::min_element(coef, coef + c.count) - 1e-12 * std::abs(scale));
      }
    }
  }
}

TEST(Bezier, CornerCoefficientsEqualDetJAtCorners) {
  std::mt19937 rng(29);
  for (const Case& c : kCases) {
    const std::vector<double> X = PerturbedNodes(c.type, &rng, 0.2);
    double coef[kMaxBezierCoefficients];
    jacobian_bezier_coefficients(c.type, X.data(), coef);
    int corners_found = 0;
    for (int k = 0; k < c.count; ++k) {
      double xi[3];
      jacobian_bezier_point(c.type, k, xi);
      for (int i = 0; i < cell_info(c.type).num_corners; ++i) {
        const double* r = reference_node(c.type, i);
        if (r[0] == xi[0] && r[1] == xi[1] && r[2] == xi[2]) {
          ++corners_found;
          EXPECT_NEAR(coef[k], DetJ(c.type, X.data(), r), 1e-12) << cell_name(c.type) << k;
        }
      }
    }
    // Degree-0 spaces have one coefficient at the centroid; all others hold every corner.
    EXPECT_EQ(corners_found, c.count == 1 ? 0 : cell_info(c.type).num_corners) << cell_name(c.type);
  }
}

TEST(Bezier, AffineCellsHaveConstantCoefficients) {
  // x = M xi + b: det J = det M everywhere, so every coefficient equals det M.
  const double M3[9] = {2, 0.3, -0.1, 0.2, 1.5, 0.4, -0.3, 0.1, 0.8};
  const double detM3 =
      2 * (1.5 * 0.8 - 0.4 * 0.1) - 0.3 * (0.2 * 0.8 + 0.4 * 0.3) + -0.1 * (0.2 * 0.1 + 1.5 * 0.3);
  for (const Case& c : kCases) {
    const int n = cell_num_nodes(c.type), d = cell_dim(c.type);
    std::vector<double> X(n * d);
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < d; ++r) {
        X[i * d + r] = 0.5;
        for (int j = 0; j < d; ++j)
          X[i * d + r] += (d == 3 ? M3[r * 3 + j] : M3[r * 3 + j]) * reference_node(c.type, i)[j];
      }
    const double expected = d == 3 ? detM3 : M3[0] * M3[4] - M3[1] * M3[3];
    double coef[kMaxBezierCoefficients];
    jacobian_bezier_coefficients(c.type, X.data(), coef);
    for (int k = 0; k < c.count; ++k) EXPECT_NEAR(coef[k], expected, 1e-12) << cell_name(c.type);
  }
}

// A tri6 whose det J is positive at all six nodes (so node sampling calls it valid) but negative
// inside: the certificate must see it.
TEST(Bezier, CatchesTri6InvertedBetweenNodes) {
  const double X[12] = {0, 0, 1, 0, 0, 1, 0.73, -0.29, 0.21, 0.78, 0.29, 0.65};
  for (int i = 0; i < 6; ++i)
    EXPECT_GT(DetJ(CellType::kTri6, X, reference_node(CellType::kTri6, i)), 0);
  double grid_min = 1e30;
  for (int i = 0; i <= 50; ++i)
    for (int j = 0; i + j <= 50; ++j) {
      const double xi[3] = {i / 50.0, j / 50.0, 0};
      grid_min = std::min(grid_min, DetJ(CellType::kTri6, X, xi));
    }
  ASSERT_LT(grid_min, 0);
  double coef[kMaxBezierCoefficients];
  jacobian_bezier_coefficients(CellType::kTri6, X, coef);
  EXPECT_LT(*std::min_element(coef, coef + 6), 0);
  EXPECT_LE(*std::min_element(coef, coef + 6), grid_min);
}

}  // namespace
}  // namespace tmop
