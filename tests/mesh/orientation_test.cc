// Tests of tmop/mesh/orientation.h.
#include "tmop/mesh/orientation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>

#include "tests/mesh/test_meshes.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"

namespace tmop {
namespace {

using testing_meshes::KuhnTets;
using testing_meshes::QuadGrid2x2;

TEST(Orientation, PositiveMeshes) {
  const Mesh tets = KuhnTets(3, 2, 2);
  const OrientationReport r = check_orientation(tets);
  EXPECT_EQ(r.positive, tets.num_cells());
  EXPECT_EQ(r.negative, 0);
  EXPECT_EQ(r.mixed_or_zero, 0);
  EXPECT_FALSE(r.opposite_convention());
  EXPECT_EQ(check_orientation(QuadGrid2x2()).positive, 4);
  EXPECT_EQ(check_orientation(testing_meshes::MixedMesh()).positive, 4);
}

TEST(Orientation, ReorientMixedMesh) {
  Mesh m = testing_meshes::MixedMesh();
  reorient(&m);
  EXPECT_EQ(check_orientation(m).negative, 4);
  reorient(&m);
  EXPECT_EQ(check_orientation(m).positive, 4);
}

TEST(Orientation, FlippedTetMeshIsDetectedAndRepaired) {
  Mesh m = KuhnTets(3, 2, 2);
  // Mirror every tet by hand (independently of reorient): swap its nodes 1 and 2.
  for (int c = 0; c < m.num_cells(); ++c) std::swap(m.cell(c)[1], m.cell(c)[2]);
  OrientationReport r = check_orientation(m);
  EXPECT_EQ(r.negative, m.num_cells());
  EXPECT_TRUE(r.opposite_convention());
  reorient(&m);
  r = check_orientation(m);
  EXPECT_EQ(r.positive, m.num_cells());
  EXPECT_FALSE(r.opposite_convention());
}

TEST(Orientation, MirroredQuadsAndTangledQuad) {
  Mesh m = QuadGrid2x2();
  for (int c = 0; c < m.num_cells(); ++c) std::swap(m.cell(c)[1], m.cell(c)[3]);
  EXPECT_EQ(check_orientation(m).negative, 4);
  EXPECT_TRUE(check_orientation(m).opposite_convention());
  // A bow-tie: corners 2 and 3 exchanged in one cell.
  Mesh t = QuadGrid2x2();
  std::swap(t.cell(0)[2], t.cell(0)[3]);
  const OrientationReport r = check_orientation(t);
  EXPECT_EQ(r.mixed_or_zero, 1);
  EXPECT_EQ(r.positive, 3);
}

TEST(Orientation, SurfaceMeshesHaveNoSign) {
  Mesh m;
  m.space_dim = 3;
  const double p[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t tri[3] = {0, 1, 2};
  m.add_cell(CellType::kTri3, tri);
  const OrientationReport r = check_orientation(m);
  EXPECT_EQ(r.positive + r.negative + r.mixed_or_zero, 0);
}

double DetAt(const Mesh& m, int c, const double* xi) {
  const CellType t = m.cell_type(c);
  const int d = cell_dim(t), n = cell_num_nodes(t);
  double X[kMaxCellNodes * 3], A[9];
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) X[i * d + j] = m.vertex(m.cell(c)[i])[j];
  cell_jacobian(t, X, d, xi, A);
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

void MapPoint(const Mesh& m, int c, const double* xi, double* x) {
  double N[kMaxCellNodes];
  const CellType t = m.cell_type(c);
  shape_values(t, xi, N);
  for (int j = 0; j < m.space_dim; ++j) x[j] = 0;
  for (int i = 0; i < cell_num_nodes(t); ++i)
    for (int j = 0; j < m.space_dim; ++j) x[j] += N[i] * m.vertex(m.cell(c)[i])[j];
}

// reorient keeps each element the same set of points: the reference element's mirror
// xi <-> eta maps the new corners onto the old ones, so the new map must equal the old map
// composed with that mirror everywhere (which checks every quadratic node), and det J flips sign
// at every Gauss point.
TEST(Orientation, ReorientKeepsTheGeometryOfEveryType) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> jitter(-0.04, 0.04);
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8,
                     CellType::kWedge6, CellType::kPyramid5, CellType::kTri6, CellType::kQuad9,
                     CellType::kTet10, CellType::kHex27}) {
    Mesh m = testing_meshes::SingleCell(t, 0.1);
    for (double& x : m.coords) x += jitter(rng);  // curved and irregular
    const Mesh original = m;
    ASSERT_EQ(check_orientation(m).positive, 1) << cell_name(t);
    reorient(&m);
    EXPECT_EQ(check_orientation(m).negative, 1) << cell_name(t);
    for (const SamplePoint& p : sample_points(t, SampleRule::kGauss)) {
      EXPECT_GT(DetAt(original, 0, p.xi), 0) << cell_name(t);
      EXPECT_LT(DetAt(m, 0, p.xi), 0) << cell_name(t);
      const double mirrored[3] = {p.xi[1], p.xi[0], p.xi[2]};
      double a[3], b[3];
      MapPoint(m, 0, p.xi, a);
      MapPoint(original, 0, mirrored, b);
      for (int j = 0; j < m.space_dim; ++j) EXPECT_NEAR(a[j], b[j], 1e-12) << cell_name(t);
    }
    reorient(&m);
    EXPECT_EQ(m.cell_nodes, original.cell_nodes) << cell_name(t);
  }
}

TEST(Orientation, ReorientLeavesBoundaryCellsAlone) {
  Mesh m = QuadGrid2x2();
  const std::int32_t line[2] = {0, 1};
  m.add_cell(CellType::kLine2, line);
  reorient(&m);
  EXPECT_EQ(m.cell(4)[0], 0);
  EXPECT_EQ(m.cell(4)[1], 1);
  EXPECT_EQ(check_orientation(m).negative, 4);
}

// A box of Kuhn tets whose interior vertices within `slab` layers of the mid-plane are mirrored
// through it (the boundary stays): the mirrored block's tets are inverted, the boundary is not.
Mesh MirroredBlock(int n, int slab) {
  Mesh m = KuhnTets(n, n, 2 * n);
  for (int v = 0; v < m.num_vertices(); ++v) {
    double* x = m.vertex(v);
    const bool interior = x[0] > 0 && x[0] < n && x[1] > 0 && x[1] < n && x[2] > 0 && x[2] < 2 * n;
    if (interior && std::abs(x[2] - n) <= slab) x[2] = 2.0 * n - x[2];
  }
  return m;
}

// The boundary decides the convention, so a tangle of most cells is read as a tangle, not as a
// file in the opposite convention; the mirror image of the whole file is read as opposite.
TEST(Orientation, MirroredInteriorBlockIsATangleNotTheOppositeConvention) {
  const int n = 6;
  const Mesh m = MirroredBlock(n, n - 1);
  const OrientationReport r = check_orientation(m);
  ASSERT_GT(2 * r.negative, r.num_elements());  // a majority vote would say "opposite"
  EXPECT_EQ(r.evidence(), OrientationReport::Evidence::kBoundary);
  EXPECT_FALSE(r.opposite_convention());
  EXPECT_NEAR(r.boundary_measure, 2.0 * n * n * n, 1e-9 * n * n * n);  // the box's volume
  EXPECT_NE(describe_orientation(r).find("Gmsh's convention: the boundary"), std::string::npos)
      << describe_orientation(r);
  std::printf("mirrored block: %d of %d tets negative, boundary encloses %.6g\n", r.negative,
              r.num_elements(), r.boundary_measure);
  Mesh flipped = m;
  reorient(&flipped);
  const OrientationReport f = check_orientation(flipped);
  EXPECT_TRUE(f.opposite_convention());
  EXPECT_LT(2 * f.negative, f.num_elements());  // a majority vote would say "Gmsh's"
  EXPECT_NEAR(f.boundary_measure, -2.0 * n * n * n, 1e-9 * n * n * n);
  EXPECT_NE(describe_orientation(f).find("opposite convention"), std::string::npos);
}

// 2D: the signed area enclosed by the boundary edges; far from the origin too.
TEST(Orientation, TwoDimensionalBoundaryAreaDecides) {
  const int n = 8;
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x[2] = {1e6 + i, -3e5 + j};
      m.add_vertex(x);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t q[4] = {j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
                                 (j + 1) * (n + 1) + i};
      m.add_cell(CellType::kQuad4, q);
    }
  for (int j = 1; j < n; ++j)  // mirror the interior columns 1..n-1 through the middle
    for (int i = 1; i < n; ++i)
      m.vertex(j * (n + 1) + i)[0] = 2e6 + n - m.vertex(j * (n + 1) + i)[0];
  const OrientationReport r = check_orientation(m);
  ASSERT_GT(2 * (r.negative + r.mixed_or_zero), r.num_elements());
  EXPECT_EQ(r.evidence(), OrientationReport::Evidence::kBoundary);
  EXPECT_FALSE(r.opposite_convention());
  EXPECT_NEAR(r.boundary_measure, n * n, 1e-6);
  reorient(&m);
  EXPECT_TRUE(check_orientation(m).opposite_convention());
}

// A boundary that encloses nothing (two equal tets, one written the other way round) is no
// evidence: the cells decide by majority.
TEST(Orientation, WithoutBoundaryEvidenceTheCellsDecide) {
  Mesh m = KuhnTets(1, 1, 1);
  Mesh two;
  two.space_dim = 3;
  for (int v = 0; v < m.num_vertices(); ++v) two.add_vertex(m.vertex(v));
  for (int c : {0, 1}) {
    std::int32_t t[4];
    for (int i = 0; i < 4; ++i) t[i] = m.cell(c)[i];
    if (c == 1) std::swap(t[1], t[2]);
    two.add_cell(CellType::kTet4, t);
  }
  const OrientationReport r = check_orientation(two);
  EXPECT_EQ(r.evidence(), OrientationReport::Evidence::kCells);
  EXPECT_FALSE(r.opposite_convention());  // 1 of 2 negative: no majority
}

}  // namespace
}  // namespace tmop
