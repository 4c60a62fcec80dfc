// Geometry fidelity of the recipes (issue 18 item 2): without --geometry a curved surface mesh
// moves on a smooth surface through its vertices, not on its facets; with an analytic geometry
// an open cap's rim stays on it; a --geometry is checked against the mesh before any work
// (check_geometry_spec).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tests/geometry/curved_test_meshes.h"
#include "tests/optimize/grid_meshes.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

// The tool's surface recipe (slide) or its auto recipe on a surface mesh (untangle if needed,
// then shape; the surface vertices slide, the rim stays).
Status run_recipe(Mesh* mesh, bool surface_recipe, const std::string& geometry) {
  UntangleOptions u;
  u.slide = surface_recipe;
  u.improve_shape_after = true;
  u.boundary.geometry = geometry;
  u.solver.threads = 1;
  RecipeResult result;
  return untangle(mesh, u, &result);
}

struct DriftCase {
  const char* name;
  bool triangles;
  bool surface_recipe;
};

class SmoothSurfaceDrift : public ::testing::TestWithParam<DriftCase> {};

// A radius-5 cube sphere (4 x 4 per face: 96 quads or 192 triangles) whose vertices were moved
// along the sphere by up to a quarter (quads) / 0.08 (triangles: more folds some of them) of the
// cube's edge: on the input's flat facets it ended up to 0.31 (quads) / 0.24 (triangles) off the
// sphere; the issue asks for 0.035.
TEST_P(SmoothSurfaceDrift, PerturbedSphereWithoutGeometry) {
  const DriftCase& c = GetParam();
  const double centre[3] = {0, 0, 0};
  Mesh mesh = curved_meshes::cube_sphere(4, 5.0, centre, c.triangles, c.triangles ? 0.08 : 0.25);
  const Mesh input = mesh;
  ASSERT_LE(curved_meshes::sphere_drift(mesh, centre, 5.0), 1e-12);
  const Status s = run_recipe(&mesh, c.surface_recipe, "");
  ASSERT_TRUE(s.ok()) << s.message();
  double moved = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k)
      moved = std::max(moved, std::abs(mesh.coords[3 * v + k] - input.coords[3 * v + k]));
  const double drift = curved_meshes::sphere_drift(mesh, centre, 5.0);
  std::printf("%s: vertices moved up to %.3f, off the sphere up to %.4f\n", c.name, moved, drift);
  EXPECT_GT(moved, 0.3);  // the mesh did change
  EXPECT_LT(drift, 0.035);
}

INSTANTIATE_TEST_SUITE_P(Spheres, SmoothSurfaceDrift,
                         ::testing::Values(DriftCase{"quads_auto", false, false},
                                           DriftCase{"quads_surface", false, true},
                                           DriftCase{"triangles_auto", true, false},
                                           DriftCase{"triangles_surface", true, true}),
                         [](const auto& info) { return std::string(info.param.name); });

// An open cap of the radius-10 sphere, every vertex (rim too) moved along the sphere: with
// --geometry=sphere:0,0,0,10 under recipe surface the rim slid on its chords and ended up to
// 0.043 off the sphere; now every vertex stays on it.
TEST(AnalyticGeometry, OpenCapRimSlidesOnTheSphere) {
  Mesh mesh = curved_meshes::spherical_cap(10, 0.6, 6, 24, 0.2);
  const Mesh input = mesh;
  const Status s = run_recipe(&mesh, true, "sphere:0,0,0,10");
  ASSERT_TRUE(s.ok()) << s.message();
  const double origin[3] = {0, 0, 0};
  double rim_moved = 0;
  for (int v = mesh.num_vertices() - 24; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k)
      rim_moved = std::max(rim_moved, std::abs(mesh.coords[3 * v + k] - input.coords[3 * v + k]));
  const double drift = curved_meshes::sphere_drift(mesh, origin, 10.0);
  std::printf("cap rim moved up to %.3f; every vertex off the sphere up to %.2e\n", rim_moved,
              drift);
  EXPECT_GT(rim_moved, 0.05);
  EXPECT_LT(drift, 1e-9);
}

TEST(CheckGeometrySpec, MalformedFarUnusedAndGood) {
  const double c[3] = {2, 2, 0};
  const Mesh sphere = curved_meshes::cube_sphere(4, 3.0, c, true);
  BoundaryOptions o;
  auto check = [&](const Mesh& m, const std::string& spec, bool slide) {
    o.geometry = spec;
    o.slide = slide;
    return check_geometry_spec(m, o);
  };
  EXPECT_TRUE(check(sphere, "", false).ok());
  EXPECT_TRUE(check(sphere, "sphere:2,2,0,3", false).ok());     // surface meshes always slide
  EXPECT_TRUE(check(sphere, "sphere:2,2,0,3.005", true).ok());  // within 1e-3 x diagonal 10.4
  Status s = check(sphere, "sphere:1,2", true);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("expected 4 comma-separated numbers"), std::string::npos);
  // The unit sphere at the origin cuts this sphere through two of its vertices, but no facet
  // lies on it: the facet nearest to it has a vertex 0.518 away.
  s = check(sphere, "sphere:0,0,0,1", true);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("is 0.5176 from the mesh"), std::string::npos) << s.message();
  EXPECT_FALSE(check(sphere, "sphere:2,2,0,3.05", true).ok());
  EXPECT_FALSE(check(sphere, "plane:0,0,0,0,0,1", true).ok());
  EXPECT_FALSE(check(sphere, "/nonexistent/surface.stl", true).ok());
  // A volume mesh: only sliding boundary vertices use a geometry.
  const Mesh box = testing_grid::grid(CellType::kTet4, 3);  // the unit cube
  EXPECT_TRUE(check(box, "plane:0,0,0,0,0,1", true).ok());
  s = check(box, "plane:0,0,0,0,0,1", false);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("would be unused"), std::string::npos) << s.message();
  EXPECT_FALSE(check(box, "plane:0,0,-0.1,0,0,1", true).ok());
  // A 2D mesh has no surfaces.
  EXPECT_FALSE(check(testing_grid::grid(CellType::kTri3, 3), "plane:0,0,0,0,0,1", true).ok());
}

}  // namespace
}  // namespace tmop
