// tmop/geometry/boundary_constraints.h
// BoundaryConstraints: what the optimizer needs to know about every vertex's freedom - fixed,
// free (interior), or sliding on a curve / surface given as a ceres::Manifold - built from the
// mesh's own boundary (boundary_classification.h) and an optional user geometry
// (geometry_source.h).
//
// Vertex kinds: interior -> free, no manifold. Corners -> fixed. Curve vertices -> the curve's
// PolylineManifold (straight curves: a two-point polyline, exact and clamped at the corners).
// Surface vertices -> the patch's PlaneManifold (planar patches) or TriangleSurfaceManifold in
// its smooth shape (curved patches: a smooth surface through the ORIGINAL vertices, walked on
// the original facets, so repeated steps do not drift and vertices do not sink onto the facets).
// With a user geometry, surface vertices of curved patches that lie on it (the vertex and its
// patch neighbours within on_geometry_tolerance) use it instead; planar patches keep their exact
// plane. Curves keep their polylines, except those whose vertices all lie on an analytic user
// geometry and that border only curved patches (an open cap's rim): ProjectedCurveManifold, the
// polyline projected onto the geometry.
// slide = false: every boundary vertex is fixed; surface meshes (2D cells in 3D) keep their
// surface vertices sliding (they must stay on the surface) and fix their rim curves.
//
// Ownership: the object owns every manifold; manifold(v) pointers stay valid while it lives and
// one object is shared by all the vertices of a curve / patch / user geometry, so the
// optimizer must use Problem::Options::manifold_ownership = DO_NOT_TAKE_OWNERSHIP. Not copyable.
// Every query is const and thread-safe.
// Failure (Build returns a Status, *out untouched): classification errors (empty mesh, bad
// feature angle), a malformed or unreadable geometry, a user geometry on a 2D mesh.
#ifndef TMOP_GEOMETRY_BOUNDARY_CONSTRAINTS_H_
#define TMOP_GEOMETRY_BOUNDARY_CONSTRAINTS_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/geometry/boundary_classification.h"
#include "tmop/geometry/geometry_frame.h"
#include "tmop/mesh/mesh.h"

// Forward declarations keep Ceres out of the public headers (tmop.h compiles without Ceres,
// glog or gflags include paths); callers of manifold() / geometry() include
// geometry/geometry_manifold.h.
namespace ceres {
class Manifold;
}  // namespace ceres

namespace tmop {

class GeometryManifold;  // geometry/geometry_manifold.h

struct BoundaryOptions {
  // Let boundary vertices slide on their curves / surfaces (true) or fix them all (false).
  bool slide = true;
  // Dihedral / turning angle above which an edge is a feature and a vertex a corner, degrees.
  double feature_angle_deg = 30;
  // Also split patches / curves where the file's tagged boundary cells change tag
  // (ClassifyOptions::boundary_tags): the CAD's own surfaces and curves for gmsh meshes.
  bool boundary_tags = false;
  // "" (own boundary), "sphere:cx,cy,cz,r", "plane:px,py,pz,nx,ny,nz",
  // "cylinder:px,py,pz,dx,dy,dz,r" or a surface file (.stl .obj .off .ply): geometry_source.h.
  std::string geometry;
  // A vertex lies on the user geometry when its distance is at most this times the mean
  // boundary edge length. 0.05 accepts a reference triangulation's chord error while keeping
  // vertices of other surfaces (one or more edge lengths away) on their own patches.
  double on_geometry_tolerance = 0.05;
  // optimize/ solves in normalised coordinates x' = (x - centre) / length: pass the mesh as
  // normalised to Build and that centre / length here, and the user geometry (given in the
  // user's units) is mapped the same way. The own-boundary geometry needs nothing: it is built
  // from the mesh as passed.
  GeometryFrame geometry_frame;
};

class BoundaryConstraints {
 public:
  static Status Build(const Mesh& mesh, const BoundaryOptions& options,
                      std::unique_ptr<BoundaryConstraints>* out);
  ~BoundaryConstraints();
  BoundaryConstraints(const BoundaryConstraints&) = delete;
  BoundaryConstraints& operator=(const BoundaryConstraints&) = delete;

  int num_vertices() const { return static_cast<int>(kind_.size()); }
  // The vertex's effective kind (after slide = false and the user geometry are applied).
  VertexKind kind(int vertex) const { return kind_[vertex]; }
  bool fixed(int vertex) const { return kind_[vertex] == VertexKind::kFixed; }
  // Per-vertex flags (1 = fixed), the form optimize/'s StageSpec::fixed takes.
  std::vector<char> fixed_flags() const;
  // nullptr for interior and fixed vertices. Ambient size = mesh.space_dim; tangent size 1
  // (curves) or 2 (surfaces).
  const ceres::Manifold* manifold(int vertex) const;
  const GeometryManifold* geometry(int vertex) const;
  // Unit normal of the geometry at a point x near the vertex, oriented like the mesh (outward
  // for volume meshes, along the cells' right-hand normal for surface meshes), for every vertex
  // of a surface mesh and every boundary vertex of a volume mesh. False (n untouched) for
  // interior vertices and 2D meshes.
  bool normal(int vertex, const double* x, double* n) const;
  // The normal a cell of a surface mesh sees at its corner `corner` (local index), at a point x
  // near that corner: the user geometry's where the vertex lies on it, otherwise the normal of
  // the cell's own patch, oriented like that patch's cells around the vertex at Build. A vertex
  // on a curve or corner borders several patches (at a crease or where surfaces of opposite
  // orientation meet, their normals disagree): normal() gives one of them, this the cell's.
  // Falls back to normal() for cells without a patch (volume meshes).
  bool cell_normal(int cell, int corner, const std::int32_t* cell_nodes, const double* x,
                   double* n) const;
  // Distance of x from the geometry the vertex is constrained to: the manifold's distance for
  // sliding vertices, the distance from the vertex's original position for fixed ones, 0 for
  // interior vertices.
  double distance(int vertex, const double* x) const;
  int count(VertexKind kind) const;
  // How many vertices use the user geometry (0 without one).
  int num_on_user_geometry() const { return num_on_user_geometry_; }
  const BoundaryClassification& classification() const { return classification_; }
  // One line: "slide: 8 fixed, 60 curve, 204 surface, 67 interior; 12 curves, 6 patches (6
  // planar); geometry: own boundary".
  std::string summary() const;

 private:
  BoundaryConstraints() = default;
  static void orient_cell_normals(const Mesh& mesh, BoundaryConstraints* bc);

  BoundaryClassification classification_;
  std::vector<std::unique_ptr<GeometryManifold>> manifolds_;
  std::vector<VertexKind> kind_;
  std::vector<std::int32_t> slot_;         // manifold index per vertex, -1: none
  std::vector<std::int32_t> normal_slot_;  // manifold giving the normal, -1: none
  std::vector<std::int8_t> normal_sign_;   // +1 / -1 to orient it like the mesh
  std::vector<std::uint8_t> cell_flip_;    // surface meshes: bit k set = flip corner k's normal
  int first_patch_ = 0;                    // manifold index of patch 0
  int user_slot_ = -1;                     // manifold index of the user geometry, -1: none
  std::vector<double> original_;           // coordinates at Build, for fixed vertices
  int space_dim_ = 3;
  int num_on_user_geometry_ = 0;
  bool slide_ = true;
  std::string geometry_description_;
};

}  // namespace tmop

#endif  // TMOP_GEOMETRY_BOUNDARY_CONSTRAINTS_H_
