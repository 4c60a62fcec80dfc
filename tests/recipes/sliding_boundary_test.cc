// Shape improvement of the bundled tet mesh of a box with a cylindrical hole and a spherical
// cavity, with the boundary fixed and sliding: sliding keeps every boundary vertex on the
// input's discrete boundary (corners and feature curves included) and improves the worst
// dihedral angles beyond what a fixed boundary allows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tmop/geometry/boundary_constraints.h"
#include "tmop/io/mesh_io.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/laplace.h"

namespace tmop {
namespace {

TEST(SlidingBoundary, PartStaysOnItsBoundaryAndBeatsTheFixedBoundary) {
  Mesh input;
  ASSERT_TRUE(read_mesh(TMOP_SOURCE_DIR "/data/part_perturbed.msh", &input).ok());
  ShapeOptions opt;
  opt.solver.threads = 1;
  Mesh fixed = input;
  RecipeResult r_fixed;
  ASSERT_TRUE(improve_shape(&fixed, opt, &r_fixed).ok());
  Mesh slid = input;
  opt.slide = true;
  RecipeResult r_slide;
  Status s = improve_shape(&slid, opt, &r_slide);
  ASSERT_TRUE(s.ok()) << s.message();

  // Distances to the input's own boundary, measured by constraints built on the input.
  std::unique_ptr<BoundaryConstraints> geometry;
  ASSERT_TRUE(BoundaryConstraints::Build(input, BoundaryOptions(), &geometry).ok());
  double worst = 0;
  int moved = 0;
  for (int v = 0; v < input.num_vertices(); ++v) {
    if (geometry->kind(v) == VertexKind::kInterior) continue;
    worst = std::max(worst, geometry->distance(v, slid.vertex(v)));
    double d2 = 0;
    for (int a = 0; a < 3; ++a) d2 += std::pow(slid.vertex(v)[a] - input.vertex(v)[a], 2);
    moved += d2 > 1e-12;
    if (!geometry->fixed(v)) continue;
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(slid.vertex(v)[a], input.vertex(v)[a]);
    }
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(moved, 100) << "boundary vertices should actually slide";

  const QualityReport q_in = compute_quality(input);
  const QualityReport q_fixed = compute_quality(fixed);
  const QualityReport q_slide = compute_quality(slid);
  EXPECT_EQ(q_slide.inverted_cells, 0);
  EXPECT_GT(q_slide.min_dihedral.min, q_fixed.min_dihedral.min);
  EXPECT_LT(q_slide.max_dihedral.max, q_fixed.max_dihedral.max);
  std::printf(
      "part: min dihedral %.2f (input) %.2f (fixed) %.2f (slide); max dihedral %.2f / %.2f / "
      "%.2f; boundary distance %.1e, %d boundary vertices moved\n",
      q_in.min_dihedral.min, q_fixed.min_dihedral.min, q_slide.min_dihedral.min,
      q_in.max_dihedral.max, q_fixed.max_dihedral.max, q_slide.max_dihedral.max, worst, moved);
}

}  // namespace
}  // namespace tmop

namespace tmop {
namespace {

TEST(SlidingBoundary, LaplaceProjectsBoundaryVerticesOntoTheirGeometry) {
  Mesh input;
  ASSERT_TRUE(read_mesh(TMOP_SOURCE_DIR "/data/part_perturbed.msh", &input).ok());
  Mesh mesh = input;
  LaplaceOptions opt;
  opt.slide = true;
  RecipeResult result;
  ASSERT_TRUE(laplace(&mesh, opt, &result).ok());
  std::unique_ptr<BoundaryConstraints> geometry;
  ASSERT_TRUE(BoundaryConstraints::Build(input, BoundaryOptions(), &geometry).ok());
  double worst = 0;
  int moved = 0;
  for (int v = 0; v < input.num_vertices(); ++v) {
    if (geometry->kind(v) == VertexKind::kInterior) continue;
    worst = std::max(worst, geometry->distance(v, mesh.vertex(v)));
    moved += mesh.vertex(v)[0] != input.vertex(v)[0];
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_GT(moved, 100);
  EXPECT_EQ(compute_quality(mesh).inverted_cells, 0);
}

}  // namespace
}  // namespace tmop
