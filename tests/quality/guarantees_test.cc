// The guarantees' measures, groups and checks (quality/guarantees.h).
#include "tmop/quality/guarantees.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tmop {
namespace {

// A strip in the plane: triangles (0, 1, 2) and (1, 3, 2) on the left, a quad (1, 4, 5, 3) on
// the right. Region 7 for the quad when `regions`.
Mesh tri_quad_strip(bool regions = false) {
  Mesh m;
  m.space_dim = 2;
  const double x[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t t0[] = {0, 1, 2}, t1[] = {1, 3, 2}, q[] = {1, 4, 5, 3};
  m.add_cell(CellType::kTri3, t0);
  m.add_cell(CellType::kTri3, t1);
  m.add_cell(CellType::kQuad4, q, regions ? 7 : 0);
  return m;
}

double value(const GuaranteeValues& v, int cell, GuaranteeMeasure m) {
  return v.cell[cell][static_cast<int>(m)];
}

TEST(Guarantees, EachTypeHasItsOwnMeasures) {
  const Mesh m = tri_quad_strip();
  const GuaranteeValues v = guarantee_values(m, 1);
  EXPECT_NEAR(value(v, 0, GuaranteeMeasure::kMeanRatio), std::sqrt(3.0) / 2, 1e-12);
  EXPECT_TRUE(std::isnan(value(v, 0, GuaranteeMeasure::kScaledJacobian)));
  EXPECT_NEAR(value(v, 2, GuaranteeMeasure::kScaledJacobian), 1, 1e-12);
  EXPECT_TRUE(std::isnan(value(v, 2, GuaranteeMeasure::kMeanRatio)));
  EXPECT_TRUE(std::isnan(value(v, 2, GuaranteeMeasure::kJacobianRatio)));
}

TEST(Guarantees, AWorseQuadIsCaughtWhileTheGlobalWorstIsATriangle) {
  const Mesh input = tri_quad_strip();
  const GuaranteeBaseline b = guarantee_baseline(input, 1);
  Mesh result = input;
  result.vertex(5)[0] = 2.3;  // the quad shears (SJ < 1), still far above the triangles' 0.87
  const GuaranteeValues after = guarantee_values(result, 1);
  EXPECT_GT(value(after, 2, GuaranteeMeasure::kScaledJacobian), 0.9);
  const std::vector<GuaranteeViolation> v = check_guarantees(b, after);
  ASSERT_FALSE(v.empty());
  EXPECT_EQ(v[0].kind, GuaranteeViolation::Kind::kWorst);
  EXPECT_EQ(v[0].type, CellType::kQuad4);
  EXPECT_EQ(v[0].measure, GuaranteeMeasure::kScaledJacobian);
  EXPECT_EQ(v[0].cell, 2);
  EXPECT_NE(v[0].message().find("quad4 worst scaled Jacobian 1 -> 0.957826 (cell 2)"),
            std::string::npos)
      << v[0].message();
  EXPECT_EQ(guard_violators(b, after), std::vector<int>{2});
  // The identical mesh breaks nothing.
  EXPECT_TRUE(check_guarantees(b, guarantee_values(input, 1)).empty());
}

TEST(Guarantees, CellsInvertedInTheInputMayEndAtAnyValidShape) {
  // The quad folded (vertex 5 pulled across): untangled to a sheared but valid quad, whose
  // scaled Jacobian is below the input's other cells' - not a broken guarantee.
  Mesh input = tri_quad_strip();
  input.vertex(5)[0] = 0.5;
  input.vertex(5)[1] = -0.5;
  const GuaranteeBaseline b = guarantee_baseline(input, 1);
  ASSERT_TRUE(b.input.inverted[2]);
  Mesh result = tri_quad_strip();
  result.vertex(5)[0] = 2.6;
  EXPECT_LT(value(guarantee_values(result, 1), 2, GuaranteeMeasure::kScaledJacobian), 0.9);
  EXPECT_TRUE(check_guarantees(b, guarantee_values(result, 1)).empty());
  // Still inverted: not a new inversion either; the triangles are still guarded.
  EXPECT_TRUE(check_guarantees(b, b.input).empty());
  result.vertex(2)[0] = 0.4;
  EXPECT_FALSE(check_guarantees(b, guarantee_values(result, 1)).empty());
  // tmop_optimize's check of a tangled input: new inversions only.
  GuaranteeOptions untangling;
  untangling.tangled_inversions_only = true;
  EXPECT_TRUE(check_guarantees(b, guarantee_values(result, 1), untangling).empty());
  result.vertex(2)[0] = 2.0;  // triangle 0 folds
  const std::vector<GuaranteeViolation> v =
      check_guarantees(b, guarantee_values(result, 1), untangling);
  ASSERT_FALSE(v.empty());
  EXPECT_EQ(v[0].kind, GuaranteeViolation::Kind::kInverted);
}

TEST(Guarantees, RegionsAreGroupsOfTheirOwn) {
  const Mesh input = tri_quad_strip(/*regions=*/true);
  const GuaranteeBaseline b = guarantee_baseline(input, 1);
  Mesh result = input;
  result.vertex(5)[0] = 2.3;
  const std::vector<GuaranteeViolation> v = check_guarantees(b, guarantee_values(result, 1));
  ASSERT_FALSE(v.empty());
  EXPECT_EQ(v[0].region, 7);
  EXPECT_NE(v[0].message().find("quad4 in region 7 worst"), std::string::npos) << v[0].message();
}

TEST(Guarantees, AFallingMeanIsCaughtAndItsLosersHeld) {
  // Two separate triangles: an equilateral one (1) and a right isosceles one (0.866, the
  // worst). The equilateral one gets a little worse but stays above the worst: only the mean
  // falls.
  Mesh input;
  input.space_dim = 2;
  const double x[][2] = {{0, 0}, {1, 0}, {0.5, 0.8660254037844386}, {2, 0}, {3, 0}, {2, 1}};
  for (const auto& p : x) input.add_vertex(p);
  const std::int32_t t0[] = {0, 1, 2}, t1[] = {3, 4, 5};
  input.add_cell(CellType::kTri3, t0);
  input.add_cell(CellType::kTri3, t1);
  const GuaranteeBaseline b = guarantee_baseline(input, 1);
  Mesh result = input;
  result.vertex(2)[1] = 0.75;
  const GuaranteeValues after = guarantee_values(result, 1);
  ASSERT_GT(value(after, 0, GuaranteeMeasure::kMeanRatio), std::sqrt(3.0) / 2 + 0.01);
  const std::vector<GuaranteeViolation> v = check_guarantees(b, after);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].kind, GuaranteeViolation::Kind::kMean);
  EXPECT_NE(v[0].message().find("tri3 mean mean ratio 0.933013 -> "), std::string::npos)
      << v[0].message();
  EXPECT_EQ(guard_violators(b, after), std::vector<int>{0});  // the cell whose value fell
  GuaranteeOptions no_means;
  no_means.means = false;
  EXPECT_TRUE(check_guarantees(b, after, no_means).empty());
  EXPECT_TRUE(guard_violators(b, after, no_means).empty());
}

TEST(Guarantees, NewSliversAndInversionsAreCaught) {
  Mesh input;
  const double x[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : x) input.add_vertex(p);
  const std::int32_t t[] = {0, 1, 2, 3};
  input.add_cell(CellType::kTet4, t);
  const GuaranteeBaseline b = guarantee_baseline(input, 1);
  Mesh sliver = input;  // the apex falls onto the middle of the base's hypotenuse: a sliver
  sliver.vertex(3)[0] = 0.5;
  sliver.vertex(3)[1] = 0.5;
  sliver.vertex(3)[2] = 0.02;
  const GuaranteeValues s = guarantee_values(sliver, 1);
  ASSERT_TRUE(s.sliver[0]);
  bool found = false;
  for (const GuaranteeViolation& g : check_guarantees(b, s))
    if (g.kind == GuaranteeViolation::Kind::kSlivers) {
      found = true;
      EXPECT_NE(g.message().find("tet4 slivers 0 -> 1 (cell 0)"), std::string::npos) << g.message();
    }
  EXPECT_TRUE(found);
  Mesh inverted = input;
  inverted.vertex(3)[2] = -1;
  const GuaranteeValues iv = guarantee_values(inverted, 1);
  ASSERT_TRUE(iv.inverted[0]);
  found = false;
  for (const GuaranteeViolation& g : check_guarantees(b, iv))
    found |= g.kind == GuaranteeViolation::Kind::kInverted;
  EXPECT_TRUE(found);
  EXPECT_EQ(guard_violators(b, iv), std::vector<int>{0});
}

TEST(Guarantees, QuadraticCellsHaveCornerAndCurvedMeasures) {
  Mesh m;
  m.space_dim = 2;
  const double h = std::sqrt(3.0) / 2;
  const double x[][2] = {{0, 0}, {1, 0}, {0.5, h}, {0.5, 0}, {0.75, h / 2}, {0.25, h / 2}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t t[] = {0, 1, 2, 3, 4, 5};
  m.add_cell(CellType::kTri6, t);
  GuaranteeValues v = guarantee_values(m, 1);
  EXPECT_NEAR(value(v, 0, GuaranteeMeasure::kCornerMeanRatio), 1, 1e-12);
  EXPECT_NEAR(value(v, 0, GuaranteeMeasure::kMeanRatio), 1, 1e-12);
  EXPECT_NEAR(value(v, 0, GuaranteeMeasure::kJacobianRatio), 1, 1e-12);
  m.vertex(3)[1] = 0.1;  // a curved edge: the corners stay ideal, the curved measures fall
  v = guarantee_values(m, 1);
  EXPECT_NEAR(value(v, 0, GuaranteeMeasure::kCornerMeanRatio), 1, 1e-12);
  EXPECT_LT(value(v, 0, GuaranteeMeasure::kJacobianRatio), 0.9);
  EXPECT_LT(value(v, 0, GuaranteeMeasure::kMeanRatio), 0.99);
}

TEST(Guarantees, ValuesDoNotDependOnTheThreadCount) {
  Mesh m = tri_quad_strip();
  m.vertex(3)[0] = 1.2;
  const GuaranteeValues a = guarantee_values(m, 1), b = guarantee_values(m, 2);
  for (int c = 0; c < m.num_cells(); ++c)
    for (int k = 0; k < kNumGuaranteeMeasures; ++k)
      EXPECT_TRUE(a.cell[c][k] == b.cell[c][k] ||
                  (std::isnan(a.cell[c][k]) && std::isnan(b.cell[c][k])));
}

}  // namespace
}  // namespace tmop
