// Boundary classification of gmsh meshes, checked vertex by vertex against the known geometry:
// a box (tet4, tet10, and its surface triangulation), the part with a drilled hole and a
// spherical cavity (data/part.geo), and a 2D square with a hole.
#include "tmop/geometry/boundary_classification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "tests/geometry/geometry_test_meshes.h"

namespace tmop {
namespace {

using testing_util::load_geometry_mesh;

bool at_bound(double x, double lo, double hi) {
  return std::fabs(x - lo) < 1e-12 || std::fabs(x - hi) < 1e-12;
}

// Expected kind of a vertex of the box [0,hx]x[0,1]x[0,1] (volume mesh): by how many
// coordinates are on the box's faces.
VertexKind box_kind(const double* x, double hx = 1) {
  int on = at_bound(x[0], 0, hx);
  for (int i = 1; i < 3; ++i) on += at_bound(x[i], 0, 1);
  return on == 0 ? VertexKind::kInterior
                 : (on == 1 ? VertexKind::kSurface
                            : (on == 2 ? VertexKind::kCurve : VertexKind::kFixed));
}

void expect_box(const Mesh& mesh, const BoundaryClassification& c) {
  int expected[kNumVertexKinds] = {0, 0, 0, 0};
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const VertexKind k = box_kind(mesh.vertex(v));
    ++expected[static_cast<int>(k)];
    ASSERT_EQ(c.kind[v], k) << "vertex " << v;
  }
  EXPECT_EQ(c.count(VertexKind::kFixed), 8);
  for (int k = 0; k < kNumVertexKinds; ++k) {
    EXPECT_EQ(c.count(static_cast<VertexKind>(k)), expected[k]);
  }
  ASSERT_EQ(c.curves.size(), 12u);
  for (const BoundaryCurve& curve : c.curves) {
    EXPECT_TRUE(curve.straight);
    EXPECT_FALSE(curve.closed);
  }
  ASSERT_EQ(c.patches.size(), 6u);
  for (const BoundaryPatch& p : c.patches) {
    EXPECT_TRUE(p.planar);
    // Outward: the normal points away from the box centre.
    double r = 0;
    for (int i = 0; i < 3; ++i) r += (p.point[i] - 0.5) * p.normal[i];
    EXPECT_GT(r, 0.4);
  }
  // A curve's / patch's vertices agree on their id: every surface vertex of one patch has the
  // same constant coordinate.
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (c.kind[v] != VertexKind::kSurface) continue;
    const BoundaryPatch& p = c.patches[c.id[v]];
    double h = 0;
    for (int i = 0; i < 3; ++i) h += (mesh.vertex(v)[i] - p.point[i]) * p.normal[i];
    EXPECT_NEAR(h, 0, 1e-12);
  }
}

TEST(BoundaryClassification, BoxTet4) {
  const Mesh mesh = load_geometry_mesh("box.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  expect_box(mesh, c);
  EXPECT_EQ(c.count(VertexKind::kInterior), 67);  // known count of this fixture
}

TEST(BoundaryClassification, BoxTet10MidNodesTakeTheirEdgesKind) {
  const Mesh mesh = load_geometry_mesh("box_tet10.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  expect_box(mesh, c);
  // Curves run corner, mid, corner, ...: odd length.
  for (const BoundaryCurve& curve : c.curves) EXPECT_EQ(curve.vertices.size() % 2, 1u);
}

TEST(BoundaryClassification, BoxHex8AndHex27) {
  for (const char* name : {"box_hex.msh", "box_hex27.msh"}) {
    const Mesh mesh = load_geometry_mesh(name);
    BoundaryClassification c;
    ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok()) << name;
    expect_box(mesh, c);
  }
  // 5 x 5 x 5 grid points, of which 3^3 inside: 8 corners, 12 x 3 on edges, 6 x 9 on faces.
  const Mesh hex = load_geometry_mesh("box_hex.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(hex, {}, &c).ok());
  EXPECT_EQ(c.count(VertexKind::kCurve), 36);
  EXPECT_EQ(c.count(VertexKind::kSurface), 54);
  EXPECT_EQ(c.count(VertexKind::kInterior), 27);
  // hex27: 9 x 9 x 9 nodes; each patch splits 16 quad9 faces into 128 triangles.
  const Mesh hex27 = load_geometry_mesh("box_hex27.msh");
  ASSERT_TRUE(classify_boundary(hex27, {}, &c).ok());
  EXPECT_EQ(c.count(VertexKind::kCurve), 12 * 7);
  EXPECT_EQ(c.count(VertexKind::kSurface), 6 * 49);
  EXPECT_EQ(c.count(VertexKind::kInterior), 7 * 7 * 7);
  for (const BoundaryPatch& p : c.patches) EXPECT_EQ(p.triangles.size(), 128u);
}

TEST(BoundaryClassification, BoxSurfaceMesh) {
  Mesh mesh = load_geometry_mesh("box_surface.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  // Every vertex of a surface mesh is on the surface: the box's classification without the
  // interior (vertices of the 0D/1D tag cells are the same points).
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_EQ(c.kind[v], box_kind(mesh.vertex(v))) << v;
  }
  EXPECT_EQ(c.count(VertexKind::kInterior), 0);
  EXPECT_EQ(c.count(VertexKind::kFixed), 8);
  EXPECT_EQ(c.curves.size(), 12u);
  EXPECT_EQ(c.patches.size(), 6u);
}

// The part: box [0,2]x[0,1]x[0,1], hole of radius 0.25 along z through (0.6, 0.5), spherical
// cavity of radius 0.25 at (1.45, 0.5, 0.5).
struct PartPoint {
  bool on_sphere, on_cylinder, on_rim;
};
PartPoint part_point(const double* x) {
  const double rs =
      std::sqrt(std::pow(x[0] - 1.45, 2) + std::pow(x[1] - 0.5, 2) + std::pow(x[2] - 0.5, 2));
  const double rc = std::hypot(x[0] - 0.6, x[1] - 0.5);
  const bool cyl = std::fabs(rc - 0.25) < 1e-6;
  return {std::fabs(rs - 0.25) < 1e-6, cyl && !at_bound(x[2], 0, 1), cyl && at_bound(x[2], 0, 1)};
}

void expect_part(const Mesh& mesh, const BoundaryClassification& c) {
  int sphere_patch = -1, cylinder_patch = -1, rims = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const PartPoint p = part_point(mesh.vertex(v));
    if (p.on_sphere) {
      ASSERT_EQ(c.kind[v], VertexKind::kSurface) << v;
      if (sphere_patch < 0) sphere_patch = c.id[v];
      EXPECT_EQ(c.id[v], sphere_patch);
    } else if (p.on_cylinder) {
      ASSERT_EQ(c.kind[v], VertexKind::kSurface) << v;
      if (cylinder_patch < 0) cylinder_patch = c.id[v];
      EXPECT_EQ(c.id[v], cylinder_patch);
    } else if (p.on_rim) {
      ASSERT_EQ(c.kind[v], VertexKind::kCurve) << v;
      EXPECT_TRUE(c.curves[c.id[v]].closed);
      ++rims;
    } else {
      // Everything else is the box: its own rules.
      EXPECT_EQ(c.kind[v], box_kind(mesh.vertex(v), 2)) << v;
    }
  }
  ASSERT_GE(sphere_patch, 0);
  ASSERT_GE(cylinder_patch, 0);
  EXPECT_NE(sphere_patch, cylinder_patch);
  EXPECT_FALSE(c.patches[sphere_patch].planar);
  EXPECT_FALSE(c.patches[cylinder_patch].planar);
  EXPECT_GT(rims, 10);
  int planar = 0, straight = 0, closed = 0;
  for (const BoundaryPatch& p : c.patches) planar += p.planar;
  for (const BoundaryCurve& curve : c.curves) {
    straight += curve.straight;
    closed += curve.closed;
  }
  EXPECT_EQ(c.count(VertexKind::kFixed), 8);
  EXPECT_EQ(c.patches.size(), 8u);
  EXPECT_EQ(planar, 6);
  EXPECT_EQ(c.curves.size(), 14u);
  EXPECT_EQ(straight, 12);
  EXPECT_EQ(closed, 2);
}

TEST(BoundaryClassification, PartWithHoleAndCavity) {
  // At -clmax 0.2 the cavity (radius 0.25) is meshed so coarsely that facets meet at ~35
  // degrees near its pole; 40 degrees keeps the sphere one smooth patch.
  const Mesh mesh = load_geometry_mesh("part.msh");
  BoundaryClassification c;
  ClassifyOptions options;
  options.feature_angle_deg = 40;
  ASSERT_TRUE(classify_boundary(mesh, options, &c).ok());
  expect_part(mesh, c);
}

TEST(BoundaryClassification, PartAtTheDefaultAngleSeesTheCoarsePole) {
  const Mesh mesh = load_geometry_mesh("part.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  // 3 corners and 2 short curves at the cavity's pole, the rest as at 40 degrees.
  EXPECT_EQ(c.count(VertexKind::kFixed), 11);
  EXPECT_EQ(c.curves.size(), 16u);
  EXPECT_EQ(c.patches.size(), 8u);
}

void expect_square_with_hole(const Mesh& mesh) {
  ASSERT_EQ(mesh.space_dim, 2);
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double* x = mesh.vertex(v);
    const int on = at_bound(x[0], 0, 1) + at_bound(x[1], 0, 1);
    const bool hole = std::fabs(std::hypot(x[0] - 0.5, x[1] - 0.5) - 0.25) < 1e-6;
    const VertexKind expected =
        on == 2 ? VertexKind::kFixed
                : (on == 1 || hole ? VertexKind::kCurve : VertexKind::kInterior);
    ASSERT_EQ(c.kind[v], expected) << v;
    if (hole) {
      EXPECT_TRUE(c.curves[c.id[v]].closed);
    }
  }
  EXPECT_EQ(c.count(VertexKind::kFixed), 4);
  EXPECT_EQ(c.count(VertexKind::kSurface), 0);
  ASSERT_EQ(c.curves.size(), 5u);
  int straight = 0;
  for (const BoundaryCurve& curve : c.curves) straight += curve.straight;
  EXPECT_EQ(straight, 4);
  EXPECT_TRUE(c.patches.empty());
}

TEST(BoundaryClassification, SquareWithHole2D) {
  expect_square_with_hole(load_geometry_mesh("square_hole.msh"));
}

TEST(BoundaryClassification, SquareWithHole2DTri6) {
  // Mid-edge nodes of boundary edges join their curves (gmsh puts them on the circle).
  expect_square_with_hole(load_geometry_mesh("square_hole_tri6.msh"));
}

TEST(BoundaryClassification, BoxSurfaceMeshTri6) {
  const Mesh mesh = load_geometry_mesh("box_surface_tri6.msh");
  BoundaryClassification c;
  ASSERT_TRUE(classify_boundary(mesh, {}, &c).ok());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_EQ(c.kind[v], box_kind(mesh.vertex(v))) << v;
  }
  EXPECT_EQ(c.count(VertexKind::kFixed), 8);
  EXPECT_EQ(c.curves.size(), 12u);
  EXPECT_EQ(c.patches.size(), 6u);
}

TEST(BoundaryClassification, FeatureAngleDecidesCorners2D) {
  // A regular hexagon split into 6 triangles: turning angle 60 degrees at each boundary vertex.
  Mesh mesh;
  mesh.space_dim = 2;
  const double centre[2] = {0, 0};
  mesh.add_vertex(centre);
  for (int k = 0; k < 6; ++k) {
    const double p[2] = {std::cos(M_PI * k / 3), std::sin(M_PI * k / 3)};
    mesh.add_vertex(p);
  }
  for (int k = 0; k < 6; ++k) {
    const std::int32_t tri[3] = {0, 1 + k, 1 + (k + 1) % 6};
    mesh.add_cell(CellType::kTri3, tri);
  }
  BoundaryClassification c;
  ClassifyOptions options;
  ASSERT_TRUE(classify_boundary(mesh, options, &c).ok());
  EXPECT_EQ(c.count(VertexKind::kFixed), 6);
  options.feature_angle_deg = 61;
  ASSERT_TRUE(classify_boundary(mesh, options, &c).ok());
  EXPECT_EQ(c.count(VertexKind::kFixed), 0);
  EXPECT_EQ(c.count(VertexKind::kCurve), 6);
  ASSERT_EQ(c.curves.size(), 1u);
  EXPECT_TRUE(c.curves[0].closed);
  EXPECT_EQ(c.curves[0].vertices.size(), 6u);
}

TEST(BoundaryClassification, BoundaryTagsGiveTheCadFeaturesAtAnyAngle) {
  // With a 179 degree feature angle only the tagged faces / lines (gmsh entities) split.
  ClassifyOptions options;
  options.feature_angle_deg = 179;
  options.boundary_tags = true;
  BoundaryClassification c;
  const Mesh box = load_geometry_mesh("box.msh");
  ASSERT_TRUE(classify_boundary(box, options, &c).ok());
  expect_box(box, c);
  const Mesh part = load_geometry_mesh("part.msh");
  ASSERT_TRUE(classify_boundary(part, options, &c).ok());
  expect_part(part, c);
  const Mesh square = load_geometry_mesh("square_hole.msh");
  ASSERT_TRUE(classify_boundary(square, options, &c).ok());
  EXPECT_EQ(c.count(VertexKind::kFixed), 4);
  EXPECT_EQ(c.curves.size(), 5u);
  // Without the tags nothing is sharp enough: the box is one patch without curves.
  options.boundary_tags = false;
  ASSERT_TRUE(classify_boundary(box, options, &c).ok());
  EXPECT_EQ(c.patches.size(), 1u);
  EXPECT_EQ(c.curves.size(), 0u);
}

TEST(BoundaryClassification, RejectsBadInput) {
  Mesh empty;
  BoundaryClassification c;
  EXPECT_FALSE(classify_boundary(empty, {}, &c).ok());
  const Mesh mesh = load_geometry_mesh("box.msh");
  ClassifyOptions options;
  options.feature_angle_deg = 0;
  EXPECT_FALSE(classify_boundary(mesh, options, &c).ok());
}

}  // namespace
}  // namespace tmop
