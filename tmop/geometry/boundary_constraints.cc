#include "tmop/geometry/boundary_constraints.h"

#include <cmath>
#include <sstream>

#include "tmop/element/cell_type.h"
#include "tmop/geometry/geometry_source.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/polyline_manifold.h"
#include "tmop/geometry/projected_curve_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"
#include "tmop/geometry/vec3.h"

namespace tmop {
namespace {

// The patch's triangles on a compact copy of their vertices (the patch owns its geometry).
std::unique_ptr<GeometryManifold> patch_manifold(const Mesh& mesh, const BoundaryPatch& patch,
                                                 std::vector<std::int32_t>* local) {
  if (patch.planar) return std::make_unique<PlaneManifold>(patch.point, patch.normal);
  std::vector<double> vertices;
  std::vector<std::int32_t> triangles;
  std::vector<std::int32_t> touched;
  for (const auto& t : patch.triangles) {
    for (std::int32_t v : t) {
      if ((*local)[v] < 0) {
        (*local)[v] = static_cast<std::int32_t>(vertices.size() / 3);
        vertices.insert(vertices.end(), mesh.vertex(v), mesh.vertex(v) + 3);
        touched.push_back(v);
      }
      triangles.push_back((*local)[v]);
    }
  }
  for (std::int32_t v : touched) (*local)[v] = -1;
  return std::make_unique<TriangleSurfaceManifold>(std::move(vertices), triangles,
                                                   TriangleSurfaceManifold::Shape::kSmooth);
}

}  // namespace

// Per cell of a surface mesh and corner: whether to flip the normal of the cell's patch there.
// The patch normal is oriented like the vote of the patch's cells around the vertex, each
// counted by its geometric (right-hand) normal times its parity, and then turned by the cell's
// own parity, so a surface a generator oriented the other way is not taken for inverted. Only
// the cell's own patch votes: at a sharp crease (t3's surfaces meet at up to 139 degrees between
// consistently ordered cells) the other side's cells would outvote it. A fold sharper than the
// feature angle therefore reads as a crease (like a blade's trailing edge), and the folded cells
// as valid; a user geometry's normals see it (docs/geometry.md).
void BoundaryConstraints::orient_cell_normals(const Mesh& mesh, BoundaryConstraints* bc) {
  const BoundaryClassification& c = bc->classification_;
  const int nc = mesh.num_cells(), nv = mesh.num_vertices();
  bc->cell_flip_.assign(nc, 0);
  if (c.cell_patch.size() != static_cast<std::size_t>(nc) ||
      c.cell_parity.size() != static_cast<std::size_t>(nc))
    return;
  auto corners = [&](int cell) { return cell_info(mesh.cell_type(cell)).num_corners; };
  std::vector<double> normal(3 * static_cast<std::size_t>(nc), 0.0);
  std::vector<int> offsets(nv + 1, 0);
  for (int k = 0; k < nc; ++k) {
    if (c.cell_patch[k] < 0) continue;
    const std::int32_t* x = mesh.cell(k);
    const int m = corners(k);
    double d1[3], d2[3];
    vec3::sub(mesh.vertex(x[m == 4 ? 2 : 1]), mesh.vertex(x[0]), d1);
    vec3::sub(mesh.vertex(x[m == 4 ? 3 : 2]), mesh.vertex(x[m == 4 ? 1 : 0]), d2);
    vec3::cross(d1, d2, &normal[3 * k]);
    for (int i = 0; i < m; ++i) ++offsets[x[i] + 1];
  }
  for (int v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  std::vector<std::int32_t> around(offsets[nv]);
  {
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int k = 0; k < nc; ++k) {
      if (c.cell_patch[k] < 0) continue;
      for (int i = 0; i < corners(k); ++i) around[fill[mesh.cell(k)[i]]++] = k;
    }
  }
  for (int k = 0; k < nc; ++k) {
    if (c.cell_patch[k] < 0) continue;
    const GeometryManifold& g = *bc->manifolds_[bc->first_patch_ + c.cell_patch[k]];
    for (int i = 0; i < corners(k); ++i) {
      const std::int32_t v = mesh.cell(k)[i];
      double vote[3] = {0, 0, 0};
      for (int j = offsets[v]; j < offsets[v + 1]; ++j) {
        const std::int32_t t = around[j];
        if (c.cell_patch[t] != c.cell_patch[k]) continue;
        for (int a = 0; a < 3; ++a) vote[a] += c.cell_parity[t] * normal[3 * t + a];
      }
      double n[3];
      if (g.Normal(mesh.vertex(v), n) && vec3::dot(n, vote) * c.cell_parity[k] < 0)
        bc->cell_flip_[k] |= std::uint8_t(1u << i);
    }
  }
}

BoundaryConstraints::~BoundaryConstraints() = default;

Status BoundaryConstraints::Build(const Mesh& mesh, const BoundaryOptions& options,
                                  std::unique_ptr<BoundaryConstraints>* out) {
  std::unique_ptr<BoundaryConstraints> bc(new BoundaryConstraints());
  GeometrySource source;
  Status s = load_geometry_source(options.geometry, &source, options.geometry_frame);
  if (!s.ok()) return s;
  const int dim = mesh.dim();
  const int space = mesh.space_dim;
  const bool surface_mesh = dim == 2 && space == 3;
  ClassifyOptions classify;
  classify.feature_angle_deg = options.feature_angle_deg;
  // A surface mesh on a smooth analytic surface has no feature edges of its own: the angles
  // between its facets are discretisation (a coarse or perturbed sphere has facets meeting at
  // more than 30 degrees), and fixing them as corners would cap its quality. Its open boundary
  // curves, if any, are still curves.
  if (surface_mesh && source.kind == GeometrySourceKind::kAnalytic)
    classify.feature_angle_deg = 179.9;
  classify.boundary_tags = options.boundary_tags;
  s = classify_boundary(mesh, classify, &bc->classification_);
  if (!s.ok()) return s;
  if (source.surface && space != 3) {
    return Status::Failure("geometry '" + options.geometry + "': a 2D mesh has no surfaces");
  }
  const BoundaryClassification& c = bc->classification_;
  const int nv = mesh.num_vertices();
  bc->space_dim_ = space;
  bc->slide_ = options.slide;
  bc->geometry_description_ = source.description;
  bc->original_ = mesh.coords;
  bc->kind_ = c.kind;
  bc->slot_.assign(nv, -1);
  bc->normal_slot_.assign(nv, -1);
  bc->normal_sign_.assign(nv, 1);

  // One manifold per curve, then one per patch, then the user's.
  for (const BoundaryCurve& curve : c.curves) {
    std::vector<double> points;
    auto add = [&](std::int32_t v) {
      points.insert(points.end(), mesh.vertex(v), mesh.vertex(v) + space);
    };
    if (curve.straight) {
      add(curve.vertices.front());
      add(curve.vertices.back());
    } else {
      for (std::int32_t v : curve.vertices) add(v);
    }
    bc->manifolds_.push_back(std::make_unique<PolylineManifold>(space, points, curve.closed));
  }
  const int first_patch = static_cast<int>(bc->manifolds_.size());
  std::vector<std::int32_t> local(nv, -1);
  for (const BoundaryPatch& patch : c.patches) {
    bc->manifolds_.push_back(patch_manifold(mesh, patch, &local));
  }
  int user = -1;
  bc->first_patch_ = first_patch;
  if (source.surface) {
    user = static_cast<int>(bc->manifolds_.size());
    bc->user_slot_ = user;
    bc->manifolds_.push_back(std::move(source.surface));
  }

  for (int v = 0; v < nv; ++v) {
    if (c.kind[v] == VertexKind::kCurve) bc->slot_[v] = c.id[v];
    if (c.kind[v] == VertexKind::kSurface) bc->slot_[v] = first_patch + c.id[v];
    if (c.vertex_patch[v] >= 0) bc->normal_slot_[v] = first_patch + c.vertex_patch[v];
  }

  // User geometry: surface vertices of curved patches that lie on it with their neighbours.
  if (user >= 0) {
    double edge_sum = 0;
    long edge_count = 0;
    for (const BoundaryPatch& patch : c.patches) {
      for (const auto& t : patch.triangles) {
        for (int k = 0; k < 3; ++k) {
          double e[3];
          vec3::sub(mesh.vertex(t[k]), mesh.vertex(t[(k + 1) % 3]), e);
          edge_sum += vec3::norm(e);
          ++edge_count;
        }
      }
    }
    const double tol = options.on_geometry_tolerance * edge_sum / std::max(edge_count, 1L);
    const GeometryManifold& g = *bc->manifolds_[user];
    std::vector<char> on(nv, 0), rejected(nv, 0);
    for (const BoundaryPatch& patch : c.patches) {
      if (patch.planar) continue;
      for (const auto& t : patch.triangles) {
        bool all = true;
        for (std::int32_t v : t) {
          if (on[v] == 0) on[v] = g.Distance(mesh.vertex(v)) <= tol ? 1 : 2;
          all = all && on[v] == 1;
        }
        if (!all) {
          for (std::int32_t v : t) rejected[v] = 1;
        }
      }
    }
    for (int v = 0; v < nv; ++v) {
      if (c.kind[v] != VertexKind::kSurface || c.patches[c.id[v]].planar) continue;
      if (on[v] == 1 && !rejected[v]) {
        bc->slot_[v] = user;
        bc->normal_slot_[v] = user;
        ++bc->num_on_user_geometry_;
      }
    }
    // Curves on an analytic geometry (an open cap's rim) that border only curved patches: their
    // polylines projected onto it, so their vertices stay on it instead of on the chords. A
    // curve shared with a planar patch keeps its polyline (the projection could leave the
    // plane).
    if (source.kind == GeometrySourceKind::kAnalytic && space == 3) {
      const int nc = static_cast<int>(c.curves.size());
      std::vector<char> eligible(nc, 1);
      for (const BoundaryPatch& patch : c.patches) {
        for (const auto& t : patch.triangles) {
          for (int k = 0; k < 3; ++k) {
            const std::int32_t a = t[k], b = t[(k + 1) % 3];
            const bool ca = c.kind[a] == VertexKind::kCurve, cb = c.kind[b] == VertexKind::kCurve;
            if (!ca && !cb) continue;
            const int curve = ca ? c.id[a] : c.id[b];
            const bool other = ca ? (cb ? c.id[b] == curve : c.kind[b] == VertexKind::kFixed)
                                  : c.kind[a] == VertexKind::kFixed;
            if (other && patch.planar) eligible[curve] = 0;
          }
        }
      }
      for (int k = 0; k < nc; ++k) {
        const BoundaryCurve& curve = c.curves[k];
        if (!eligible[k] || curve.vertices.size() < (curve.closed ? 3u : 2u)) continue;
        bool all_on = true;
        std::vector<double> points;
        for (std::int32_t v : curve.vertices) {
          all_on = all_on && g.Distance(mesh.vertex(v)) <= tol;
          points.insert(points.end(), mesh.vertex(v), mesh.vertex(v) + 3);
        }
        if (!all_on) continue;
        bc->manifolds_[k] = std::make_unique<ProjectedCurveManifold>(points, curve.closed, &g);
        for (std::int32_t v : curve.vertices)
          bc->num_on_user_geometry_ += c.kind[v] == VertexKind::kCurve;
      }
    }
  }

  if (!options.slide) {
    for (int v = 0; v < nv; ++v) {
      const bool keep = surface_mesh && c.kind[v] == VertexKind::kSurface;
      if (c.kind[v] != VertexKind::kInterior && !keep) {
        bc->kind_[v] = VertexKind::kFixed;
        bc->slot_[v] = -1;
      }
    }
  }
  for (int v = 0; v < nv; ++v) {
    if (bc->kind_[v] == VertexKind::kFixed) bc->slot_[v] = -1;
  }

  // Orient the geometry's normals like the mesh: compare with the area-weighted normal of the
  // vertex's patch triangles (analytic and file geometries have their own orientation).
  if (space == 3) {
    std::vector<double> mesh_normal(3 * static_cast<std::size_t>(nv), 0.0);
    for (const BoundaryPatch& patch : c.patches) {
      for (const auto& t : patch.triangles) {
        double e1[3], e2[3], n[3];
        vec3::sub(mesh.vertex(t[1]), mesh.vertex(t[0]), e1);
        vec3::sub(mesh.vertex(t[2]), mesh.vertex(t[0]), e2);
        vec3::cross(e1, e2, n);
        for (std::int32_t v : t) {
          for (int i = 0; i < 3; ++i) mesh_normal[3 * v + i] += n[i];
        }
      }
    }
    for (int v = 0; v < nv; ++v) {
      const int slot = bc->normal_slot_[v];
      double n[3];
      if (slot < 0 || !bc->manifolds_[slot]->Normal(mesh.vertex(v), n)) continue;
      if (vec3::dot(n, &mesh_normal[3 * v]) < 0) bc->normal_sign_[v] = -1;
    }
  }
  if (surface_mesh) orient_cell_normals(mesh, bc.get());
  *out = std::move(bc);
  return Status::Ok();
}

std::vector<char> BoundaryConstraints::fixed_flags() const {
  std::vector<char> flags(kind_.size());
  for (std::size_t v = 0; v < kind_.size(); ++v) flags[v] = kind_[v] == VertexKind::kFixed;
  return flags;
}

const ceres::Manifold* BoundaryConstraints::manifold(int vertex) const { return geometry(vertex); }

const GeometryManifold* BoundaryConstraints::geometry(int vertex) const {
  const int slot = slot_[vertex];
  return slot < 0 ? nullptr : manifolds_[slot].get();
}

bool BoundaryConstraints::normal(int vertex, const double* x, double* n) const {
  const int slot = normal_slot_[vertex];
  if (slot < 0 || space_dim_ != 3) return false;
  if (!manifolds_[slot]->Normal(x, n)) return false;
  if (normal_sign_[vertex] < 0) {
    for (int i = 0; i < 3; ++i) n[i] = -n[i];
  }
  return true;
}

bool BoundaryConstraints::cell_normal(int cell, int corner, const std::int32_t* cell_nodes,
                                      const double* x, double* n) const {
  const int vertex = cell_nodes[corner];
  const std::vector<std::int32_t>& patch_of = classification_.cell_patch;
  if (space_dim_ != 3 || static_cast<std::size_t>(cell) >= patch_of.size() || patch_of[cell] < 0 ||
      (user_slot_ >= 0 && normal_slot_[vertex] == user_slot_))
    return normal(vertex, x, n);
  if (!manifolds_[first_patch_ + patch_of[cell]]->Normal(x, n)) return false;
  if (cell_flip_[cell] & (1u << corner)) {
    for (int i = 0; i < 3; ++i) n[i] = -n[i];
  }
  return true;
}

double BoundaryConstraints::distance(int vertex, const double* x) const {
  if (const GeometryManifold* g = geometry(vertex)) return g->Distance(x);
  if (kind_[vertex] != VertexKind::kFixed) return 0;
  double s = 0;
  for (int i = 0; i < space_dim_; ++i) {
    const double d = x[i] - original_[static_cast<std::size_t>(vertex) * space_dim_ + i];
    s += d * d;
  }
  return std::sqrt(s);
}

int BoundaryConstraints::count(VertexKind kind) const {
  int n = 0;
  for (VertexKind k : kind_) n += k == kind;
  return n;
}

std::string BoundaryConstraints::summary() const {
  int planar = 0;
  for (const BoundaryPatch& p : classification_.patches) planar += p.planar;
  std::ostringstream os;
  os << (slide_ ? "slide: " : "fixed boundary: ") << count(VertexKind::kFixed) << " fixed, "
     << count(VertexKind::kCurve) << " curve, " << count(VertexKind::kSurface) << " surface, "
     << count(VertexKind::kInterior) << " interior; " << classification_.curves.size()
     << " curves, " << classification_.patches.size() << " patches (" << planar
     << " planar); geometry: " << geometry_description_;
  if (num_on_user_geometry_ > 0) os << " (" << num_on_user_geometry_ << " vertices)";
  return os.str();
}

}  // namespace tmop
