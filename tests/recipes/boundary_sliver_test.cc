// Slivers whose four vertices all lie on the boundary: a fixed boundary cannot repair them
// (none of their nodes may move), sliding boundary vertices on their planar faces can.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>

#include "tmop/geometry/boundary_constraints.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

// Slivers (max dihedral > 150, min < 10) whose corners are all boundary vertices.
int boundary_slivers(const Mesh& m) {
  const std::vector<char> boundary = boundary_vertex_mask(m);
  int count = 0;
  for (int c = 0; c < m.num_cells(); ++c) {
    if (m.cell_type(c) != CellType::kTet4) continue;
    bool all = true;
    double x[12];
    for (int i = 0; i < 4; ++i) {
      all &= boundary[m.cell(c)[i]] != 0;
      for (int a = 0; a < 3; ++a) x[3 * i + a] = m.vertex(m.cell(c)[i])[a];
    }
    const CellQuality q = cell_quality(CellType::kTet4, x, nullptr);
    count += all && q.max_dihedral_deg > 150 && q.min_dihedral_deg < 10;
  }
  return count;
}

TEST(BoundarySlivers, SlidingRemovesThemAFixedBoundaryCannot) {
  if (std::system("gmsh --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gmsh";
  char dir[] = "/tmp/tmop_bsliver_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string d = dir;
  std::ofstream(d + "/box.geo") << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0,1,1,1};\n"
                                   "Mesh.CharacteristicLengthMax = 0.34;\n";
  ASSERT_EQ(
      std::system(("gmsh -3 " + d + "/box.geo -o " + d + "/box.msh > /dev/null 2>&1").c_str()), 0);
  Mesh mesh;
  ASSERT_TRUE(read_mesh(d + "/box.msh", &mesh).ok());
  std::system(("rm -rf " + d).c_str());
  mesh.remove_lower_dimensional_cells();

  // Slide face vertices within their faces (random, keeping every tet valid) until some
  // all-boundary tets become slivers.
  std::unique_ptr<BoundaryConstraints> geometry;
  ASSERT_TRUE(BoundaryConstraints::Build(mesh, BoundaryOptions(), &geometry).ok());
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.16, 0.16);
  for (int sweep = 0; sweep < 40 && boundary_slivers(mesh) < 3; ++sweep)
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      if (geometry->kind(v) != VertexKind::kSurface) continue;
      double saved[3], n[3];
      for (int a = 0; a < 3; ++a) saved[a] = mesh.vertex(v)[a];
      ASSERT_TRUE(geometry->normal(v, saved, n));
      for (int a = 0; a < 3; ++a)
        if (std::abs(n[a]) < 0.5) mesh.vertex(v)[a] = saved[a] + u(rng);
      bool ok = measure_mesh(mesh, SampleRule::kDefault).inverted == 0;
      for (int a = 0; a < 3 && ok; ++a)  // stay inside the face
        ok = std::abs(n[a]) >= 0.5 || (mesh.vertex(v)[a] > 0.02 && mesh.vertex(v)[a] < 0.98);
      if (ok) continue;
      for (int a = 0; a < 3; ++a) mesh.vertex(v)[a] = saved[a];
    }
  const int before = boundary_slivers(mesh);
  ASSERT_GE(before, 1) << "the fixture should have slivers with every corner on the boundary";

  Mesh fixed = mesh, slid = mesh;
  ShapeOptions opt;
  opt.solver.threads = 1;
  RecipeResult r;
  ASSERT_TRUE(improve_shape(&fixed, opt, &r).ok());
  opt.slide = true;
  ASSERT_TRUE(improve_shape(&slid, opt, &r).ok());
  EXPECT_EQ(boundary_slivers(fixed), before);  // nothing of theirs may move
  EXPECT_EQ(boundary_slivers(slid), 0);
  EXPECT_EQ(compute_quality(slid).slivers, 0);
  EXPECT_EQ(compute_quality(slid).inverted_cells, 0);
  std::unique_ptr<BoundaryConstraints> check;
  ASSERT_TRUE(BoundaryConstraints::Build(mesh, BoundaryOptions(), &check).ok());
  double off = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    off = std::max(off, check->distance(v, slid.vertex(v)));
  EXPECT_LT(off, 1e-10);
  std::printf("boundary slivers: %d -> fixed %d, sliding %d; boundary distance %.1e\n", before,
              boundary_slivers(fixed), boundary_slivers(slid), off);
}

}  // namespace
}  // namespace tmop
