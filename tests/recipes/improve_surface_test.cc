// The OpenMesh API: a lat-long sphere held as an OpenMesh TriMesh (float and double points) and
// a quad PolyMesh, improved in place on the exact sphere.
#include "tmop/recipes/improve_surface.h"

// OpenMesh's inline containers trip GCC 12's -Wmaybe-uninitialized (a false positive inside
// std::vector construction in its headers), as in tmop/io/openmesh_io.cc.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <cmath>
#include <cstdio>

#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using TriMeshF = OpenMesh::TriMesh_ArrayKernelT<>;
using TriMeshD = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using PolyMeshD = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

// Lat-long sphere: triangles (with pole fans) or quads (pole fans stay triangles).
template <class OM>
OM sphere(int nlat, int nlon, bool quads) {
  OM om;
  std::vector<typename OM::VertexHandle> v;
  v.push_back(om.add_vertex(typename OM::Point(0, 0, 1)));
  for (int i = 1; i < nlat; ++i) {
    const double th = M_PI * std::pow(double(i) / nlat, 1.6);
    for (int j = 0; j < nlon; ++j) {
      const double ph = 2 * M_PI * j / nlon;
      v.push_back(om.add_vertex(typename OM::Point(std::sin(th) * std::cos(ph),
                                                   std::sin(th) * std::sin(ph), std::cos(th))));
    }
  }
  v.push_back(om.add_vertex(typename OM::Point(0, 0, -1)));
  auto id = [&](int i, int j) { return v[1 + (i - 1) * nlon + (j % nlon)]; };
  for (int j = 0; j < nlon; ++j) om.add_face(v[0], id(1, j), id(1, j + 1));
  for (int i = 1; i < nlat - 1; ++i)
    for (int j = 0; j < nlon; ++j) {
      if (quads) {
        om.add_face(std::vector<typename OM::VertexHandle>{id(i, j), id(i + 1, j), id(i + 1, j + 1),
                                                           id(i, j + 1)});
      } else {
        om.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
        om.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
      }
    }
  for (int j = 0; j < nlon; ++j) om.add_face(v.back(), id(nlat - 1, j + 1), id(nlat - 1, j));
  return om;
}

template <class OM>
double worst_radius_error(const OM& om) {
  double worst = 0;
  for (auto vh : om.vertices()) {
    const auto& p = om.point(vh);
    worst = std::max(
        worst,
        std::abs(std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]) - 1));
  }
  return worst;
}

template <class OM>
void check(OM om, double tolerance, const char* label, bool quads = false) {
  UntangleOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = improve_surface(&om, "sphere:0,0,0,1", opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_LT(worst_radius_error(om), tolerance);
  EXPECT_EQ(result.after.inverted, 0);
  // Triangles are judged by their mean ratio, which the shape recipe raises. Quads are judged by
  // their scaled Jacobian (angles): the recipe keeps each corner's aspect (the lat-long
  // sphere's thin polar quads stay thin, docs/quality.md "Guarantees"), so the shape-quality
  // minimum of measure_mesh, which counts aspect, is not a goal there.
  if (!quads) {
    EXPECT_GT(result.after.min_quality, 1.4 * result.before.min_quality);
  }
  std::printf("%s: worst shape quality %.3f -> %.3f, max |r - 1| %.1e\n", label,
              result.before.min_quality, result.after.min_quality, worst_radius_error(om));
}

TEST(ImproveSurface, FloatTriMeshStaysOnTheSphereToFloatPrecision) {
  check(sphere<TriMeshF>(16, 32, false), 1e-6, "TriMesh float");
}

TEST(ImproveSurface, DoubleTriMeshStaysOnTheSphereExactly) {
  check(sphere<TriMeshD>(16, 32, false), 1e-12, "TriMesh double");
}

TEST(ImproveSurface, QuadPolyMesh) {
  check(sphere<PolyMeshD>(16, 32, true), 1e-12, "PolyMesh", true);
}

TEST(ImproveSurface, RefusesPolygonsWithMoreThanFourVertices) {
  PolyMeshD om;
  std::vector<PolyMeshD::VertexHandle> v;
  for (int i = 0; i < 5; ++i)
    v.push_back(om.add_vertex(PolyMeshD::Point(std::cos(i * 1.2566), std::sin(i * 1.2566), 0)));
  om.add_face(v);
  RecipeResult result;
  EXPECT_FALSE(improve_surface(&om, "", UntangleOptions(), &result).ok());
}

}  // namespace
}  // namespace tmop
