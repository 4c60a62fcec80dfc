#include "tmop/quality/quality_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/quality/test_meshes.h"
#include "tmop/quality/count_inverted.h"
#include "tmop/quality/edge_length_stats.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/worst_quality.h"

namespace tmop {
namespace {

using testing_meshes::tet_block;
using testing_meshes::tri_grid;

TEST(QualityReport, CountsTypesAndIgnoresLowerDimensionalCells) {
  Mesh m = tet_block(2, 0.1);
  const std::int32_t tri[3] = {0, 1, 3};
  const std::int32_t line[2] = {0, 1};
  m.add_cell(CellType::kTri3, tri);
  m.add_cell(CellType::kLine2, line);
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.dim, 3);
  EXPECT_EQ(r.num_elements, 48);
  EXPECT_EQ(r.num_cells, 50);
  EXPECT_EQ(r.elements_by_type[static_cast<int>(CellType::kTet4)], 48);
  EXPECT_EQ(r.elements_by_type[static_cast<int>(CellType::kTri3)], 0);
  EXPECT_EQ(r.mean_ratio.count, 48);
  EXPECT_TRUE(std::isnan(r.mean_ratio.values[48]));
  EXPECT_TRUE(std::isnan(r.min_angle.values[48]));  // the boundary triangle has no angles here
  EXPECT_EQ(r.inverted_cells, 0);
  EXPECT_EQ(r.tets, 48);
}

TEST(QualityReport, StatisticsAndHistogramsAgreeWithTheValues) {
  const QualityReport r = compute_quality(tet_block(3, 0.25));
  double lo = 1e300, hi = -1e300, sum = 0;
  for (double v : r.mean_ratio.values) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  EXPECT_EQ(r.mean_ratio.min, lo);
  EXPECT_EQ(r.mean_ratio.max, hi);
  EXPECT_DOUBLE_EQ(r.mean_ratio.mean, sum / r.mean_ratio.values.size());
  for (const QualityMeasure* m : r.measures()) {
    if (m->histogram.edges.empty()) continue;
    std::int64_t total = m->histogram.below + m->histogram.above;
    for (std::int64_t n : m->histogram.counts) total += n;
    EXPECT_EQ(total, m->count + m->infinite) << m->key;
  }
}

TEST(QualityReport, ResultsDoNotDependOnTheThreadCount) {
  const Mesh m = tet_block(12, 0.3);  // > 4096 cells: several chunks
  QualityOptions one, two, three;
  one.threads = 1;
  two.threads = 2;
  three.threads = 3;
  const std::string a = quality_json(compute_quality(m, one));
  EXPECT_EQ(a, quality_json(compute_quality(m, two)));
  EXPECT_EQ(a, quality_json(compute_quality(m, three)));
}

TEST(QualityReport, ClockwiseTriangleInAPlanarMeshIsInverted) {
  Mesh m = tri_grid(3, 0.1);
  std::swap(m.cell(4)[1], m.cell(4)[2]);
  const QualityReport r = compute_quality(m);
  EXPECT_TRUE(r.planar);
  EXPECT_EQ(r.inverted_cells, 1);
  EXPECT_EQ(r.inverted[4], 1);
  EXPECT_LT(r.mean_ratio.values[4], 0);
  EXPECT_EQ(r.condition_number.infinite, 1);
  EXPECT_EQ(count_inverted(m), 1);
  EXPECT_EQ(worst_quality(m), r.mean_ratio.min);
  EXPECT_LT(worst_quality(m), 0);
}

TEST(QualityReport, PlanarMeshStoredIn3DIsOrientedByZ) {
  Mesh flat = tri_grid(2, 0.1);
  Mesh m;
  m.space_dim = 3;
  for (int v = 0; v < flat.num_vertices(); ++v) {
    const double x[3] = {flat.vertex(v)[0], flat.vertex(v)[1], 5.0};
    m.add_vertex(x);
  }
  for (int c = 0; c < flat.num_cells(); ++c) m.add_cell(flat.cell_types[c], flat.cell(c));
  std::swap(m.cell(0)[1], m.cell(0)[2]);
  const QualityReport r = compute_quality(m);
  EXPECT_TRUE(r.planar);
  EXPECT_EQ(r.inverted_cells, 1);
}

TEST(QualityReport, SurfaceCellsAreMeasuredAgainstTheirOwnNormal) {
  // Two equilateral triangles folded along their shared edge: a non-planar surface.
  Mesh m;
  m.space_dim = 3;
  const double h = std::sqrt(3.0) / 2;
  const double x[4][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}, {0.5, -h * 0.6, -h * 0.8}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t a[3] = {0, 1, 2}, b[3] = {0, 3, 1};
  m.add_cell(CellType::kTri3, a);
  m.add_cell(CellType::kTri3, b);
  const QualityReport r = compute_quality(m);
  EXPECT_FALSE(r.planar);
  EXPECT_EQ(r.inverted_cells, 0);
  EXPECT_NEAR(r.mean_ratio.min, 1, 1e-12);
  EXPECT_NEAR(r.min_angle.min, 60, 1e-9);
}

TEST(QualityReport, ConstructedSliverIsCounted) {
  // Four points near the corners of a square, alternately lifted by 0.05: flat, all edges
  // reasonable, dihedral angles near 0 and 180 degrees.
  Mesh m = tet_block(1, 0);
  const double s[4][3] = {{10, 0, 0}, {11, 0, 0.05}, {11, 1, 0}, {10, 1, 0.05}};
  const int first = m.num_vertices();
  for (const auto& p : s) m.add_vertex(p);
  const std::int32_t sliver[4] = {first, first + 1, first + 2, first + 3};  // det = 0.1 > 0
  m.add_cell(CellType::kTet4, sliver);
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.inverted_cells, 0);
  EXPECT_EQ(r.slivers, 1);
  const int c = m.num_cells() - 1;
  EXPECT_GT(r.max_dihedral.values[c], 150);
  EXPECT_LT(r.min_dihedral.values[c], 10);
  EXPECT_LT(r.mean_ratio.values[c], 0.3);
}

TEST(QualityReport, WorstQualityUsesScaledJacobianForNonSimplices) {
  Mesh m = tet_block(1, 0);
  const double y[8][3] = {{3, 0, 0}, {4, 0, 0}, {4.5, 1, 0}, {3.5, 1, 0},
                          {3, 0, 1}, {4, 0, 1}, {4.5, 1, 1}, {3.5, 1, 1}};
  std::int32_t hex[8];
  for (int i = 0; i < 8; ++i) hex[i] = m.add_vertex(y[i]);
  m.add_cell(CellType::kHex8, hex);
  const QualityReport r = compute_quality(m);
  const double sheared = 1 / std::sqrt(1.25);
  EXPECT_NEAR(r.scaled_jacobian.values[6], sheared, 1e-12);
  double expected = sheared;
  for (int c = 0; c < 6; ++c) expected = std::min(expected, r.mean_ratio.values[c]);
  EXPECT_EQ(worst_quality(m), expected);
}

TEST(EdgeLengthStats, CountsSharedEdgesOnce) {
  // Two tets sharing the face (0, 1, 2): 9 unique edges.
  Mesh m;
  m.space_dim = 3;
  const double x[5][3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {0, 0, -3}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t a[4] = {0, 1, 2, 3}, b[4] = {0, 2, 1, 4};
  m.add_cell(CellType::kTet4, a);
  m.add_cell(CellType::kTet4, b);
  const EdgeLengthStats s = edge_length_stats(m);
  EXPECT_EQ(s.count, 9);
  EXPECT_DOUBLE_EQ(s.min, 2);
  EXPECT_DOUBLE_EQ(s.max, std::sqrt(13.0));
  const double sum = 2 + 2 + 2 + std::sqrt(8.0) * 3 + 3 + std::sqrt(13.0) * 2;
  EXPECT_NEAR(s.mean, sum / 9, 1e-15);
}

TEST(EdgeLengthStats, GridMatchesTheClosedForm) {
  // An unperturbed n x n x n Kuhn block: 3n(n+1)^2 axis edges of length 1, 3n^2(n+1) face
  // diagonals of sqrt2 and n^3 body diagonals of sqrt3.
  const int n = 4;
  const EdgeLengthStats s = edge_length_stats(tet_block(n, 0), 2);
  const std::int64_t axis = 3 * n * (n + 1) * (n + 1), face = 3 * n * n * (n + 1), body = n * n * n;
  EXPECT_EQ(s.count, axis + face + body);
  EXPECT_NEAR(s.mean, (axis + face * std::sqrt(2.0) + body * std::sqrt(3.0)) / s.count, 1e-14);
  EXPECT_DOUBLE_EQ(s.min, 1);
  EXPECT_DOUBLE_EQ(s.max, std::sqrt(3.0));
}

TEST(QualityReport, EmptyMeshHasNoMeasures) {
  const Mesh m;
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.num_elements, 0);
  EXPECT_EQ(r.mean_ratio.count, 0);
  EXPECT_TRUE(std::isnan(worst_quality(m)));
  EXPECT_EQ(count_inverted(m), 0);
}

}  // namespace
}  // namespace tmop
