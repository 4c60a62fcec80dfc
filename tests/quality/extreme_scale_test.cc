// Valid meshes at extreme scales (issue 19): squared lengths and det T under- or overflow in
// doubles at 1e-310 and 1e300, which made a unit-shaped square "4 inverted, edge length 0" or
// gave infinite edge lengths and scaled Jacobians. Shape measures must not depend on the scale;
// lengths must come out at the scale.
#include <gtest/gtest.h>

#include <cmath>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

// A 2 x 2 grid of squares of side h (2D), or a regular-ish tet (3D) of edge about h.
Mesh squares(double h) {
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x[2] = {i * h, j * h};
      m.add_vertex(x);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const std::int32_t a = 3 * j + i;
      const std::int32_t q[4] = {a, a + 1, a + 4, a + 3};
      m.add_cell(CellType::kQuad4, q);
    }
  m.cell_region.assign(4, 0);
  m.cell_entity.assign(4, 0);
  return m;
}

Mesh tet(double h) {
  Mesh m;
  m.space_dim = 3;
  const double x[4][3] = {{0, 0, 0}, {h, 0, 0}, {0.5 * h, 0.75 * h, 0}, {0.5 * h, 0.25 * h, h}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t t[4] = {0, 1, 2, 3};
  m.add_cell(CellType::kTet4, t);
  m.cell_region.assign(1, 0);
  m.cell_entity.assign(1, 0);
  return m;
}

void expect_near_rel(double got, double want, const char* what, double h) {
  EXPECT_NEAR(got / want, 1.0, 1e-12) << what << " at " << h << ": " << got << " vs " << want;
}

TEST(ExtremeScale, SquaresAreMeasuredTheSameAtEveryScale) {
  const QualityReport unit = compute_quality(squares(1.0));
  for (double h : {1e-310, 1e-300, 1e-200, 1e200, 1e300}) {
    const QualityReport r = compute_quality(squares(h));
    EXPECT_EQ(r.inverted_cells, 0) << h;
    EXPECT_EQ(r.scaled_jacobian.min, unit.scaled_jacobian.min) << h;
    EXPECT_EQ(r.scaled_jacobian.infinite, 0) << h;
    EXPECT_EQ(r.condition_number.max, unit.condition_number.max) << h;
    EXPECT_EQ(r.condition_number.infinite, 0) << h;
    expect_near_rel(r.edge_length.min, h, "unique edge length min", h);
    expect_near_rel(r.edge_length.max, h, "unique edge length max", h);
    expect_near_rel(r.min_edge_length.min, h, "cell min edge length", h);
    expect_near_rel(r.max_edge_length.max, h, "cell max edge length", h);
    EXPECT_EQ(r.edge_ratio.max, 1.0) << h;
  }
}

TEST(ExtremeScale, TetShapeMeasuresDoNotDependOnTheScale) {
  const QualityReport unit = compute_quality(tet(1.0));
  for (double h : {1e-310, 1e-300, 1e300}) {
    const QualityReport r = compute_quality(tet(h));
    EXPECT_EQ(r.inverted_cells, 0) << h;
    expect_near_rel(r.mean_ratio.min, unit.mean_ratio.min, "mean ratio", h);
    expect_near_rel(r.scaled_jacobian.min, unit.scaled_jacobian.min, "scaled Jacobian", h);
    expect_near_rel(r.condition_number.max, unit.condition_number.max, "condition number", h);
    expect_near_rel(r.min_dihedral.min, unit.min_dihedral.min, "min dihedral", h);
    expect_near_rel(r.edge_length.max, h * unit.edge_length.max, "edge length", h);
  }
}

// A degenerate cell stays degenerate at every scale (the scaling does not hide a zero).
TEST(ExtremeScale, AFlatCellIsStillInverted) {
  for (double h : {1e-310, 1.0, 1e300}) {
    Mesh m = squares(h);
    m.coords[2 * 4 + 1] = 0;  // the middle vertex onto the bottom edge: cells 0 and 1 degenerate
    m.coords[2 * 4] = 0;
    const QualityReport r = compute_quality(m);
    EXPECT_GT(r.inverted_cells, 0) << h;
  }
}

}  // namespace
}  // namespace tmop
