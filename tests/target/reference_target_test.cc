// The reference target: W = the Jacobian of a reference mesh (the mesh itself by default) at
// every sample point, and its failures.
#include <gtest/gtest.h>

#include "target_test_meshes.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

using namespace testing_targets;

constexpr double kTol = 1e-14;

TargetSpec reference_spec(const Mesh* reference = nullptr) {
  TargetSpec s;
  s.type = TargetType::kReference;
  s.reference = reference;
  return s;
}

// Every canonical point of `rule`: W equals `source`'s Jacobian there.
void expect_jacobians(const Mesh& mesh, const Mesh& source, SampleRule rule) {
  const std::vector<double> W = targets(mesh, reference_spec(&source), rule);
  const int d = mesh.dim();
  const SampleSet set = canonical_sample_set(mesh, rule);
  ASSERT_EQ(W.size(), set.size() * d * d);
  for (std::size_t p = 0; p < set.size(); ++p) {
    const std::vector<double> A = jacobian_at(source, p, rule);
    EXPECT_LT(max_abs_diff(A.data(), &W[p * d * d], d * d), kTol) << "point " << p;
  }
}

TEST(ReferenceTarget, KeepsWhatIsThereForEveryType) {
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8,
                     CellType::kWedge6, CellType::kPyramid5, CellType::kTri6, CellType::kTet10}) {
    SCOPED_TRACE(cell_name(t));
    const Mesh m = distorted_cell(t, general_matrix(cell_dim(t)), 0.05);
    expect_jacobians(m, m, SampleRule::kDefault);
    expect_jacobians(m, m, SampleRule::kGauss);
  }
}

TEST(ReferenceTarget, AffineTriangleAndTetGiveTheirMatrix) {
  const std::vector<double> M2 = {2, 1, 0, 3};
  const Mesh tri = affine_cell(CellType::kTri3, M2);
  const std::vector<double> W2 = targets(tri, reference_spec());
  EXPECT_LT(max_abs_diff(W2.data(), M2.data(), 4), kTol);
  const std::vector<double> M3 = general_matrix(3);
  const Mesh tet = affine_cell(CellType::kTet4, M3);
  const std::vector<double> W3 = targets(tet, reference_spec());
  EXPECT_LT(max_abs_diff(W3.data(), M3.data(), 9), kTol);
}

// TargetSpec::cell_scale multiplies each cell's reference Jacobian by its factor; a list of
// the wrong length is refused.
TEST(ReferenceTarget, CellScaleMultipliesEachCellsJacobian) {
  const std::vector<double> M2 = {2, 1, 0, 3};
  const Mesh tri = affine_cell(CellType::kTri3, M2);
  TargetSpec spec = reference_spec();
  spec.cell_scale = {0.5};
  const std::vector<double> W = targets(tri, spec);
  const double half[4] = {1, 0.5, 0, 1.5};
  EXPECT_LT(max_abs_diff(W.data(), half, 4), kTol);
  spec.cell_scale = {0.5, 2};
  std::vector<double> out;
  EXPECT_FALSE(build_targets(tri, SampleRule::kDefault, spec, &out).ok());
}

TEST(ReferenceTarget, BilinearQuadDiffersAtEachCorner) {
  // Trapezoid (0,0) (4,0) (3,2) (1,2): A at corner 0 is [[2, 0.5], [0, 1]], at corner 1
  // [[2, -0.5], [0, 1]] (half the edge vectors, reference [-1,1]^2).
  Mesh m;
  m.space_dim = 2;
  const double p[4][2] = {{0, 0}, {4, 0}, {3, 2}, {1, 2}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t q[4] = {0, 1, 2, 3};
  m.add_cell(CellType::kQuad4, q);
  const std::vector<double> W = targets(m, reference_spec(), SampleRule::kCorners);
  ASSERT_EQ(W.size(), 16u);
  const double c0[4] = {2, 0.5, 0, 1}, c1[4] = {2, -0.5, 0, 1};
  EXPECT_LT(max_abs_diff(&W[0], c0, 4), kTol);
  EXPECT_LT(max_abs_diff(&W[4], c1, 4), kTol);
}

TEST(ReferenceTarget, FromAnotherMeshOfTheSameTopology) {
  const Mesh m = affine_cell(CellType::kHex8, general_matrix(3));
  const Mesh other = distorted_cell(CellType::kHex8, {2, 0, 0, 0, 1, 0, 0, 0, 0.5}, 0.1);
  expect_jacobians(m, other, SampleRule::kDefault);
  // And not the mesh's own Jacobians.
  const std::vector<double> W = targets(m, reference_spec(&other));
  const std::vector<double> own = jacobian_at(m, 0);
  EXPECT_GT(max_abs_diff(W.data(), own.data(), 9), 0.1);
}

TEST(ReferenceTarget, MismatchedTopologyFails) {
  const Mesh m = affine_cell(CellType::kQuad4, {1, 0, 0, 1});
  std::vector<double> W = {7};
  // Another vertex count.
  Mesh more = m;
  const double x[2] = {9, 9};
  more.add_vertex(x);
  Status s = build_targets(m, SampleRule::kDefault, reference_spec(&more), &W);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("do not match"), std::string::npos) << s.message();
  // The same vertices, other connectivity.
  Mesh renumbered = m;
  std::swap(renumbered.cell_nodes[0], renumbered.cell_nodes[1]);
  EXPECT_FALSE(build_targets(m, SampleRule::kDefault, reference_spec(&renumbered), &W).ok());
  // The same vertices as two triangles.
  Mesh split = m;
  split.cell_types.clear();
  split.cell_offsets = {0};
  split.cell_nodes.clear();
  split.cell_region.clear();
  split.cell_entity.clear();
  const std::int32_t a[3] = {0, 1, 2}, b[3] = {0, 2, 3};
  split.add_cell(CellType::kTri3, a);
  split.add_cell(CellType::kTri3, b);
  EXPECT_FALSE(build_targets(m, SampleRule::kDefault, reference_spec(&split), &W).ok());
  EXPECT_EQ(W, std::vector<double>{7});
}

TEST(ReferenceTarget, SingularReferenceFails) {
  const Mesh m = affine_cell(CellType::kTri3, {1, 0, 0, 1});
  const Mesh flat = affine_cell(CellType::kTri3, {1, 2, 0, 0});  // collinear corners
  std::vector<double> W;
  const Status s = build_targets(m, SampleRule::kDefault, reference_spec(&flat), &W);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("singular"), std::string::npos) << s.message();
  EXPECT_TRUE(W.empty());
}

TEST(ReferenceTarget, SurfaceTriangleKeepsLengthsAndAngleInItsPlane) {
  // A triangle in 3D: A is 3 x 2; W is 2 x 2 with W^T W = A^T A and det W > 0.
  Mesh m;
  m.space_dim = 3;
  const double p[3][3] = {{0, 0, 0}, {1, 1, 0.5}, {-0.3, 0.4, 1.2}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t t[3] = {0, 1, 2};
  m.add_cell(CellType::kTri3, t);
  const std::vector<double> W = targets(m, reference_spec());
  ASSERT_EQ(W.size(), 4u);
  const double a1[3] = {1, 1, 0.5}, a2[3] = {-0.3, 0.4, 1.2};
  auto dot = [](const double* u, const double* v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const std::vector<double> WtW = mul(transpose(W, 2), W, 2);
  EXPECT_NEAR(WtW[0], dot(a1, a1), kTol);
  EXPECT_NEAR(WtW[1], dot(a1, a2), kTol);
  EXPECT_NEAR(WtW[3], dot(a2, a2), kTol);
  EXPECT_GT(det(W, 2), 0);
}

}  // namespace
}  // namespace tmop
