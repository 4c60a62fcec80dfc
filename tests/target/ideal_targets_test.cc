// The ideal-shape targets: ideal_unit, equal_size, local_size, size_field, lambda_identity.
// Each test states the W the algorithm must build on a small hand-made mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "target_test_meshes.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

using namespace testing_targets;

constexpr double kTol = 1e-14;

TargetSpec spec_of(TargetType type) {
  TargetSpec s;
  s.type = type;
  return s;
}

void expect_matrix(const std::vector<double>& W, std::size_t p, const std::vector<double>& want,
                   double tol = kTol) {
  const int n = static_cast<int>(want.size());
  for (int i = 0; i < n; ++i) EXPECT_NEAR(W[p * n + i], want[i], tol) << "entry " << i;
}

// --- ideal_unit -------------------------------------------------------------------------------

TEST(IdealUnitTarget, EquilateralTriangleWhateverTheCell) {
  // A long thin triangle: the target does not look at it.
  const Mesh m = affine_cell(CellType::kTri3, {5, 0.1, 0, 0.02});
  const std::vector<double> W = targets(m, spec_of(TargetType::kIdealUnitSize));
  ASSERT_EQ(W.size(), 4u);
  expect_matrix(W, 0, {1, 0.5, 0, kSqrt3 / 2});
}

TEST(IdealUnitTarget, UnitSquareAndCubeFromTheBiUnitReference) {
  // Reference quad / hex are [-1,1]^d, so the unit square / cube is W = I / 2, at every corner.
  const Mesh q = affine_cell(CellType::kQuad4, {3, 1, 0, 2});
  const std::vector<double> Wq = targets(q, spec_of(TargetType::kIdealUnitSize));
  ASSERT_EQ(Wq.size(), 4u * 4);
  for (int p = 0; p < 4; ++p) expect_matrix(Wq, p, {0.5, 0, 0, 0.5});
  const Mesh h = affine_cell(CellType::kHex8, general_matrix(3));
  const std::vector<double> Wh = targets(h, spec_of(TargetType::kIdealUnitSize));
  ASSERT_EQ(Wh.size(), 9u * 8);
  for (int p = 0; p < 8; ++p) expect_matrix(Wh, p, {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5});
}

TEST(IdealUnitTarget, RegularTetHasSixUnitEdges) {
  const Mesh m = affine_cell(CellType::kTet4, general_matrix(3));
  const std::vector<double> W = targets(m, spec_of(TargetType::kIdealUnitSize));
  ASSERT_EQ(W.size(), 9u);
  const double s = std::sqrt(2.0 / 3);
  expect_matrix(W, 0, {1, 0.5, 0.5, 0, kSqrt3 / 2, kSqrt3 / 6, 0, 0, s});
  // Columns are the edges from node 0; the other edges are their differences.
  double e[3][3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) e[j][i] = W[i * 3 + j];
  auto length = [](const double* a, const double* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
  };
  const double zero[3] = {0, 0, 0};
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(length(e[j], zero), 1, kTol);
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) EXPECT_NEAR(length(e[i], e[j]), 1, kTol);
}

TEST(IdealUnitTarget, IsTheJacobianOfTheIdealElementItself) {
  // Independent of ideal_jacobian's table: the Jacobian of a cell built from the ideal corners.
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8,
                     CellType::kWedge6, CellType::kPyramid5}) {
    const Mesh m = ideal_cell(t, 1.0);
    const int d = cell_dim(t);
    const std::vector<double> W = targets(m, spec_of(TargetType::kIdealUnitSize));
    const SampleSet set = canonical_sample_set(m, SampleRule::kDefault);
    for (std::size_t p = 0; p < set.size(); ++p) {
      const std::vector<double> A = jacobian_at(m, p);
      EXPECT_LT(max_abs_diff(A.data(), &W[p * d * d], d * d), kTol) << cell_name(t);
    }
  }
}

// --- equal_size -------------------------------------------------------------------------------

TEST(EqualSizeTarget, MeanEquivalentEdgeOfAMixedTriQuadMesh) {
  // A unit square (h = 1) and, beside it, an equilateral triangle of edge 2 (h = 2): mean 1.5.
  Mesh m = ideal_cell(CellType::kQuad4, 1.0);
  const Mesh tri = ideal_cell(CellType::kTri3, 2.0);
  const int base = m.num_vertices();
  for (int v = 0; v < 3; ++v) {
    const double x[2] = {tri.vertex(v)[0] + 5, tri.vertex(v)[1]};
    m.add_vertex(x);
  }
  const std::int32_t t[3] = {base, base + 1, base + 2};
  m.add_cell(CellType::kTri3, t);
  EXPECT_NEAR(cell_equivalent_edge(m, 0), 1.0, kTol);
  EXPECT_NEAR(cell_equivalent_edge(m, 1), 2.0, kTol);
  EXPECT_NEAR(mean_equivalent_edge(m), 1.5, kTol);
  const std::vector<double> W = targets(m, spec_of(TargetType::kIdealEqualSize));
  ASSERT_EQ(W.size(), 4u * 4 + 4);  // 4 quad corners, 1 triangle centroid
  for (int q = 0; q < 4; ++q) expect_matrix(W, q, {0.75, 0, 0, 0.75});
  expect_matrix(W, 4, {1.5, 0.75, 0, 1.5 * kSqrt3 / 2});
}

TEST(EqualSizeTarget, MeanEquivalentEdgeOfAMixedTetHexMesh) {
  // A cube of edge 2 (h = 2) and a regular tet of edge 1 (h = 1), unconnected: mean 1.5.
  Mesh m = ideal_cell(CellType::kHex8, 2.0);
  const Mesh tet = ideal_cell(CellType::kTet4, 1.0);
  std::int32_t nodes[4];
  for (int v = 0; v < 4; ++v) {
    const double x[3] = {tet.vertex(v)[0] + 5, tet.vertex(v)[1], tet.vertex(v)[2]};
    nodes[v] = m.add_vertex(x);
  }
  m.add_cell(CellType::kTet4, nodes);
  const std::vector<double> W = targets(m, spec_of(TargetType::kIdealEqualSize));
  ASSERT_EQ(W.size(), 9u * 9);
  for (int p = 0; p < 8; ++p) expect_matrix(W, p, {0.75, 0, 0, 0, 0.75, 0, 0, 0, 0.75});
  const double s = std::sqrt(2.0 / 3);
  expect_matrix(W, 8, {1.5, 0.75, 0.75, 0, 1.5 * kSqrt3 / 2, 1.5 * kSqrt3 / 6, 0, 0, 1.5 * s});
}

// --- local_size -------------------------------------------------------------------------------

TEST(LocalSizeTarget, EachCellItsOwnEquivalentEdge) {
  // Right triangle with unit legs: area 1/2 = h^2 sqrt3/4, h = sqrt(2/sqrt3).
  const Mesh right = affine_cell(CellType::kTri3, {1, 0, 0, 1});
  const double h = std::sqrt(2 / kSqrt3);
  const std::vector<double> W = targets(right, spec_of(TargetType::kIdealLocalSize));
  expect_matrix(W, 0, {h, h / 2, 0, h * kSqrt3 / 2});
  // An equilateral triangle of edge 3 is its own target.
  const Mesh big = ideal_cell(CellType::kTri3, 3.0);
  const std::vector<double> Wb = targets(big, spec_of(TargetType::kIdealLocalSize));
  expect_matrix(Wb, 0, jacobian_at(big, 0));
}

TEST(LocalSizeTarget, BilinearQuadUsesItsAreaAtEveryCorner) {
  // Trapezoid (0,0) (4,0) (3,2) (1,2): area 6, h = sqrt(6); the same W at all four corners.
  Mesh m;
  m.space_dim = 2;
  const double p[4][2] = {{0, 0}, {4, 0}, {3, 2}, {1, 2}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t q[4] = {0, 1, 2, 3};
  m.add_cell(CellType::kQuad4, q);
  const double h = std::sqrt(6.0);
  const std::vector<double> W = targets(m, spec_of(TargetType::kIdealLocalSize));
  ASSERT_EQ(W.size(), 16u);
  for (int c = 0; c < 4; ++c) expect_matrix(W, c, {h / 2, 0, 0, h / 2});
}

TEST(LocalSizeTarget, RegularTetAndCubeOfGivenEdge) {
  const Mesh tet = ideal_cell(CellType::kTet4, 0.25);
  EXPECT_NEAR(cell_equivalent_edge(tet, 0), 0.25, kTol);
  expect_matrix(targets(tet, spec_of(TargetType::kIdealLocalSize)), 0, jacobian_at(tet, 0));
  const Mesh hex = ideal_cell(CellType::kHex8, 3.0);
  const std::vector<double> W = targets(hex, spec_of(TargetType::kIdealLocalSize));
  for (int p = 0; p < 8; ++p) expect_matrix(W, p, {1.5, 0, 0, 0, 1.5, 0, 0, 0, 1.5});
}

TEST(LocalSizeTarget, ZeroAreaCellFails) {
  const Mesh flat = affine_cell(CellType::kTri3, {1, 2, 0, 0});
  std::vector<double> W = {42};
  const Status s =
      build_targets(flat, SampleRule::kDefault, spec_of(TargetType::kIdealLocalSize), &W);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cell 0"), std::string::npos) << s.message();
  EXPECT_EQ(W, std::vector<double>{42});  // untouched on failure
}

// --- size_field -------------------------------------------------------------------------------

Mesh unit_square_with_field(const std::vector<double>& h) {
  Mesh m = ideal_cell(CellType::kQuad4, 1.0);
  m.point_data.push_back({"h", 1, h});
  return m;
}

TEST(SizeFieldTarget, NodalValuesAtCornersInterpolatedElsewhere) {
  const Mesh m = unit_square_with_field({1, 2, 3, 4});
  TargetSpec spec = spec_of(TargetType::kIdealSizeField);
  spec.size_field = "h";
  const std::vector<double> W = targets(m, spec, SampleRule::kCorners);
  ASSERT_EQ(W.size(), 16u);
  for (int c = 0; c < 4; ++c) expect_matrix(W, c, {0.5 * (c + 1), 0, 0, 0.5 * (c + 1)});
  // Centroid: bilinear interpolation = the mean 2.5.
  const std::vector<double> Wc = targets(m, spec, SampleRule::kCentroid);
  expect_matrix(Wc, 0, {1.25, 0, 0, 1.25});
}

TEST(SizeFieldTarget, TriangleCentroidAndTheFrameLength) {
  Mesh m = affine_cell(CellType::kTri3, {1, 0, 0, 1});
  m.point_data.push_back({"h", 1, {1, 2, 6}});
  TargetSpec spec = spec_of(TargetType::kIdealSizeField);
  spec.size_field = "h";
  expect_matrix(targets(m, spec), 0, {3, 1.5, 0, 3 * kSqrt3 / 2});
  // The mesh is the user's divided by 2 (a normalised stage): the user's sizes are halved.
  spec.frame.length = 2;
  expect_matrix(targets(m, spec), 0, {1.5, 0.75, 0, 1.5 * kSqrt3 / 2});
}

TEST(SizeFieldTarget, MissingWrongOrNonPositiveFieldFails) {
  TargetSpec spec = spec_of(TargetType::kIdealSizeField);
  spec.size_field = "h";
  std::vector<double> W;
  Mesh none = ideal_cell(CellType::kQuad4, 1.0);
  Status s = build_targets(none, SampleRule::kDefault, spec, &W);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("'h'"), std::string::npos) << s.message();
  Mesh vector = ideal_cell(CellType::kQuad4, 1.0);
  vector.point_data.push_back({"h", 2, std::vector<double>(8, 1.0)});
  EXPECT_FALSE(build_targets(vector, SampleRule::kDefault, spec, &W).ok());
  const Mesh negative = unit_square_with_field({1, 1, -1, 1});
  s = build_targets(negative, SampleRule::kDefault, spec, &W);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("not positive"), std::string::npos) << s.message();
}

// --- lambda_identity --------------------------------------------------------------------------

TEST(LambdaIdentityTarget, MeanEdgeLengthOverUniqueEdges) {
  // The unit square split along its diagonal: 4 edges of 1 and one of sqrt2, each counted once.
  Mesh m;
  m.space_dim = 2;
  const double p[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t a[3] = {0, 1, 2}, b[3] = {0, 2, 3};
  m.add_cell(CellType::kTri3, a);
  m.add_cell(CellType::kTri3, b);
  const double lambda = (4 + std::sqrt(2.0)) / 5;
  const std::vector<double> W = targets(m, spec_of(TargetType::kMeanEdgeLength));
  ASSERT_EQ(W.size(), 8u);
  for (int p2 = 0; p2 < 2; ++p2) expect_matrix(W, p2, {lambda, lambda / 2, 0, lambda * kSqrt3 / 2});
}

TEST(LambdaIdentityTarget, HexWithUnequalEdges) {
  // A 1 x 2 x 3 box: 4 edges of each length, mean 2; W = lambda * I / 2 at every corner.
  const Mesh m = affine_cell(CellType::kHex8, {0.5, 0, 0, 0, 1, 0, 0, 0, 1.5});
  const std::vector<double> W = targets(m, spec_of(TargetType::kMeanEdgeLength));
  ASSERT_EQ(W.size(), 72u);
  for (int p = 0; p < 8; ++p) expect_matrix(W, p, {1, 0, 0, 0, 1, 0, 0, 0, 1});
}

TEST(TargetNames, RoundTripAndUnknown) {
  for (const char* n : {"ideal_unit", "equal_size", "local_size", "size_field", "reference",
                        "lambda_identity", "composed"}) {
    TargetType t;
    ASSERT_TRUE(target_type_from_name(n, &t)) << n;
    EXPECT_STREQ(target_type_name(t), n);
  }
  TargetType t;
  EXPECT_FALSE(target_type_from_name("ideal", &t));
}

}  // namespace
}  // namespace tmop
