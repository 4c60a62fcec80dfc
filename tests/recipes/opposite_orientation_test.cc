// A tet mesh in Medit format whose cells all use the opposite orientation convention (every
// det J < 0 in Gmsh's convention) is recognised, not reported "100% inverted": tmop_optimize
// improves it and writes it back in its own convention.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/fold_check.h"
#include "tmop/mesh/orientation.h"
#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

TEST(OppositeOrientation, MeditTetMeshIsImprovedAndKeepsItsConvention) {
  const std::string tool = TMOP_BINARY_DIR "/tools/tmop_optimize";
  if (std::system(("test -x " + tool).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
  Mesh mesh = testing_grid::grid(CellType::kTet4, 4);
  std::mt19937 rng(3);
  testing_grid::perturb(&mesh, 4, 0.35, &rng);
  reorient(&mesh);  // every tet now negative in Gmsh's convention
  ASSERT_TRUE(check_orientation(mesh).opposite_convention());
  char dir[] = "/tmp/tmop_medit_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string in = std::string(dir) + "/flipped.mesh", out = std::string(dir) + "/out.mesh";
  ASSERT_TRUE(write_mesh(in, mesh).ok());
  const std::string cmd = tool + " --input=" + in + " --output=" + out + " > " + dir + "/log 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  Mesh result;
  ASSERT_TRUE(read_mesh(out, &result).ok());
  const OrientationReport o = check_orientation(result);
  EXPECT_EQ(o.negative, result.num_elements());  // still the file's own convention
  EXPECT_TRUE(folded_facets(result).empty());
  EXPECT_NE(result.coords, mesh.coords);  // interior vertices moved
  std::system(("rm -rf " + std::string(dir)).c_str());
}

// tmop_quality's report (and so tmop_compare's) measures such a mesh in its own convention: the
// same numbers as for the mesh in Gmsh's convention, and it says so.
TEST(OppositeOrientation, QualityReportMeasuresInTheMeshsConvention) {
  Mesh mesh = testing_grid::grid(CellType::kTet4, 3);
  std::mt19937 rng(4);
  testing_grid::perturb(&mesh, 3, 0.3, &rng);
  const QualityReport own = compute_quality(mesh);
  EXPECT_FALSE(own.opposite_convention);
  Mesh flipped = mesh;
  reorient(&flipped);
  const QualityReport r = compute_quality(flipped);
  EXPECT_TRUE(r.opposite_convention);
  EXPECT_EQ(r.inverted_cells, 0);
  EXPECT_EQ(r.mean_ratio.min, own.mean_ratio.min);
  EXPECT_EQ(r.mean_ratio.mean, own.mean_ratio.mean);
  QualityOptions as_stored;
  as_stored.detect_convention = false;
  EXPECT_EQ(compute_quality(flipped, as_stored).inverted_cells, flipped.num_elements());
}

}  // namespace
}  // namespace tmop
