// Composed targets W = size x orientation x skew x aspect with per-factor sources
// (composed_target.h): what each source builds, that the factors recombine to the initial
// Jacobian, that each factor changes only what it should, and the failures.
#include "tmop/target/composed_target.h"

#include <gtest/gtest.h>

#include <cmath>

#include "target_test_meshes.h"
#include "tmop/target/target.h"
#include "tmop/target/target_factors.h"

namespace tmop {
namespace {

using namespace testing_targets;

constexpr double kPi = 3.14159265358979323846;

TargetSpec composed(FactorSource size, FactorSource orientation, FactorSource skew,
                    FactorSource aspect) {
  TargetSpec s;
  s.type = TargetType::kComposed;
  s.composed.size.source = size;
  s.composed.orientation.source = orientation;
  s.composed.skew.source = skew;
  s.composed.aspect.source = aspect;
  return s;
}

TargetSpec all_initial() {
  return composed(FactorSource::kInitial, FactorSource::kInitial, FactorSource::kInitial,
                  FactorSource::kInitial);
}

TargetFactor constant(std::vector<double> v) {
  TargetFactor f;
  f.source = FactorSource::kConstant;
  f.value = std::move(v);
  return f;
}

double scale_of(const std::vector<double>& A) {
  double s = 0;
  for (double a : A) s = std::max(s, std::abs(a));
  return s;
}

std::string build_error(const Mesh& mesh, const TargetSpec& spec,
                        SampleRule rule = SampleRule::kDefault) {
  std::vector<double> W = {7};
  const Status s = build_targets(mesh, rule, spec, &W);
  EXPECT_EQ(W, std::vector<double>{7}) << "W must be untouched on failure";
  return s.ok() ? std::string("(ok)") : s.message();
}

void expect_contains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << text << "' lacks '" << part << "'";
}

const CellType kAllTypes[] = {
    CellType::kTri3,     CellType::kQuad4, CellType::kTet4,  CellType::kHex8,  CellType::kWedge6,
    CellType::kPyramid5, CellType::kTri6,  CellType::kQuad9, CellType::kTet10, CellType::kHex27};

// --- recombination ----------------------------------------------------------------------------

TEST(ComposedTarget, AllFactorsFromTheInitialMeshGiveItsJacobian) {
  for (CellType t : kAllTypes) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = distorted_cell(t, general_matrix(d), 0.05);
    for (SampleRule rule : {SampleRule::kDefault, SampleRule::kGauss, SampleRule::kCentroid}) {
      const std::vector<double> W = targets(m, all_initial(), rule);
      const SampleSet set = canonical_sample_set(m, rule);
      ASSERT_EQ(W.size(), set.size() * d * d);
      for (std::size_t p = 0; p < set.size(); ++p) {
        const std::vector<double> A = jacobian_at(m, p, rule);
        EXPECT_LT(max_abs_diff(A.data(), &W[p * d * d], d * d), 1e-12 * scale_of(A))
            << "point " << p;
      }
    }
  }
}

TEST(ComposedTarget, AllInitialEqualsTheReferenceTargetOnAMixedMeshAndASurface) {
  // Mixed tri + quad sharing an edge, and the same triangle lifted into 3D (a surface cell).
  Mesh m;
  m.space_dim = 2;
  const double p[5][2] = {{0, 0}, {1.2, 0.1}, {1.1, 1.3}, {-0.1, 0.9}, {0.6, 2.0}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t q[4] = {0, 1, 2, 3}, t[3] = {3, 2, 4};
  m.add_cell(CellType::kQuad4, q);
  m.add_cell(CellType::kTri3, t);
  TargetSpec reference;
  reference.type = TargetType::kReference;
  const std::vector<double> Wr = targets(m, reference), Wc = targets(m, all_initial());
  ASSERT_EQ(Wr.size(), Wc.size());
  EXPECT_LT(max_abs_diff(Wr.data(), Wc.data(), static_cast<int>(Wr.size())), 1e-14);

  Mesh s;
  s.space_dim = 3;
  const double ps[3][3] = {{0, 0, 0}, {1, 1, 0.5}, {-0.3, 0.4, 1.2}};
  for (auto& x : ps) s.add_vertex(x);
  const std::int32_t st[3] = {0, 1, 2};
  s.add_cell(CellType::kTri3, st);
  const std::vector<double> Sr = targets(s, reference), Sc = targets(s, all_initial());
  EXPECT_LT(max_abs_diff(Sr.data(), Sc.data(), 4), 1e-14);
}

TEST(ComposedTarget, InitialFactorsComeFromTheReferenceMeshWhenGiven) {
  const Mesh m = affine_cell(CellType::kHex8, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  const Mesh other = distorted_cell(CellType::kHex8, general_matrix(3), 0.1);
  TargetSpec spec = all_initial();
  spec.reference = &other;
  const std::vector<double> W = targets(m, spec);
  for (int p = 0; p < 8; ++p) {
    const std::vector<double> A = jacobian_at(other, p);
    EXPECT_LT(max_abs_diff(A.data(), &W[p * 9], 9), 1e-12);
  }
}

// --- the ideal and mean sources reproduce the ideal targets -----------------------------------

TEST(ComposedTarget, DefaultIsTheEqualSizeTarget) {
  for (bool three_d : {false, true}) {
    Mesh m = three_d ? distorted_cell(CellType::kHex8, general_matrix(3), 0.05)
                     : distorted_cell(CellType::kQuad4, general_matrix(2), 0.05);
    // Add a second cell of another type (a mixed mesh), unconnected.
    const Mesh extra = three_d ? affine_cell(CellType::kTet4, {2, 0, 0, 0, 1, 0, 0, 0, 1})
                               : affine_cell(CellType::kTri3, {2, 0.5, 0, 1});
    std::vector<std::int32_t> nodes;
    for (int v = 0; v < extra.num_vertices(); ++v) nodes.push_back(m.add_vertex(extra.vertex(v)));
    m.add_cell(extra.cell_type(0), nodes.data());
    TargetSpec equal;
    equal.type = TargetType::kIdealEqualSize;
    TargetSpec spec;
    spec.type = TargetType::kComposed;  // default factors: equal, identity, ideal, ideal
    const std::vector<double> We = targets(m, equal), Wc = targets(m, spec);
    ASSERT_EQ(We.size(), Wc.size());
    EXPECT_LT(max_abs_diff(We.data(), Wc.data(), static_cast<int>(We.size())), 1e-14);
  }
}

TEST(ComposedTarget, IdealSizeIsTheIdealUnitTarget) {
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    const Mesh m = distorted_cell(t, general_matrix(cell_dim(t)), 0.05);
    TargetSpec unit;
    unit.type = TargetType::kIdealUnitSize;
    const std::vector<double> Wu = targets(m, unit);
    const std::vector<double> Wc = targets(m, composed(FactorSource::kIdeal, FactorSource::kIdeal,
                                                       FactorSource::kIdeal, FactorSource::kIdeal));
    EXPECT_LT(max_abs_diff(Wu.data(), Wc.data(), static_cast<int>(Wu.size())), 1e-15)
        << cell_name(t);
  }
}

TEST(ComposedTarget, InitialSizeOfAnAffineCellIsTheLocalSizeTarget) {
  // For an affine cell det A is constant, so the pointwise size is the cell's equivalent edge.
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    const Mesh m = affine_cell(t, general_matrix(cell_dim(t)));
    TargetSpec local;
    local.type = TargetType::kIdealLocalSize;
    const std::vector<double> Wl = targets(m, local);
    const std::vector<double> Wc = targets(m, composed(FactorSource::kInitial, FactorSource::kIdeal,
                                                       FactorSource::kIdeal, FactorSource::kIdeal));
    EXPECT_LT(max_abs_diff(Wl.data(), Wc.data(), static_cast<int>(Wl.size())), 1e-14)
        << cell_name(t);
  }
}

// --- each factor alone changes only what it should --------------------------------------------

TEST(ComposedTarget, SizeChangesOnlyTheDeterminant) {
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = distorted_cell(t, general_matrix(d), 0.05);
    TargetSpec spec = all_initial();
    spec.composed.size = constant({0.3});
    const std::vector<double> W = targets(m, spec);
    const double v = det(std::vector<double>(ideal_jacobian(t), ideal_jacobian(t) + d * d), d);
    for (std::size_t p = 0; p < W.size() / (d * d); ++p) {
      const std::vector<double> A = jacobian_at(m, p), Wp = at(W, d, p);
      EXPECT_NEAR(det(Wp, d), std::pow(0.3, d) * v, 1e-14);
      // The rest of A is kept: W = (det W / det A)^(1/d) A.
      const double k = std::pow(det(Wp, d) / det(A, d), 1.0 / d);
      for (int i = 0; i < d * d; ++i) EXPECT_NEAR(Wp[i], k * A[i], 1e-13);
    }
  }
}

TEST(ComposedTarget, OrientationChangesNeitherTheMetricTensorNorTheDeterminant) {
  // 2D: R e1 at 30 degrees; 3D: R e1 along a, R e2 in the plane of a and b.
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = distorted_cell(t, general_matrix(d), 0.05);
    TargetSpec spec = all_initial();
    const std::vector<double> a = {1, 2, -0.5}, b = {0, 1, 1};
    spec.composed.orientation = d == 2 ? constant({std::cos(kPi / 6), std::sin(kPi / 6)})
                                       : constant({a[0], a[1], a[2], b[0], b[1], b[2]});
    const std::vector<double> W = targets(m, spec);
    for (std::size_t p = 0; p < W.size() / (d * d); ++p) {
      const std::vector<double> A = jacobian_at(m, p), Wp = at(W, d, p);
      const std::vector<double> AtA = mul(transpose(A, d), A, d),
                                WtW = mul(transpose(Wp, d), Wp, d);
      EXPECT_LT(max_abs_diff(AtA.data(), WtW.data(), d * d), 1e-13);
      EXPECT_NEAR(det(Wp, d), det(A, d), 1e-13);
      const double l1 = column_length(Wp, d, 0);
      if (d == 2) {
        EXPECT_NEAR(Wp[0] / l1, std::cos(kPi / 6), 1e-14);
        EXPECT_NEAR(Wp[2] / l1, std::sin(kPi / 6), 1e-14);
      } else {
        const double na = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(Wp[i * 3] / l1, a[i] / na, 1e-14);
        const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                             a[0] * b[1] - a[1] * b[0]};
        EXPECT_NEAR(Wp[1] * n[0] + Wp[4] * n[1] + Wp[7] * n[2], 0, 1e-13);  // W e2 . (a x b)
      }
    }
  }
}

TEST(ComposedTarget, IdentityOrientationGivesTheUpperTriangularFactor) {
  const Mesh m = distorted_cell(CellType::kTet4, general_matrix(3), 0.0);
  const std::vector<double> W =
      targets(m, composed(FactorSource::kInitial, FactorSource::kIdeal, FactorSource::kInitial,
                          FactorSource::kInitial));
  const std::vector<double> A = jacobian_at(m, 0);
  EXPECT_NEAR(W[3], 0, 1e-15);
  EXPECT_NEAR(W[6], 0, 1e-15);
  EXPECT_NEAR(W[7], 0, 1e-15);
  const std::vector<double> AtA = mul(transpose(A, 3), A, 3), WtW = mul(transpose(W, 3), W, 3);
  EXPECT_LT(max_abs_diff(AtA.data(), WtW.data(), 9), 1e-13);
}

// Column length ratios relative to column 0, and the pairwise angles.
std::vector<double> ratios(const std::vector<double>& A, int d) {
  std::vector<double> r;
  for (int j = 1; j < d; ++j) r.push_back(column_length(A, d, j) / column_length(A, d, 0));
  return r;
}
std::vector<double> angles(const std::vector<double>& A, int d) {
  std::vector<double> r;
  for (int i = 0; i < d; ++i)
    for (int j = i + 1; j < d; ++j) r.push_back(column_angle(A, d, i, j));
  return r;
}
void expect_near(const std::vector<double>& a, const std::vector<double>& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tol) << "entry " << i;
}
// The direction of column 0.
std::vector<double> first_direction(const std::vector<double>& A, int d) {
  std::vector<double> e;
  for (int i = 0; i < d; ++i) e.push_back(A[i * d] / column_length(A, d, 0));
  return e;
}

TEST(ComposedTarget, SkewSetsOnlyTheAngles) {
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = distorted_cell(t, general_matrix(d), 0.05);
    TargetSpec spec = all_initial();
    const std::vector<double> want =
        d == 2 ? std::vector<double>{75} : std::vector<double>{70, 80, 100};
    spec.composed.skew = constant(want);
    const std::vector<double> W = targets(m, spec);
    for (std::size_t p = 0; p < W.size() / (d * d); ++p) {
      const std::vector<double> A = jacobian_at(m, p), Wp = at(W, d, p);
      expect_near(angles(Wp, d), want, 1e-11);
      expect_near(ratios(Wp, d), ratios(A, d), 1e-13);
      expect_near(first_direction(Wp, d), first_direction(A, d), 1e-14);
      EXPECT_NEAR(det(Wp, d), det(A, d), 1e-13);
    }
  }
}

TEST(ComposedTarget, AspectSetsOnlyTheLengthRatios) {
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8}) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = distorted_cell(t, general_matrix(d), 0.05);
    TargetSpec spec = all_initial();
    spec.composed.aspect = d == 2 ? constant({3, 1}) : constant({1, 2, 0.5});
    const std::vector<double> want =
        d == 2 ? std::vector<double>{1.0 / 3} : std::vector<double>{2, 0.5};
    const std::vector<double> W = targets(m, spec);
    for (std::size_t p = 0; p < W.size() / (d * d); ++p) {
      const std::vector<double> A = jacobian_at(m, p), Wp = at(W, d, p);
      expect_near(ratios(Wp, d), want, 1e-13);
      expect_near(angles(Wp, d), angles(A, d), 1e-11);
      expect_near(first_direction(Wp, d), first_direction(A, d), 1e-14);
      EXPECT_NEAR(det(Wp, d), det(A, d), 1e-13);
    }
  }
}

TEST(ComposedTarget, ConstantFactorsOnIdealShapesGiveHandComputedMatrices) {
  // A quad with h = 2, skew 60 degrees, aspect 1:1, no rotation: W = 2 sqrt(v / sin60) Q with
  // v = 1/4 (the reference square is [-1,1]^2): a rhombus with the unit square's area times 4.
  const Mesh q = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.size = constant({2});
  spec.composed.skew = constant({60});
  const std::vector<double> W = targets(q, spec, SampleRule::kCentroid);
  const double s = 2 * std::sqrt(0.25 / (kSqrt3 / 2));
  const double want[4] = {s, s * 0.5, 0, s * kSqrt3 / 2};
  EXPECT_LT(max_abs_diff(W.data(), want, 4), 1e-15);
  // A triangle with skew 60 is the equilateral one; with skew 90 and aspect 1:1 the right
  // isosceles triangle of the same area.
  const Mesh t = affine_cell(CellType::kTri3, {1, 0, 0, 1});
  spec.composed.skew = constant({90});
  spec.composed.size = constant({1});
  const std::vector<double> Wt = targets(t, spec);
  const double leg = std::sqrt(kSqrt3 / 2);  // leg^2 / 2 = sqrt3 / 4
  const double right[4] = {leg, 0, 0, leg};
  EXPECT_LT(max_abs_diff(Wt.data(), right, 4), 1e-15);
}

// --- fields and functions ---------------------------------------------------------------------

TEST(ComposedTarget, FieldsAreInterpolatedWithTheShapeFunctions) {
  Mesh m = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  m.point_data.push_back({"h", 1, {1, 2, 3, 4}});
  // 2D vectors as .vtu writes them (3 components), at 0, 90, 45 and 0 degrees.
  m.point_data.push_back({"dir", 3, {1, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0}});
  m.point_data.push_back({"phi", 1, {60, 70, 80, 90}});
  m.point_data.push_back({"len", 2, {1, 1, 2, 1, 3, 1, 4, 1}});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "field:h", &spec.composed.size).ok());
  ASSERT_TRUE(
      parse_target_factor(FactorKind::kOrientation, "field:dir", &spec.composed.orientation).ok());
  ASSERT_TRUE(parse_target_factor(FactorKind::kSkew, "field:phi", &spec.composed.skew).ok());
  ASSERT_TRUE(parse_target_factor(FactorKind::kAspect, "field:len", &spec.composed.aspect).ok());
  const std::vector<double> W = targets(m, spec, SampleRule::kCorners);
  ASSERT_EQ(W.size(), 16u);
  const double dir[4] = {0, 90, 45, 0};
  for (int c = 0; c < 4; ++c) {
    SCOPED_TRACE(c);
    const std::vector<double> Wc = at(W, 2, c);
    EXPECT_NEAR(det(Wc, 2), (c + 1) * (c + 1) * 0.25, 1e-14);  // h^2 v, v = 1/4
    EXPECT_NEAR(column_angle(Wc, 2, 0, 1), 60 + 10 * c, 1e-11);
    EXPECT_NEAR(column_length(Wc, 2, 0) / column_length(Wc, 2, 1), c + 1, 1e-13);
    const double a = dir[c] * kPi / 180;
    expect_near(first_direction(Wc, 2), {std::cos(a), std::sin(a)}, 1e-15);
  }
  // At the centroid: the mean of the nodal values (bilinear interpolation).
  const std::vector<double> Wm = targets(m, spec, SampleRule::kCentroid);
  EXPECT_NEAR(det(Wm, 2), 2.5 * 2.5 * 0.25, 1e-14);
  EXPECT_NEAR(column_angle(Wm, 2, 0, 1), 75, 1e-11);
}

TEST(ComposedTarget, FunctionsSeeTheUsersCoordinatesAndUnits) {
  // A triangle with centroid (1, 1) in mesh coordinates; the mesh is the user's mapped by
  // x_mesh = (x_user - (10, 0)) / 2: the function sees x_user = (12, 2) and its size (in the
  // user's units) is halved in the mesh's.
  Mesh m;
  m.space_dim = 2;
  const double p[3][2] = {{0, 0}, {3, 0}, {0, 3}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t t[3] = {0, 1, 2};
  m.add_cell(CellType::kTri3, t);
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  double seen[3] = {0, 0, 0};
  spec.composed.size.source = FactorSource::kFunction;
  spec.composed.size.function = [&](const double* x, double* v) {
    for (int a = 0; a < 3; ++a) seen[a] = x[a];
    v[0] = x[0] / 4;  // 3 in the user's units
  };
  spec.frame.centre[0] = 10;
  spec.frame.length = 2;
  const std::vector<double> W = targets(m, spec);
  EXPECT_NEAR(seen[0], 12, 1e-14);
  EXPECT_NEAR(seen[1], 2, 1e-14);
  EXPECT_EQ(seen[2], 0);
  const double want[4] = {1.5, 0.75, 0, 1.5 * kSqrt3 / 2};
  EXPECT_LT(max_abs_diff(W.data(), want, 4), 1e-14);
}

TEST(ComposedTarget, FrameRotationTurnsTheUsersOrientationsOnly) {
  // The mesh is the user's turned by +90 degrees: a user axis along x is along y in the mesh.
  const Mesh m = distorted_cell(CellType::kQuad4, general_matrix(2), 0.05);
  TargetSpec spec = all_initial();
  spec.composed.orientation = constant({1, 0});
  const double rot[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  std::copy(rot, rot + 9, spec.frame.rotation);
  const std::vector<double> W = targets(m, spec);
  for (int p = 0; p < 4; ++p) expect_near(first_direction(at(W, 2, p), 2), {0, 1}, 1e-15);
  // Initial factors are the mesh's own: the frame does not touch them.
  const std::vector<double> Wi = targets(m, [&] {
    TargetSpec s = all_initial();
    std::copy(rot, rot + 9, s.frame.rotation);
    return s;
  }());
  const std::vector<double> A = jacobian_at(m, 0);
  EXPECT_LT(max_abs_diff(A.data(), Wi.data(), 4), 1e-13);
}

TEST(ComposedTarget, ConstantSizeIsInTheUsersUnits) {
  const Mesh m = ideal_cell(CellType::kHex8, 1.0);
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.size = constant({3});
  spec.frame.length = 1.5;
  const std::vector<double> W = targets(m, spec, SampleRule::kCentroid);
  const double want[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // h = 3 / 1.5 = 2 -> W = 2 I / 2
  EXPECT_LT(max_abs_diff(W.data(), want, 9), 1e-15);
}

// --- failures ---------------------------------------------------------------------------------

TEST(ComposedTargetErrors, SourcesAFactorDoesNotHave) {
  const Mesh m = affine_cell(CellType::kTri3, {1, 0, 0, 1});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.skew.source = FactorSource::kMeanSize;
  expect_contains(build_error(m, spec), "composed target skew: 'equal' is a source of the size");
  EXPECT_FALSE(check_composed_target(m, spec).ok());
}

TEST(ComposedTargetErrors, WrongValueCountsAndValues) {
  const Mesh tet = affine_cell(CellType::kTet4, general_matrix(3));
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.skew = constant({60});
  expect_contains(build_error(tet, spec), "skew: 3 values");
  spec.composed.skew = constant({60, 60, 60});
  spec.composed.orientation = constant({1, 0});
  expect_contains(build_error(tet, spec), "orientation: 6 values");
  spec.composed.orientation = constant({1, 0, 0, 2, 0, 0});
  expect_contains(build_error(tet, spec), "orientation: invalid value");
  spec.composed.orientation = TargetFactor();
  spec.composed.size = constant({-1});
  expect_contains(build_error(tet, spec), "size: invalid value -1");
  spec.composed.size = constant({1});
  spec.composed.skew = constant({10, 10, 90});
  expect_contains(build_error(tet, spec), "skew: invalid value");
  spec.composed.skew = TargetFactor();
  spec.composed.aspect = constant({1, 0, 1});
  expect_contains(build_error(tet, spec), "aspect: invalid value");
  EXPECT_FALSE(check_composed_target(tet, spec).ok());
}

TEST(ComposedTargetErrors, MissingOrBadFieldsAndFunctions) {
  Mesh m = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  m.point_data.push_back({"h", 1, {1, 1, -1, 1}});
  m.point_data.push_back({"v", 2, std::vector<double>(8, 1.0)});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.size.source = FactorSource::kField;
  spec.composed.size.field = "nope";
  expect_contains(build_error(m, spec), "size: no point_data array 'nope' with 1 component");
  spec.composed.size.field = "v";  // two components: not a size
  expect_contains(build_error(m, spec), "no point_data array 'v'");
  spec.composed.size.field = "h";  // negative at one corner: passes the check, fails there
  EXPECT_TRUE(check_composed_target(m, spec).ok());
  expect_contains(build_error(m, spec, SampleRule::kCorners), "field 'h' gives invalid values -1");
  spec.composed.size = TargetFactor();
  spec.composed.aspect.source = FactorSource::kFunction;
  expect_contains(build_error(m, spec), "aspect: the function source has no function");
  spec.composed.aspect.function = [](const double*, double* v) { v[0] = 1; };  // forgets v[1]
  expect_contains(build_error(m, spec), "aspect: the function gives invalid values");
}

TEST(ComposedTargetErrors, InitialFactorsOfAnInvertedCell) {
  const Mesh m = affine_cell(CellType::kTri3, {1, 0, 0, -1});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.skew.source = FactorSource::kInitial;
  EXPECT_TRUE(check_composed_target(m, spec).ok());
  expect_contains(build_error(m, spec), "cell 0: the initial Jacobian has det <= 0");
}

TEST(ComposedTargetErrors, SurfaceMeshOrientationAndReferenceTopology) {
  Mesh s;
  s.space_dim = 3;
  const double ps[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}};
  for (auto& x : ps) s.add_vertex(x);
  const std::int32_t st[3] = {0, 1, 2};
  s.add_cell(CellType::kTri3, st);
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.orientation = constant({1, 0});
  expect_contains(build_error(s, spec), "orientation: a surface mesh");
  const Mesh other = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  TargetSpec ref;
  ref.type = TargetType::kComposed;
  ref.reference = &other;
  expect_contains(build_error(s, ref), "do not match");
  EXPECT_FALSE(check_composed_target(s, ref).ok());
}

// --- the command-line form --------------------------------------------------------------------

TEST(ParseTargetFactor, EverySourceAndItsErrors) {
  TargetFactor f;
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "equal", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kMeanSize);
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "initial", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kInitial);
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "ideal", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kIdeal);
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "field:h", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kField);
  EXPECT_EQ(f.field, "h");
  ASSERT_TRUE(parse_target_factor(FactorKind::kSize, "0.25", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kConstant);
  EXPECT_EQ(f.value, std::vector<double>{0.25});
  ASSERT_TRUE(parse_target_factor(FactorKind::kOrientation, "identity", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kIdeal);
  ASSERT_TRUE(parse_target_factor(FactorKind::kOrientation, "angle:90", &f).ok());
  ASSERT_EQ(f.value.size(), 2u);
  EXPECT_NEAR(f.value[0], 0, 3e-16);
  EXPECT_NEAR(f.value[1], 1, 3e-16);
  ASSERT_TRUE(parse_target_factor(FactorKind::kOrientation, "1,0,0,0,1,0", &f).ok());
  EXPECT_EQ(f.value.size(), 6u);
  ASSERT_TRUE(parse_target_factor(FactorKind::kSkew, "70,80,100", &f).ok());
  EXPECT_EQ(f.value, (std::vector<double>{70, 80, 100}));
  ASSERT_TRUE(parse_target_factor(FactorKind::kAspect, "2,1", &f).ok());

  f.field = "kept";
  for (const char* bad : {"", "equa", "field:", "1,,2", "1,x", "nan", "angle:30"}) {
    const Status s = parse_target_factor(FactorKind::kSize, bad, &f);
    EXPECT_FALSE(s.ok()) << bad;
    expect_contains(s.message(), "size source");
  }
  EXPECT_EQ(f.field, "kept");  // untouched on failure
  EXPECT_FALSE(parse_target_factor(FactorKind::kSkew, "equal", &f).ok());
  EXPECT_FALSE(parse_target_factor(FactorKind::kSkew, "identity", &f).ok());
  EXPECT_FALSE(parse_target_factor(FactorKind::kOrientation, "angle:x", &f).ok());
  EXPECT_FALSE(parse_target_factor(FactorKind::kOrientation, "angle:1,2", &f).ok());
}

// --- the smooth aspect (smoothed_aspect.h) ---------------------------------------------------

TargetSpec smooth_aspect() {
  return composed(FactorSource::kInitial, FactorSource::kInitial, FactorSource::kInitial,
                  FactorSource::kSmooth);
}

TEST(SmoothAspect, AffineCellsKeepTheirInitialAspect) {
  // One affine cell: every point's metric is the same, so the smooth aspect is the initial one.
  for (CellType t : kAllTypes) {
    SCOPED_TRACE(cell_name(t));
    const int d = cell_dim(t);
    const Mesh m = affine_cell(t, general_matrix(d));
    const std::vector<double> W = targets(m, smooth_aspect()), Wi = targets(m, all_initial());
    ASSERT_EQ(W.size(), Wi.size());
    for (std::size_t p = 0; p < W.size() / (d * d); ++p)
      expect_near(ratios(at(W, d, p), d), ratios(at(Wi, d, p), d), 1e-12);
  }
}

// An n x n grid of quads on [0, sx] x [0, sy], vertex (i, j) at index j (n + 1) + i.
Mesh quad_grid(int n, double sx, double sy) {
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x[2] = {sx * i / n, sy * j / n};
      m.add_vertex(x);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t q[4] = {j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
                                 (j + 1) * (n + 1) + i};
      m.add_cell(CellType::kQuad4, q);
    }
  return m;
}

TEST(SmoothAspect, AUniformStretchIsKeptAndANudgedVertexIsNot) {
  // A 6 x 6 grid stretched 4:1: every target keeps the 4:1 ratio.
  Mesh m = quad_grid(6, 4, 1);
  std::vector<double> W = targets(m, smooth_aspect());
  for (std::size_t p = 0; p < W.size() / 4; ++p) expect_near(ratios(at(W, 2, p), 2), {0.25}, 1e-12);
  // A square grid with one interior vertex moved by 0.4 of the spacing along x: the cells
  // around it are 1.4:1 and 0.6:1 initially; the smooth targets are much nearer 1:1.
  m = quad_grid(6, 1, 1);
  m.vertex(3 * 7 + 3)[0] += 0.4 / 6;
  W = targets(m, smooth_aspect());
  const std::vector<double> Wi = targets(m, all_initial());
  double worst_smooth = 0, worst_initial = 0;
  for (std::size_t p = 0; p < W.size() / 4; ++p) {
    worst_smooth = std::max(worst_smooth, std::abs(std::log(ratios(at(W, 2, p), 2)[0])));
    worst_initial = std::max(worst_initial, std::abs(std::log(ratios(at(Wi, 2, p), 2)[0])));
  }
  EXPECT_GT(worst_initial, std::log(1.39));
  EXPECT_LT(worst_smooth, 0.5 * worst_initial);
}

TEST(SmoothAspect, RotatingTheMeshChangesNoRatio) {
  Mesh m = quad_grid(5, 3, 1);
  m.vertex(2 * 6 + 2)[1] += 0.05;
  Mesh r = m;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (int v = 0; v < r.num_vertices(); ++v) {
    const double x = r.vertex(v)[0], y = r.vertex(v)[1];
    r.vertex(v)[0] = c * x - s * y + 2;
    r.vertex(v)[1] = s * x + c * y - 1;
  }
  const std::vector<double> W = targets(m, smooth_aspect()), Wr = targets(r, smooth_aspect());
  for (std::size_t p = 0; p < W.size() / 4; ++p)
    expect_near(ratios(at(Wr, 2, p), 2), ratios(at(W, 2, p), 2), 1e-12);
}

TEST(SmoothAspect, IsASourceOfTheAspectOnly) {
  const Mesh m = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  TargetSpec spec;
  spec.type = TargetType::kComposed;
  spec.composed.skew.source = FactorSource::kSmooth;
  expect_contains(build_error(m, spec), "'smooth' is a source of the aspect only");
  TargetFactor f;
  EXPECT_TRUE(parse_target_factor(FactorKind::kAspect, "smooth", &f).ok());
  EXPECT_EQ(f.source, FactorSource::kSmooth);
  EXPECT_FALSE(parse_target_factor(FactorKind::kSize, "smooth", &f).ok());
}

}  // namespace
}  // namespace tmop
