// Tests of tmop/element/sample_points.h.
#include "tmop/element/sample_points.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tmop/element/shape.h"

namespace tmop {
namespace {

constexpr CellType kAllTypes[] = {
    CellType::kVertex,   CellType::kLine2,     CellType::kLine3,    CellType::kTri3,
    CellType::kQuad4,    CellType::kTet4,      CellType::kHex8,     CellType::kWedge6,
    CellType::kPyramid5, CellType::kTri6,      CellType::kQuad9,    CellType::kTet10,
    CellType::kHex27,    CellType::kQuad8,     CellType::kHex20,    CellType::kWedge15,
    CellType::kWedge18,  CellType::kPyramid13, CellType::kPyramid14};
constexpr SampleRule kAllRules[] = {SampleRule::kDefault, SampleRule::kCorners, SampleRule::kNodes,
                                    SampleRule::kCentroid, SampleRule::kGauss};

bool InsideReference(CellType type, const double* x) {
  const double e = 1e-12;
  auto in11 = [&](double v) { return v >= -1 - e && v <= 1 + e; };
  switch (cell_info(type).linear) {
    case CellType::kVertex:
      return x[0] == 0 && x[1] == 0 && x[2] == 0;
    case CellType::kLine2:
      return in11(x[0]);
    case CellType::kQuad4:
      return in11(x[0]) && in11(x[1]);
    case CellType::kHex8:
      return in11(x[0]) && in11(x[1]) && in11(x[2]);
    case CellType::kTri3:
      return x[0] >= -e && x[1] >= -e && x[0] + x[1] <= 1 + e;
    case CellType::kTet4:
      return x[0] >= -e && x[1] >= -e && x[2] >= -e && x[0] + x[1] + x[2] <= 1 + e;
    case CellType::kWedge6:
      return x[0] >= -e && x[1] >= -e && x[0] + x[1] <= 1 + e && in11(x[2]);
    case CellType::kPyramid5:
      return x[2] >= -e && x[2] <= 1 + e && std::abs(x[0]) <= 1 - x[2] + e &&
             std::abs(x[1]) <= 1 - x[2] + e;
    default:
      return false;
  }
}

TEST(SamplePoints, InsideTheElementWithWeightsSummingToOne) {
  for (CellType t : kAllTypes) {
    for (SampleRule r : kAllRules) {
      const std::vector<SamplePoint>& pts = sample_points(t, r);
      ASSERT_FALSE(pts.empty()) << cell_name(t) << " " << sample_rule_name(r);
      double sum = 0;
      for (const SamplePoint& p : pts) {
        EXPECT_TRUE(InsideReference(t, p.xi)) << cell_name(t) << " " << sample_rule_name(r);
        EXPECT_GT(p.weight, 0);
        sum += p.weight;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14) << cell_name(t) << " " << sample_rule_name(r);
    }
  }
}

TEST(SamplePoints, DefaultRulesFollowTheDesign) {
  EXPECT_EQ(sample_points(CellType::kTri3, SampleRule::kDefault).size(), 1u);
  EXPECT_EQ(sample_points(CellType::kTet4, SampleRule::kDefault).size(), 1u);
  EXPECT_EQ(sample_points(CellType::kQuad4, SampleRule::kDefault).size(), 4u);
  EXPECT_EQ(sample_points(CellType::kHex8, SampleRule::kDefault).size(), 8u);
  EXPECT_EQ(sample_points(CellType::kWedge6, SampleRule::kDefault).size(), 6u);
  EXPECT_EQ(sample_points(CellType::kPyramid5, SampleRule::kDefault).size(), 4u);
  EXPECT_EQ(sample_points(CellType::kTri6, SampleRule::kDefault).size(), 6u);
  EXPECT_EQ(sample_points(CellType::kQuad9, SampleRule::kDefault).size(), 9u);
  EXPECT_EQ(sample_points(CellType::kTet10, SampleRule::kDefault).size(), 10u);
  EXPECT_EQ(sample_points(CellType::kHex27, SampleRule::kDefault).size(), 27u);
  EXPECT_EQ(sample_points(CellType::kQuad8, SampleRule::kDefault).size(), 8u);
  EXPECT_EQ(sample_points(CellType::kHex20, SampleRule::kDefault).size(), 20u);
  EXPECT_EQ(sample_points(CellType::kWedge15, SampleRule::kDefault).size(), 15u);
  EXPECT_EQ(sample_points(CellType::kWedge18, SampleRule::kDefault).size(), 18u);
  EXPECT_EQ(sample_points(CellType::kPyramid13, SampleRule::kDefault).size(), 12u);
  EXPECT_EQ(sample_points(CellType::kPyramid14, SampleRule::kDefault).size(), 13u);
  // A pyramid's apex (z = 1) is never sampled.
  for (CellType t : {CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14})
    for (SampleRule r : kAllRules)
      for (const SamplePoint& p : sample_points(t, r)) EXPECT_LT(p.xi[2], 0.99) << cell_name(t);
}

// Exact integrals over the reference elements divided by their volumes (independent closed
// forms): the average of x^a y^b z^c.
//   simplex of dim d: a! b! c! d! / (a + b + c + d)!      (Dirichlet integral times d!)
//   [-1,1]^k: prod over axes of (1/(p+1) if p even else 0)
double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }
double CubeAverage(int p) { return p % 2 ? 0.0 : 1.0 / (p + 1); }

double ExactAverage(CellType type, const int* p) {
  switch (cell_info(type).linear) {
    case CellType::kLine2:
      return p[1] || p[2] ? 0 : CubeAverage(p[0]);
    case CellType::kQuad4:
      return p[2] ? 0 : CubeAverage(p[0]) * CubeAverage(p[1]);
    case CellType::kHex8:
      return CubeAverage(p[0]) * CubeAverage(p[1]) * CubeAverage(p[2]);
    case CellType::kTri3:
      return p[2] ? 0 : Factorial(p[0]) * Factorial(p[1]) * 2 / Factorial(p[0] + p[1] + 2);
    case CellType::kTet4:
      return Factorial(p[0]) * Factorial(p[1]) * Factorial(p[2]) * 6 /
             Factorial(p[0] + p[1] + p[2] + 3);
    case CellType::kWedge6:
      return Factorial(p[0]) * Factorial(p[1]) * 2 / Factorial(p[0] + p[1] + 2) * CubeAverage(p[2]);
    case CellType::kPyramid5: {
      // Layer z has side 2(1 - z): the average of x^a y^b over it is (1-z)^(a+b) times the cube
      // average; integrate 4 (1-z)^2 * that * z^c over [0, 1] with a Beta function, / (4/3).
      const int k = p[0] + p[1] + 2;
      const double beta = Factorial(k) * Factorial(p[2]) / Factorial(k + p[2] + 1);
      return CubeAverage(p[0]) * CubeAverage(p[1]) * 4 * beta / (4.0 / 3);
    }
    default:
      return 1;
  }
}

TEST(SamplePoints, GaussRuleIntegratesDegreeTwoExactly) {
  for (CellType t : kAllTypes) {
    const int d = cell_dim(t);
    if (d == 0) continue;
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 2 - a; ++b)
        for (int c = 0; c <= 2 - a - b; ++c) {
          if ((d < 2 && b) || (d < 3 && c)) continue;
          const int p[3] = {a, b, c};
          double q = 0;
          for (const SamplePoint& s : sample_points(t, SampleRule::kGauss))
            q += s.weight * std::pow(s.xi[0], a) * std::pow(s.xi[1], b) * std::pow(s.xi[2], c);
          EXPECT_NEAR(q, ExactAverage(t, p), 1e-14)
              << cell_name(t) << " x^" << a << " y^" << b << " z^" << c;
        }
  }
}

TEST(SamplePoints, RuleNamesRoundTrip) {
  for (SampleRule r : kAllRules) {
    SampleRule back;
    ASSERT_TRUE(sample_rule_from_name(sample_rule_name(r), &back));
    EXPECT_EQ(back, r);
  }
  SampleRule r;
  EXPECT_FALSE(sample_rule_from_name("bogus", &r));
}

}  // namespace
}  // namespace tmop
