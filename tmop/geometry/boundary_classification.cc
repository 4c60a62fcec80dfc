#include "tmop/geometry/boundary_classification.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <utility>

#include "tmop/geometry/vec3.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

// A boundary facet of a volume mesh or a cell of a surface mesh: the pieces patches are made
// of. mid[j] is the node in the middle of the edge (corners[j], corners[j + 1]), -1 if linear.
struct Face {
  std::int32_t tag = 0;  // the tagged lower-dimensional cell on this facet (0: none)
  int num_corners = 0;
  std::int32_t corners[4] = {-1, -1, -1, -1};
  std::int32_t mid[4] = {-1, -1, -1, -1};
  std::int32_t centre = -1;
  std::int32_t region = 0;
  std::int32_t cell = -1;  // surface meshes: the cell itself
  double normal[3] = {0, 0, 0};
};

// Two faces of a surface mesh sharing an edge that no other face has; `flip`: their corners run
// along it in the same direction (opposite orders).
struct FacePair {
  std::int32_t a, b;
  bool flip;
};

// Orientation components of a surface mesh's cells and each cell's parity in its component,
// by a breadth-first walk across FacePairs (the first cell reached in a component gets +1; a
// non-orientable component keeps the first parity each cell is given).
void orient_surface_cells(const Mesh& mesh, const std::vector<Face>& faces,
                          const std::vector<FacePair>& pairs, BoundaryClassification* out) {
  const int nf = static_cast<int>(faces.size());
  std::vector<int> offsets(nf + 1, 0);
  for (const FacePair& p : pairs) {
    ++offsets[p.a + 1];
    ++offsets[p.b + 1];
  }
  for (int i = 0; i < nf; ++i) offsets[i + 1] += offsets[i];
  std::vector<std::pair<std::int32_t, bool>> next(offsets[nf]);
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (const FacePair& p : pairs) {
      next[fill[p.a]++] = {p.b, p.flip};
      next[fill[p.b]++] = {p.a, p.flip};
    }
  }
  std::vector<std::int32_t> component(nf, -1);
  std::vector<std::int8_t> parity(nf, 0);
  std::vector<std::int32_t> queue;
  int count = 0;
  for (int start = 0; start < nf; ++start) {
    if (component[start] >= 0) continue;
    component[start] = count;
    parity[start] = 1;
    queue.assign(1, start);
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::int32_t f = queue[q];
      for (int k = offsets[f]; k < offsets[f + 1]; ++k) {
        const std::int32_t g = next[k].first;
        if (component[g] >= 0) continue;
        component[g] = count;
        parity[g] = static_cast<std::int8_t>(next[k].second ? -parity[f] : parity[f]);
        queue.push_back(g);
      }
    }
    ++count;
  }
  out->cell_component.assign(mesh.num_cells(), -1);
  out->cell_parity.assign(mesh.num_cells(), 0);
  for (int i = 0; i < nf; ++i) {
    if (faces[i].cell < 0) continue;
    out->cell_component[faces[i].cell] = component[i];
    out->cell_parity[faces[i].cell] = parity[i];
  }
}

// An edge of the feature graph (boundary edge of a planar mesh, feature edge otherwise).
struct FeatureEdge {
  std::int32_t a, b, mid, region, tag;
};

// Tags of the lower-dimensional cells of dimension `dim`, by sorted corner list, for lookups
// of facets. Entity tag first (the CAD entity), region tag when there is none.
class FacetTags {
 public:
  FacetTags(const Mesh& mesh, int dim) {
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const CellInfo& info = cell_info(mesh.cell_type(c));
      if (info.dim != dim) continue;
      std::int32_t tag = c < static_cast<int>(mesh.cell_entity.size()) ? mesh.cell_entity[c] : 0;
      if (tag == 0 && c < static_cast<int>(mesh.cell_region.size())) tag = mesh.cell_region[c];
      if (tag != 0) entries_.push_back({key(mesh.cell(c), info.num_corners), tag});
    }
    std::sort(entries_.begin(), entries_.end());
  }
  std::int32_t find(const std::int32_t* corners, int n) const {
    const Key k = key(corners, n);
    auto it = std::lower_bound(entries_.begin(), entries_.end(),
                               std::make_pair(k, std::numeric_limits<std::int32_t>::min()));
    return it != entries_.end() && it->first == k ? it->second : 0;
  }

 private:
  using Key = std::array<std::int32_t, 4>;
  static Key key(const std::int32_t* corners, int n) {
    Key k = {-1, -1, -1, -1};
    std::copy(corners, corners + n, k.begin());
    // Insertion sort of at most 4 entries (std::sort trips GCC 12's -Warray-bounds here).
    for (int i = 1; i < n; ++i) {
      for (int j = i; j > 0 && k[j - 1] > k[j]; --j) std::swap(k[j - 1], k[j]);
    }
    return k;
  }
  std::vector<std::pair<Key, std::int32_t>> entries_;
};

std::int32_t region_of(const Mesh& mesh, int cell) {
  return cell < static_cast<int>(mesh.cell_region.size()) ? mesh.cell_region[cell] : 0;
}

// The (region, entity) pair of a cell as one key (topology.h's same_region).
std::int64_t region_key(const Mesh& mesh, int cell) {
  const std::int64_t e =
      cell < static_cast<int>(mesh.cell_entity.size()) ? mesh.cell_entity[cell] : 0;
  return (std::int64_t(region_of(mesh, cell)) << 32) ^ (e & 0xffffffff);
}

// Region values of interface facets: below any file tag, one per pair of regions.
constexpr std::int32_t kInterfaceRegionBase = std::numeric_limits<std::int32_t>::min() / 2;

// Extra nodes of quadratic facet `local` of a cell: mid-edge nodes of its edges (in the facet's
// corner order) and, for hex27, the node in the middle of the face.
void facet_extra_nodes(CellType type, int local, const std::int32_t* nodes, std::int32_t* mid,
                       std::int32_t* centre) {
  const CellInfo& info = cell_info(type);
  const CellFacet& facet = info.facets[local];
  const int edges = facet.num_corners == 2 ? 1 : facet.num_corners;
  for (int j = 0; j < 4; ++j) mid[j] = -1;
  *centre = -1;
  if (info.order != 2) return;
  for (int j = 0; j < edges; ++j) {
    const int a = facet.corners[j], b = facet.corners[(j + 1) % facet.num_corners];
    for (int e = 0; e < info.num_edges; ++e) {
      if ((info.edges[e][0] == a && info.edges[e][1] == b) ||
          (info.edges[e][0] == b && info.edges[e][1] == a)) {
        mid[j] = nodes[info.num_corners + e];
      }
    }
  }
  // hex27's and wedge18's face nodes (cell_type.h's facet_nodes).
  if (facet_node(info, local) >= 0) *centre = nodes[facet_node(info, local)];
}

void face_normal(const Mesh& mesh, Face* f) {
  const double* p[4];
  for (int k = 0; k < f->num_corners; ++k) p[k] = mesh.vertex(f->corners[k]);
  double e1[3], e2[3];
  if (f->num_corners == 3) {
    vec3::sub(p[1], p[0], e1);
    vec3::sub(p[2], p[0], e2);
  } else {  // the diagonals' cross product is twice the quad's vector area
    vec3::sub(p[2], p[0], e1);
    vec3::sub(p[3], p[1], e2);
  }
  vec3::cross(e1, e2, f->normal);
  vec3::normalize(f->normal);
}

// Splits a (possibly quadratic) face into triangles with the face's orientation.
void triangulate(const Face& f, std::vector<std::array<std::int32_t, 3>>* out) {
  const std::int32_t* c = f.corners;
  const std::int32_t* m = f.mid;
  const bool quadratic = m[0] >= 0;
  if (f.num_corners == 3) {
    if (!quadratic) {
      out->push_back({c[0], c[1], c[2]});
    } else {
      out->push_back({c[0], m[0], m[2]});
      out->push_back({m[0], c[1], m[1]});
      out->push_back({m[2], m[1], c[2]});
      out->push_back({m[0], m[1], m[2]});
    }
    return;
  }
  auto quad = [&](std::int32_t a, std::int32_t b, std::int32_t cc, std::int32_t d) {
    out->push_back({a, b, cc});
    out->push_back({a, cc, d});
  };
  if (!quadratic || f.centre < 0) {
    quad(c[0], c[1], c[2], c[3]);
  } else {
    const std::int32_t o = f.centre;
    quad(c[0], m[0], o, m[3]);
    quad(m[0], c[1], m[1], o);
    quad(o, m[1], c[2], m[2]);
    quad(m[3], o, m[2], c[3]);
  }
}

int find_root(std::vector<int>* parent, int i) {
  while ((*parent)[i] != i) {
    (*parent)[i] = (*parent)[(*parent)[i]];
    i = (*parent)[i];
  }
  return i;
}

// Largest distance of the points from the line through a and b (dim 2 or 3), and |b - a|.
double line_deviation(const Mesh& mesh, const std::vector<std::int32_t>& pts, double* chord) {
  const int dim = mesh.space_dim;
  const double* a = mesh.vertex(pts.front());
  const double* b = mesh.vertex(pts.back());
  double d[3] = {0, 0, 0};
  for (int i = 0; i < dim; ++i) d[i] = b[i] - a[i];
  *chord = vec3::normalize(d);
  double worst = 0;
  for (std::int32_t v : pts) {
    double r[3] = {0, 0, 0};
    for (int i = 0; i < dim; ++i) r[i] = mesh.vertex(v)[i] - a[i];
    const double along = vec3::dot(r, d);
    for (int i = 0; i < 3; ++i) r[i] -= along * d[i];
    worst = std::max(worst, vec3::norm(r));
  }
  return worst;
}

void fit_plane(const Mesh& mesh, BoundaryPatch* patch, std::vector<int>* stamp, int mark) {
  std::vector<std::int32_t> verts;
  for (const auto& t : patch->triangles) {
    for (std::int32_t v : t) {
      if ((*stamp)[v] != mark) {
        (*stamp)[v] = mark;
        verts.push_back(v);
      }
    }
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), lo, hi;
  lo.setConstant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (std::int32_t v : verts) {
    const Eigen::Vector3d p(mesh.vertex(v));
    centroid += p;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  centroid /= static_cast<double>(verts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::int32_t v : verts) {
    const Eigen::Vector3d r = Eigen::Vector3d(mesh.vertex(v)) - centroid;
    cov += r * r.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d n = eig.eigenvectors().col(0);  // smallest eigenvalue: the plane's normal
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  for (const auto& t : patch->triangles) {
    const Eigen::Vector3d a(mesh.vertex(t[0])), b(mesh.vertex(t[1])), c(mesh.vertex(t[2]));
    area += (b - a).cross(c - a);
  }
  if (n.dot(area) < 0) n = -n;
  double worst = 0;
  for (std::int32_t v : verts) {
    worst = std::max(worst, std::fabs((Eigen::Vector3d(mesh.vertex(v)) - centroid).dot(n)));
  }
  for (int i = 0; i < 3; ++i) {
    patch->point[i] = centroid[i];
    patch->normal[i] = n[i];
  }
  patch->planar = worst <= 1e-10 * (hi - lo).norm();
}

}  // namespace

const char* vertex_kind_name(VertexKind kind) {
  switch (kind) {
    case VertexKind::kInterior:
      return "interior";
    case VertexKind::kFixed:
      return "fixed";
    case VertexKind::kCurve:
      return "curve";
    case VertexKind::kSurface:
      return "surface";
  }
  return "?";
}

int BoundaryClassification::count(VertexKind k) const {
  return static_cast<int>(std::count(kind.begin(), kind.end(), k));
}

Status classify_boundary(const Mesh& mesh, const ClassifyOptions& options,
                         BoundaryClassification* out) {
  *out = BoundaryClassification();
  const int dim = mesh.dim();
  const int space = mesh.space_dim;
  if (mesh.num_elements() == 0) return Status::Failure("classify_boundary: mesh has no elements");
  if (dim < 2) return Status::Failure("classify_boundary: 1D meshes have no boundary geometry");
  if (dim == 3 && space != 3) return Status::Failure("classify_boundary: 3D cells in 2D space");
  if (!(options.feature_angle_deg > 0 && options.feature_angle_deg < 180)) {
    return Status::Failure("classify_boundary: feature angle must be in (0, 180) degrees");
  }
  const double cos_feature = std::cos(options.feature_angle_deg * M_PI / 180);
  const int nv = mesh.num_vertices();

  // 1. Faces (volume and surface meshes) or boundary edges (planar meshes).
  std::vector<Face> faces;
  std::vector<FeatureEdge> features;
  std::unique_ptr<FacetTags> tags;
  if (options.boundary_tags) tags = std::make_unique<FacetTags>(mesh, dim - 1);
  if (dim == 3) {
    for (const BoundaryFacet& bf : boundary_facets(mesh)) {
      Face f;
      if (tags) f.tag = tags->find(bf.corners, bf.num_corners);
      f.num_corners = bf.num_corners;
      std::copy(bf.corners, bf.corners + 4, f.corners);
      facet_extra_nodes(mesh.cell_type(bf.cell), bf.local, mesh.cell(bf.cell), f.mid, &f.centre);
      f.region = region_of(mesh, bf.cell);
      faces.push_back(f);
    }
    // Region interfaces are boundaries of their regions: their facets (from the first cell's
    // side) form patches of their own, one region value per pair of regions, and the edges
    // where they meet the outer boundary (three facets) become feature curves.
    if (options.region_interfaces) {
      std::map<std::pair<std::int64_t, std::int64_t>, std::int32_t> pair_region;
      for (const InteriorFacet& inf : region_interface_facets(mesh)) {
        const int c = inf.cell[0];
        const CellFacet& facet = cell_info(mesh.cell_type(c)).facets[inf.local[0]];
        Face f;
        f.num_corners = facet.num_corners;
        for (int k = 0; k < 4; ++k)
          f.corners[k] = k < facet.num_corners ? mesh.cell(c)[facet.corners[k]] : -1;
        facet_extra_nodes(mesh.cell_type(c), inf.local[0], mesh.cell(c), f.mid, &f.centre);
        const std::int64_t a = region_key(mesh, inf.cell[0]), b = region_key(mesh, inf.cell[1]);
        const auto key = std::make_pair(std::min(a, b), std::max(a, b));
        auto it = pair_region.find(key);
        if (it == pair_region.end())
          it = pair_region.emplace(key, kInterfaceRegionBase - std::int32_t(pair_region.size()))
                   .first;
        f.region = it->second;
        faces.push_back(f);
      }
    }
  } else if (space == 3) {
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (!mesh.is_element(c, dim)) continue;
      const CellInfo& info = cell_info(mesh.cell_type(c));
      const std::int32_t* nodes = mesh.cell(c);
      Face f;
      f.num_corners = info.num_corners;
      for (int k = 0; k < info.num_corners; ++k) {
        f.corners[k] = nodes[k];
        if (info.order == 2) f.mid[k] = nodes[info.num_corners + k];
      }
      if (mesh.cell_type(c) == CellType::kQuad9) f.centre = nodes[8];
      f.region = region_of(mesh, c);
      f.cell = c;
      faces.push_back(f);
    }
  } else {
    for (const BoundaryFacet& bf : boundary_facets(mesh)) {
      std::int32_t mid[4], centre;
      facet_extra_nodes(mesh.cell_type(bf.cell), bf.local, mesh.cell(bf.cell), mid, &centre);
      const std::int32_t tag = tags ? tags->find(bf.corners, 2) : 0;
      features.push_back({bf.corners[0], bf.corners[1], mid[0], region_of(mesh, bf.cell), tag});
    }
    if (options.region_interfaces) {
      for (const InteriorFacet& inf : region_interface_facets(mesh)) {
        const int c = inf.cell[0];
        const CellFacet& facet = cell_info(mesh.cell_type(c)).facets[inf.local[0]];
        std::int32_t mid[4], centre;
        facet_extra_nodes(mesh.cell_type(c), inf.local[0], mesh.cell(c), mid, &centre);
        features.push_back({mesh.cell(c)[facet.corners[0]], mesh.cell(c)[facet.corners[1]], mid[0],
                            kInterfaceRegionBase, 0});
      }
    }
  }
  for (Face& f : faces) face_normal(mesh, &f);

  // 2. Feature edges of the faces, and patches: faces joined across the other edges.
  const int nf = static_cast<int>(faces.size());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<FacePair> pairs;  // surface meshes: faces sharing an edge of exactly two faces
  {
    struct EdgeRecord {
      std::int32_t lo, hi, face, j;
      bool operator<(const EdgeRecord& o) const {
        return lo != o.lo ? lo < o.lo : (hi != o.hi ? hi < o.hi : face < o.face);
      }
    };
    std::vector<EdgeRecord> records;
    records.reserve(4 * faces.size());
    for (int i = 0; i < nf; ++i) {
      const Face& f = faces[i];
      for (int j = 0; j < f.num_corners; ++j) {
        const std::int32_t a = f.corners[j], b = f.corners[(j + 1) % f.num_corners];
        records.push_back({std::min(a, b), std::max(a, b), i, j});
      }
    }
    std::sort(records.begin(), records.end());
    const bool orient = dim == 2 && space == 3;
    for (std::size_t i = 0; i < records.size();) {
      std::size_t e = i;
      while (e < records.size() && records[e].lo == records[i].lo &&
             records[e].hi == records[i].hi) {
        ++e;
      }
      bool feature = e - i != 2;
      if (!feature) {
        const Face& f = faces[records[i].face];
        const Face& g = faces[records[i + 1].face];
        // Consistently oriented neighbours run along the shared edge in opposite directions;
        // surface meshes may not be consistent, so compare the normals up to that flip.
        const bool same_direction = f.corners[records[i].j] == g.corners[records[i + 1].j];
        if (orient) pairs.push_back({records[i].face, records[i + 1].face, same_direction});
        const double c = vec3::dot(f.normal, g.normal) * (same_direction ? -1 : 1);
        feature = c < cos_feature || (options.region_interfaces && f.region != g.region) ||
                  (f.tag != 0 && g.tag != 0 && f.tag != g.tag);
      }
      if (feature) {
        const EdgeRecord& r = records[i];
        const Face& f = faces[r.face];
        features.push_back(
            {f.corners[r.j], f.corners[(r.j + 1) % f.num_corners], f.mid[r.j], f.region, f.tag});
      } else {
        const int a = find_root(&parent, records[i].face);
        const int b = find_root(&parent, records[i + 1].face);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
      }
      i = e;
    }
  }
  out->num_feature_edges = static_cast<int>(features.size());

  // 3. Corners: feature-graph degree other than 2, a sharp turn, or (planar meshes) a change
  // of region along the boundary.
  const int ne = static_cast<int>(features.size());
  std::vector<std::int64_t> offsets(nv + 1, 0);
  for (const FeatureEdge& e : features) {
    ++offsets[e.a + 1];
    ++offsets[e.b + 1];
  }
  for (int v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  std::vector<std::int32_t> incident(offsets[nv]);
  {
    std::vector<std::int64_t> fill(offsets.begin(), offsets.end() - 1);
    for (int i = 0; i < ne; ++i) {
      incident[fill[features[i].a]++] = i;
      incident[fill[features[i].b]++] = i;
    }
  }
  out->kind.assign(nv, VertexKind::kInterior);
  out->id.assign(nv, -1);
  out->vertex_patch.assign(nv, -1);
  std::vector<char> corner(nv, 0);
  for (int v = 0; v < nv; ++v) {
    const std::int64_t degree = offsets[v + 1] - offsets[v];
    if (degree == 0) continue;
    bool is_corner = degree != 2;
    if (!is_corner) {
      const FeatureEdge& e1 = features[incident[offsets[v]]];
      const FeatureEdge& e2 = features[incident[offsets[v] + 1]];
      const std::int32_t p = e1.a == v ? e1.b : e1.a;
      const std::int32_t q = e2.a == v ? e2.b : e2.a;
      double in[3] = {0, 0, 0}, outv[3] = {0, 0, 0};
      for (int i = 0; i < space; ++i) {
        in[i] = mesh.vertex(v)[i] - mesh.vertex(p)[i];
        outv[i] = mesh.vertex(q)[i] - mesh.vertex(v)[i];
      }
      vec3::normalize(in);
      vec3::normalize(outv);
      is_corner = vec3::dot(in, outv) < cos_feature ||
                  (dim == 2 && space == 2 && options.region_interfaces && e1.region != e2.region) ||
                  (dim == 2 && space == 2 && e1.tag != 0 && e2.tag != 0 && e1.tag != e2.tag);
    }
    corner[v] = is_corner;
    if (is_corner) out->kind[v] = VertexKind::kFixed;
  }

  // 4. Curves: walk the feature graph from every corner to the next corner; what is left are
  // closed loops without corners.
  std::vector<char> used(ne, 0);
  auto trace = [&](std::int32_t start, int first_edge, bool closed) {
    BoundaryCurve curve;
    curve.closed = closed;
    const int id = static_cast<int>(out->curves.size());
    curve.vertices.push_back(start);
    std::int32_t v = start;
    int e = first_edge;
    while (true) {
      used[e] = 1;
      const FeatureEdge& fe = features[e];
      const std::int32_t next = fe.a == v ? fe.b : fe.a;
      if (fe.mid >= 0) curve.vertices.push_back(fe.mid);
      if (next == start && closed) break;
      curve.vertices.push_back(next);
      if (corner[next]) break;
      // A non-corner has exactly two feature edges: continue through the other one.
      const int e1 = incident[offsets[next]], e2 = incident[offsets[next] + 1];
      e = e1 == e ? e2 : e1;
      v = next;
      if (used[e]) break;
    }
    for (std::int32_t u : curve.vertices) {
      if (!corner[u]) {
        out->kind[u] = VertexKind::kCurve;
        out->id[u] = id;
      }
    }
    if (!closed && curve.vertices.size() >= 2) {
      double chord;
      const double dev = line_deviation(mesh, curve.vertices, &chord);
      curve.straight = chord > 0 && dev <= 1e-10 * chord;
    }
    out->curves.push_back(std::move(curve));
  };
  for (int v = 0; v < nv; ++v) {
    if (!corner[v]) continue;
    for (std::int64_t k = offsets[v]; k < offsets[v + 1]; ++k) {
      if (!used[incident[k]]) trace(v, incident[k], false);
    }
  }
  for (int e = 0; e < ne; ++e) {
    if (!used[e]) trace(features[e].a, e, true);
  }

  // 5. Patches: union-find components of the faces, with their triangles; every node of a face
  // that is neither a corner nor on a curve slides on the face's patch.
  std::vector<int> patch_of_root(nf, -1);
  if (dim == 2 && space == 3) orient_surface_cells(mesh, faces, pairs, out);
  if (dim == 2 && space == 3) out->cell_patch.assign(mesh.num_cells(), -1);
  for (int i = 0; i < nf; ++i) {
    const int root = find_root(&parent, i);
    if (patch_of_root[root] < 0) {
      patch_of_root[root] = static_cast<int>(out->patches.size());
      out->patches.emplace_back();
    }
    const int patch = patch_of_root[root];
    const Face& f = faces[i];
    auto& triangles = out->patches[patch].triangles;
    const std::size_t first = triangles.size();
    triangulate(f, &triangles);
    if (f.cell >= 0) {
      out->cell_patch[f.cell] = patch;
      // A patch's triangles run one way: those of cells ordered the other way are turned.
      if (out->cell_parity[f.cell] < 0)
        for (std::size_t t = first; t < triangles.size(); ++t)
          std::swap(triangles[t][1], triangles[t][2]);
    }
    auto assign = [&](std::int32_t v) {
      if (v < 0) return;
      if (out->vertex_patch[v] < 0) out->vertex_patch[v] = patch;
      if (out->kind[v] == VertexKind::kInterior) {
        out->kind[v] = VertexKind::kSurface;
        out->id[v] = patch;
      }
    };
    for (int k = 0; k < f.num_corners; ++k) {
      assign(f.corners[k]);
      assign(f.mid[k]);
    }
    assign(f.centre);
  }
  std::vector<int> stamp(nv, -1);
  for (int p = 0; p < static_cast<int>(out->patches.size()); ++p) {
    fit_plane(mesh, &out->patches[p], &stamp, p);
  }
  return Status::Ok();
}

}  // namespace tmop
