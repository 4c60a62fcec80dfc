// tmop/geometry/boundary_classification.h
// Classifies the vertices of a mesh by the geometry of its own boundary (no CAD needed):
//
//   volume mesh (3D elements): the boundary facets are split into surface patches by feature
//     edges - edges whose two boundary facets meet at a dihedral angle above feature_angle_deg
//     (angle between the outward normals), edges of the boundary that are non-manifold (not
//     exactly two facets), and, optionally, edges where the facets' owning cells carry different
//     cell_region tags (region interfaces reaching the boundary) and, optionally, where the
//     file's tagged boundary faces change tag. Feature edges form curves;
//     their vertices with a number of feature edges other than 2, or where the curve turns by
//     more than feature_angle_deg, are corners.
//   surface mesh (2D cells in 3D): the cells themselves play the boundary facets' role; edges of
//     one cell (the surface's own rim) are feature edges too.
//   planar mesh (2D cells in 2D): the boundary edges form the curves; corners by turning angle
//     (and region changes).
//
// Output per vertex: kind (interior: off the boundary; fixed: corner; curve: slides on the curve
// `id`; surface: slides on the patch `id`). Quadratic cells: corners are classified by the linear
// facets; mid-edge nodes take the kind of their edge (feature edge -> its curve, otherwise the
// facet's patch) and mid-face nodes the facet's patch. Curves are the polylines of feature edges
// between corners (closed loops when they meet none) with the mid-edge nodes in sequence;
// patches carry their facets split into triangles (original corner order: outward for volume
// meshes; surface meshes: turned where a cell's parity is -1, so a patch's triangles run one way)
// and a best-fit plane that counts as exact when every vertex lies within 1e-10 x the
// patch size of it; curves count as straight the same way.
//
// Failure (Status): a mesh without elements, 1D meshes, 3D elements in 2D space, a feature angle
// outside (0, 180). Cost O(N log N) in the number of boundary facets.
#ifndef TMOP_GEOMETRY_BOUNDARY_CLASSIFICATION_H_
#define TMOP_GEOMETRY_BOUNDARY_CLASSIFICATION_H_

#include <array>
#include <cstdint>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

enum class VertexKind : std::uint8_t { kInterior, kFixed, kCurve, kSurface };
constexpr int kNumVertexKinds = 4;
const char* vertex_kind_name(VertexKind kind);  // "interior", "fixed", "curve", "surface"

struct BoundaryCurve {
  // Vertices in order along the curve, mid-edge nodes included. Open curves start and end at
  // corners (fixed vertices); closed curves do not repeat their first vertex.
  std::vector<std::int32_t> vertices;
  bool closed = false;
  bool straight = false;  // open, and every vertex within 1e-10 x length of the end-to-end line
};

struct BoundaryPatch {
  std::vector<std::array<std::int32_t, 3>> triangles;  // facets split into triangles
  bool planar = false;
  double point[3] = {0, 0, 0};   // best-fit plane: centroid of the patch's vertices
  double normal[3] = {0, 0, 0};  // unit, oriented like the triangles' mean normal
};

struct ClassifyOptions {
  // Dihedral angle between adjacent boundary facets (and turning angle along curves) above
  // which an edge is a feature / a vertex a corner, in degrees. 30 keeps the edges of a box and
  // the rims of drilled holes while smooth curved surfaces (meshed with < 30 deg per facet)
  // stay single patches.
  double feature_angle_deg = 30;
  // Also split at edges where the boundary facets' cells have different cell_region tags.
  bool region_interfaces = true;
  // Also split where the boundary's own tagged cells (the lower-dimensional cells a .msh / .mesh
  // file carries: faces of volume meshes, lines of planar meshes) change tag: their entity tag,
  // or their region tag when the entity tag is 0. For meshes made from CAD this reproduces the
  // CAD's surfaces and curves whatever the angles. Facets without a tagged cell never split.
  bool boundary_tags = false;
};

struct BoundaryClassification {
  std::vector<VertexKind> kind;  // per vertex
  std::vector<std::int32_t> id;  // per vertex: curve (kCurve), patch (kSurface), else -1
  // Per vertex: a patch of a facet the vertex belongs to (any kind, -1 off the facets). Used
  // for normals of corners and curve vertices of surface meshes.
  std::vector<std::int32_t> vertex_patch;
  // Per cell of a surface mesh (2D cells in 3D): the patch of the cell (-1 for its other cells);
  // empty for other meshes. A vertex on a curve or corner borders several patches: a cell's
  // normals come from its own patch, not from the vertex's (vertex_patch).
  std::vector<std::int32_t> cell_patch;
  // Per cell of a surface mesh: its orientation component (cells joined across edges of exactly
  // two cells, whatever their angle) and its order within it: +1, or -1 where the cell's corners
  // run the other way (a surface a generator oriented on its own). -1 / 0 for other cells;
  // empty for other meshes.
  std::vector<std::int32_t> cell_component;
  std::vector<std::int8_t> cell_parity;
  std::vector<BoundaryCurve> curves;
  std::vector<BoundaryPatch> patches;  // empty for planar (2D) meshes
  int num_feature_edges = 0;

  int count(VertexKind k) const;
};

Status classify_boundary(const Mesh& mesh, const ClassifyOptions& options,
                         BoundaryClassification* out);

}  // namespace tmop

#endif  // TMOP_GEOMETRY_BOUNDARY_CLASSIFICATION_H_
