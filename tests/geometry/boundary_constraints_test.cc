// BoundaryConstraints: per-vertex kinds and manifolds on gmsh meshes, shared manifold objects,
// slide = false, analytic and file geometries, normals oriented like the mesh, and Plus steps
// that stay on the geometry.
#include "tmop/geometry/boundary_constraints.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <set>

#include "tests/geometry/geometry_test_meshes.h"
#include "tests/temp_dir.h"
#include "tmop/geometry/cylinder_manifold.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/polyline_manifold.h"
#include "tmop/geometry/reference_surface.h"
#include "tmop/geometry/sphere_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using testing_util::geometry_data;
using testing_util::load_geometry_mesh;

std::unique_ptr<BoundaryConstraints> build(const Mesh& mesh, const BoundaryOptions& options) {
  std::unique_ptr<BoundaryConstraints> bc;
  const Status s = BoundaryConstraints::Build(mesh, options, &bc);
  EXPECT_TRUE(s.ok()) << s.message();
  return bc;
}

// Random Plus steps of every sliding vertex (chained 20 times, in place on a copy of its
// coordinates), checking the result against `on_geometry` (max allowed distance).
void walk_all(const Mesh& mesh, const BoundaryConstraints& bc, double step, double on_geometry) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-step, step);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const ceres::Manifold* m = bc.manifold(v);
    if (!m) continue;
    double x[3], y[3];
    std::copy(mesh.vertex(v), mesh.vertex(v) + mesh.space_dim, x);
    for (int k = 0; k < 20; ++k) {
      const double d[2] = {u(rng), u(rng)};
      ASSERT_TRUE(m->Plus(x, d, y));
      std::copy(y, y + mesh.space_dim, x);
      ASSERT_LE(bc.distance(v, x), on_geometry) << "vertex " << v;
    }
  }
}

TEST(BoundaryConstraints, BoxSlidesOnPlanesAndLines) {
  const Mesh mesh = load_geometry_mesh("box.msh");
  auto bc = build(mesh, {});
  EXPECT_EQ(bc->count(VertexKind::kFixed), 8);
  EXPECT_EQ(bc->count(VertexKind::kCurve), 60);
  EXPECT_EQ(bc->count(VertexKind::kSurface), 204);
  EXPECT_EQ(bc->count(VertexKind::kInterior), 67);
  std::set<const ceres::Manifold*> curves, planes;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const ceres::Manifold* m = bc->manifold(v);
    switch (bc->kind(v)) {
      case VertexKind::kFixed:
      case VertexKind::kInterior:
        EXPECT_EQ(m, nullptr);
        break;
      case VertexKind::kCurve:
        ASSERT_NE(dynamic_cast<const PolylineManifold*>(m), nullptr);
        EXPECT_EQ(m->TangentSize(), 1);
        curves.insert(m);
        break;
      case VertexKind::kSurface:
        ASSERT_NE(dynamic_cast<const PlaneManifold*>(m), nullptr);
        EXPECT_EQ(m->TangentSize(), 2);
        planes.insert(m);
        break;
    }
  }
  // One shared object per curve and per patch.
  EXPECT_EQ(curves.size(), 12u);
  EXPECT_EQ(planes.size(), 6u);
  EXPECT_EQ(bc->fixed_flags().size(), static_cast<std::size_t>(mesh.num_vertices()));
  walk_all(mesh, *bc, 0.05, 1e-15);
  // Normals of boundary vertices point out of the box.
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    double n[3];
    if (bc->kind(v) != VertexKind::kSurface) continue;
    ASSERT_TRUE(bc->normal(v, mesh.vertex(v), n));
    const double* x = mesh.vertex(v);
    EXPECT_GT((x[0] - 0.5) * n[0] + (x[1] - 0.5) * n[1] + (x[2] - 0.5) * n[2], 0.49);
  }
  EXPECT_NE(bc->summary().find("8 fixed"), std::string::npos) << bc->summary();
}

TEST(BoundaryConstraints, NoSlideFixesTheWholeBoundary) {
  const Mesh mesh = load_geometry_mesh("box.msh");
  BoundaryOptions options;
  options.slide = false;
  auto bc = build(mesh, options);
  EXPECT_EQ(bc->count(VertexKind::kFixed), 8 + 60 + 204);
  for (int v = 0; v < mesh.num_vertices(); ++v) EXPECT_EQ(bc->manifold(v), nullptr);
  const double moved[3] = {mesh.vertex(0)[0] + 0.3, mesh.vertex(0)[1], mesh.vertex(0)[2] + 0.4};
  EXPECT_NEAR(bc->distance(0, moved), 0.5, 1e-15);
}

TEST(BoundaryConstraints, PartOwnBoundaryKeepsCurvedPatchesOnTheOriginalFacets) {
  const Mesh mesh = load_geometry_mesh("part.msh");
  BoundaryOptions options;
  options.feature_angle_deg = 40;
  auto bc = build(mesh, options);
  int curved = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    curved += dynamic_cast<const TriangleSurfaceManifold*>(bc->manifold(v)) != nullptr;
  }
  EXPECT_GT(curved, 50);
  // Steps of ~ a third of an edge, 20 times: still on the original triangles to round-off.
  walk_all(mesh, *bc, 0.03, 1e-14);
}

TEST(BoundaryConstraints, AnalyticSphereAndCylinder) {
  const Mesh mesh = load_geometry_mesh("part.msh");
  for (const char* spec : {"sphere:1.45,0.5,0.5,0.25", "cylinder:0.6,0.5,0,0,0,1,0.25"}) {
    BoundaryOptions options;
    options.feature_angle_deg = 40;
    options.geometry = spec;
    auto bc = build(mesh, options);
    const bool sphere = spec[0] == 's';
    int on = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const ceres::Manifold* m = bc->manifold(v);
      const bool analytic = sphere ? dynamic_cast<const SphereManifold*>(m) != nullptr
                                   : dynamic_cast<const CylinderManifold*>(m) != nullptr;
      if (!analytic) continue;
      ++on;
      EXPECT_LE(bc->distance(v, mesh.vertex(v)), 1e-12);
      // The cavity is a hole in the solid: the outward normal points towards the centre.
      double n[3];
      ASSERT_TRUE(bc->normal(v, mesh.vertex(v), n));
      const double* x = mesh.vertex(v);
      const double radial[3] = {x[0] - (sphere ? 1.45 : 0.6), x[1] - 0.5,
                                sphere ? x[2] - 0.5 : 0.0};
      EXPECT_LT(radial[0] * n[0] + radial[1] * n[1] + radial[2] * n[2], 0);
    }
    EXPECT_EQ(on, bc->num_on_user_geometry()) << spec;
    // Every node of the cavity (80) / of the hole's wall off its rims (137) is on it.
    EXPECT_EQ(on, sphere ? 80 : 137) << spec;
    walk_all(mesh, *bc, 0.03, 1e-14);
  }
}

TEST(BoundaryConstraints, UserGeometryFollowsANormalisedMesh) {
  // The optimizer's normalisation x' = (x - c) / L: the same vertices land on the sphere and
  // the file's surface, now mapped into the normalised frame.
  Mesh mesh = load_geometry_mesh("part.msh");
  const double c[3] = {1.0, 0.4, 0.6}, L = 0.07;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    for (int i = 0; i < 3; ++i) mesh.vertex(v)[i] = (mesh.vertex(v)[i] - c[i]) / L;
  }
  for (const std::string& spec :
       {std::string("sphere:1.45,0.5,0.5,0.25"), geometry_data("cavity_sphere.stl")}) {
    BoundaryOptions options;
    options.feature_angle_deg = 40;
    options.geometry = spec;
    std::copy(c, c + 3, options.geometry_frame.centre);
    options.geometry_frame.length = L;
    auto bc = build(mesh, options);
    EXPECT_EQ(bc->num_on_user_geometry(), 80) << spec;
    walk_all(mesh, *bc, 0.03 / L, 1e-12);
  }
}

TEST(BoundaryConstraints, ReferenceSurfaceFile) {
  const Mesh mesh = load_geometry_mesh("part.msh");
  BoundaryOptions options;
  options.feature_angle_deg = 40;
  options.geometry = geometry_data("cavity_sphere.stl");
  auto bc = build(mesh, options);
  // Only the cavity's vertices lie on the file's sphere; the hole keeps its own facets.
  int on = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (bc->manifold(v) == nullptr || bc->kind(v) != VertexKind::kSurface) continue;
    const double* x = mesh.vertex(v);
    const double r =
        std::sqrt(std::pow(x[0] - 1.45, 2) + std::pow(x[1] - 0.5, 2) + std::pow(x[2] - 0.5, 2));
    if (std::fabs(r - 0.25) < 1e-6) {
      ++on;
      EXPECT_LT(bc->distance(v, x), 3e-3);  // the STL's chord error, about h^2 / (8 r)
    }
  }
  EXPECT_EQ(on, bc->num_on_user_geometry());
  EXPECT_EQ(on, 80);
  walk_all(mesh, *bc, 0.03, 1e-14);

  // The same sphere (a binary STL) with a degenerate facet added: the same constraints, and the
  // summary says what was dropped.
  std::ifstream in(geometry_data("cavity_sphere.stl"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 84u);
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  ++count;
  std::memcpy(&bytes[80], &count, 4);
  const float facet[12] = {0, 0, 1, 9, 9, 9, 9, 9, 9, 8, 9, 9};  // normal, corners 1 = 2
  bytes.append(reinterpret_cast<const char*>(facet), sizeof facet);
  bytes.append(2, '\0');  // attribute byte count
  const std::string with_degenerate = testing_tmp::dir() + "cavity_sphere_degenerate.stl";
  std::ofstream(with_degenerate, std::ios::binary) << bytes;
  options.geometry = with_degenerate;
  auto repaired = build(mesh, options);
  EXPECT_EQ(repaired->num_on_user_geometry(), 80);
  EXPECT_NE(repaired->summary().find("1 degenerate facets dropped"), std::string::npos)
      << repaired->summary();
}

// Reference surfaces go through tmop's strict readers: a malformed file is one line naming
// the file and the place (OpenMesh's reader, used before, allocated 16 GB for the OFF below),
// and quads are split into two triangles.
TEST(ReferenceSurface, MalformedFilesAreRefusedWithTheirPlaceAndQuadsAreSplit) {
  const std::string dir = testing_tmp::dir();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + name) << text;
    return dir + name;
  };
  std::vector<double> v;
  std::vector<std::int32_t> t;
  const std::string off = write("huge_counts.off", "OFF\n100000000 100000000 0\n0 0 0\n");
  Status s = read_reference_surface(off, &v, &t);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind(off, 0), 0u) << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << s.message();
  const std::string obj = write("bad_coordinate.obj", "v 0 0 0\nv 1 0 zero\nv 0 1 0\nf 1 2 3\n");
  s = read_reference_surface(obj, &v, &t);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find(obj + ":2"), std::string::npos) << s.message();
  const std::string quad = write("quad.obj", "v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 2 3 4\n");
  ASSERT_TRUE(read_reference_surface(quad, &v, &t).ok());
  EXPECT_EQ(v.size(), 12u);
  EXPECT_EQ(t, (std::vector<std::int32_t>{0, 1, 2, 0, 2, 3}));
  const std::string planar = write("planar.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_TRUE(read_reference_surface(planar, &v, &t).ok());
  EXPECT_EQ(v, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));  // z = 0 kept in 3D
}

// What scanners and CAD exporters write, and a mesh reader refuses (read_mesh stays strict),
// is fine as geometry: degenerate facets are dropped with their vertices, polygons become fans.
TEST(ReferenceSurface, DegenerateFacetsAreDroppedAndPolygonsSplit) {
  const std::string dir = testing_tmp::dir();
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir + name) << text;
    return dir + name;
  };
  auto facet = [](const char* a, const char* b, const char* c) {
    return std::string("facet normal 0 0 1\nouter loop\nvertex ") + a + "\nvertex " + b +
           "\nvertex " + c + "\nendloop\nendfacet\n";
  };
  const std::string stl =
      write("degenerate.stl", "solid s\n" + facet("0 0 0", "1 0 0", "0 1 0") +
                                  facet("5 5 5", "5 5 5", "6 5 5") +
                                  facet("1 0 0", "1 1 0", "0 1 0") + "endsolid s\n");
  Mesh strict;
  EXPECT_FALSE(read_mesh(stl, &strict).ok());
  std::vector<double> v;
  std::vector<std::int32_t> t;
  SurfaceRepair repair;
  ASSERT_TRUE(read_reference_surface(stl, &v, &t, &repair).ok());
  EXPECT_EQ(repair.dropped_degenerate, 1);
  EXPECT_EQ(t.size(), 6u);
  EXPECT_EQ(v.size(), 12u);  // the degenerate facet's corners are not kept
  const std::string obj = write("pentagon.obj",
                                "v 0 0 1\nv 1 0 1\nv 2 1 1\nv 1 2 1\nv 0 1 1\nv 9 9 9\n"
                                "f 1 2 3 4 5\nf 1 1 2\n");
  EXPECT_FALSE(read_mesh(obj, &strict).ok());
  ASSERT_TRUE(read_reference_surface(obj, &v, &t, &repair).ok());
  EXPECT_EQ(repair.split_polygons, 1);
  EXPECT_EQ(repair.dropped_degenerate, 1);
  EXPECT_EQ(t, (std::vector<std::int32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
  EXPECT_EQ(v.size(), 15u);  // the unused vertex 9 9 9 is left out
}

TEST(BoundaryConstraints, SurfaceMeshNormalsFollowTheCells) {
  const Mesh mesh = load_geometry_mesh("box_surface.msh");
  BoundaryOptions options;
  options.slide = false;  // surface meshes keep their surface vertices sliding
  auto bc = build(mesh, options);
  EXPECT_EQ(bc->count(VertexKind::kSurface), 204);
  EXPECT_EQ(bc->count(VertexKind::kFixed), 68);
  // Normals of every vertex, corners included, agree with the cells' right-hand normal.
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_type(c) != CellType::kTri3) continue;
    const std::int32_t* t = mesh.cell(c);
    const double* a = mesh.vertex(t[0]);
    const double* b = mesh.vertex(t[1]);
    const double* p = mesh.vertex(t[2]);
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double cell_n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                              e1[0] * e2[1] - e1[1] * e2[0]};
    for (int k = 0; k < 3; ++k) {
      double n[3];
      ASSERT_TRUE(bc->normal(t[k], mesh.vertex(t[k]), n));
      EXPECT_GE(n[0] * cell_n[0] + n[1] * cell_n[1] + n[2] * cell_n[2], 0);
    }
  }
}

TEST(BoundaryConstraints, Square2DSlidesOnItsPolylines) {
  const Mesh mesh = load_geometry_mesh("square_hole.msh");
  auto bc = build(mesh, {});
  EXPECT_EQ(bc->count(VertexKind::kFixed), 4);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (bc->kind(v) == VertexKind::kCurve) {
      ASSERT_NE(bc->manifold(v), nullptr);
      EXPECT_EQ(bc->manifold(v)->AmbientSize(), 2);
    }
    double n[3];
    EXPECT_FALSE(bc->normal(v, mesh.vertex(v), n));
  }
  walk_all(mesh, *bc, 0.05, 1e-15);
}

TEST(BoundaryConstraints, BadGeometryIsAStatus) {
  const Mesh mesh = load_geometry_mesh("box.msh");
  for (const char* spec : {"sphere:1,2,3", "sphere:0,0,0,-1", "plane:0,0,0,0,0,0",
                           "cylinder:0,0,0,1,0,0", "nosuchfile.stl", "shape.txt"}) {
    BoundaryOptions options;
    options.geometry = spec;
    std::unique_ptr<BoundaryConstraints> bc;
    const Status s = BoundaryConstraints::Build(mesh, options, &bc);
    EXPECT_FALSE(s.ok()) << spec;
    EXPECT_EQ(bc, nullptr);
    EXPECT_EQ(s.message().find('\n'), std::string::npos);
  }
  // A reference surface of slivers only.
  const std::string slivers = std::string(TMOP_BINARY_DIR) + "/geometry_slivers.stl";
  {
    std::ofstream f(slivers);
    f << "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 2 0 0\n"
         "endloop\nendfacet\nendsolid s\n";
  }
  BoundaryOptions sliver_options;
  sliver_options.geometry = slivers;
  std::unique_ptr<BoundaryConstraints> none;
  const Status sliver_status = BoundaryConstraints::Build(mesh, sliver_options, &none);
  EXPECT_FALSE(sliver_status.ok());
  EXPECT_NE(sliver_status.message().find("positive area"), std::string::npos)
      << sliver_status.message();
  const Mesh square = load_geometry_mesh("square_hole.msh");
  BoundaryOptions options;
  options.geometry = "sphere:0,0,0,1";
  std::unique_ptr<BoundaryConstraints> bc;
  EXPECT_FALSE(BoundaryConstraints::Build(square, options, &bc).ok());
}

}  // namespace
}  // namespace tmop
