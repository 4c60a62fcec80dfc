#include "tmop/recipes/quadratic_shape.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/geometry/geometry_manifold.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/quadratic_curving.h"
#include "tmop/recipes/quadratic_guard.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Passes of the step-back repair (quadratic_guard.h) before a round's result is given up.
constexpr int kMaxStepBackPasses = 64;

bool is_quadratic_element(const Mesh& mesh, int c, int d) {
  return mesh.is_element(c, d) && cell_info(mesh.cell_type(c)).order == 2;
}

bool is_simplex(CellType t) {
  const CellType l = cell_info(t).linear;
  return l == CellType::kTri3 || l == CellType::kTet4;
}

Vec3 point(const Mesh& mesh, const std::vector<double>& coords, int v) {
  Vec3 x(0, 0, 0);
  for (int a = 0; a < mesh.space_dim; ++a)
    x[a] = coords[static_cast<std::size_t>(v) * mesh.space_dim + a];
  return x;
}

void set_point(Mesh* mesh, int v, const Vec3& x) {
  for (int a = 0; a < mesh->space_dim; ++a) mesh->vertex(v)[a] = x[a];
}

bool moved(const Mesh& mesh, const std::vector<double>& original, int v) {
  for (int a = 0; a < mesh.space_dim; ++a)
    if (mesh.vertex(v)[a] != original[static_cast<std::size_t>(v) * mesh.space_dim + a])
      return true;
  return false;
}

// The input offset o of a mid-edge node from its chord's midpoint, turned and scaled as the
// chord a -> b went to a2 -> b2 (the similarity fixing the chord; in 2D z stays 0).
Vec3 carry_offset(const Vec3& a, const Vec3& b, const Vec3& a2, const Vec3& b2, const Vec3& o) {
  const Vec3 c = b - a, c2 = b2 - a2;
  const double l = c.norm(), l2 = c2.norm();
  if (!(l > 0) || !(l2 > 0)) return o;
  const Vec3 u = c / l, u2 = c2 / l2;
  const double cs = u.dot(u2);
  const Vec3 v = u.cross(u2);
  if (cs < -0.999) return o * (l2 / l);  // a reversed edge: an inverted cell, caught later
  // Rodrigues' rotation taking u to u2: x cos + v x x + v (v . x) / (1 + cos).
  const Vec3 r = o * cs + v.cross(o) + v * (v.dot(o) / (1 + cs));
  return r * (l2 / l);
}

// Places every non-corner node of the quadratic elements from the corners in mesh->coords
// (original: the input coordinates). Nodes whose defining corners did not move keep their
// input position bit for bit.
void place_nodes(const std::vector<double>& original, Mesh* mesh, std::vector<char>* placed) {
  const int d = mesh->dim();
  placed->assign(mesh->num_vertices(), 0);
  double N[kMaxCellNodes];
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!is_quadratic_element(*mesh, c, d)) continue;
    const CellType t = mesh->cell_type(c);
    const CellInfo& info = cell_info(t);
    const std::int32_t* nodes = mesh->cell(c);
    const int nc = info.num_corners;
    for (int k = nc; k < info.num_nodes; ++k) {
      const int v = nodes[k];
      if ((*placed)[v]) continue;
      (*placed)[v] = 1;
      const Vec3 m = point(*mesh, original, v);
      if (k < nc + info.num_edges) {
        const int ia = nodes[info.edges[k - nc][0]], ib = nodes[info.edges[k - nc][1]];
        if (!moved(*mesh, original, ia) && !moved(*mesh, original, ib)) continue;
        const Vec3 a = point(*mesh, original, ia), b = point(*mesh, original, ib);
        const Vec3 a2 = point(*mesh, mesh->coords, ia), b2 = point(*mesh, mesh->coords, ib);
        set_point(mesh, v, 0.5 * (a2 + b2) + carry_offset(a, b, a2, b2, m - 0.5 * (a + b)));
      } else {
        // Face and centre nodes: the corners' linear interpolation plus the input offset. Only
        // the corners with a nonzero weight define the node (a face node: its face's corners).
        shape_values(info.linear, reference_node(t, k), N);
        bool any_moved = false;
        Vec3 old_i(0, 0, 0), new_i(0, 0, 0);
        for (int i = 0; i < nc; ++i) {
          if (std::abs(N[i]) < 1e-14) continue;
          any_moved |= moved(*mesh, original, nodes[i]);
          old_i += N[i] * point(*mesh, original, nodes[i]);
          new_i += N[i] * point(*mesh, mesh->coords, nodes[i]);
        }
        if (any_moved) set_point(mesh, v, new_i + (m - old_i));
      }
    }
  }
}

// Sliding non-corner nodes that moved go back onto their curve / surface (the constraints live
// in the geometry's frame).
void project_sliding_nodes(const RecipeGeometry& geometry, const std::vector<double>& original,
                           const std::vector<char>& placed, Mesh* mesh) {
  const BoundaryConstraints& bc = *geometry.constraints;
  const CoordinateFrame& f = geometry.frame;
  const int sd = mesh->space_dim;
  for (int v = 0; v < mesh->num_vertices(); ++v) {
    if (!placed[v] || !moved(*mesh, original, v)) continue;
    const GeometryManifold* g = bc.geometry(v);
    if (!g) continue;
    double x[3] = {0, 0, 0}, y[3] = {0, 0, 0};
    for (int i = 0; i < sd; ++i) {
      double s = 0;
      for (int j = 0; j < sd; ++j) s += f.rotation[3 * i + j] * (mesh->vertex(v)[j] - f.centre[j]);
      x[i] = s / f.length;
    }
    g->Project(x, y);
    for (int j = 0; j < sd; ++j) {
      double s = 0;
      for (int i = 0; i < sd; ++i) s += f.rotation[3 * i + j] * y[i];
      mesh->vertex(v)[j] = s * f.length + f.centre[j];
    }
  }
}

// corner_mesh without the cells flagged in `drop` (empty: none).
Mesh corner_mesh_without(const Mesh& mesh, const std::vector<char>& drop) {
  Mesh out;
  out.space_dim = mesh.space_dim;
  out.plane_z = mesh.plane_z;
  out.coords = mesh.coords;
  out.point_data = mesh.point_data;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!drop.empty() && drop[c]) continue;
    const CellType t = mesh.cell_type(c);
    out.add_cell(cell_info(t).linear, mesh.cell(c),
                 c < static_cast<int>(mesh.cell_region.size()) ? mesh.cell_region[c] : 0,
                 c < static_cast<int>(mesh.cell_entity.size()) ? mesh.cell_entity[c] : 0);
  }
  return out;
}

}  // namespace

bool use_quadratic_shape(const Mesh& mesh) {
  if (is_surface_mesh(mesh)) return false;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (is_quadratic_element(mesh, c, d)) return true;
  return false;
}

Mesh corner_mesh(const Mesh& mesh) { return corner_mesh_without(mesh, {}); }

QuadraticCellMeasures quadratic_cell_measures(CellType type, const double* nodes) {
  QuadraticCellMeasures m;
  const CellInfo& info = cell_info(type);
  const int d = info.dim;
  const double up[3] = {0, 0, 1};  // planar meshes: +z orients (surface meshes are not used)
  const CellQuality corner = cell_quality(info.linear, nodes, d == 2 ? up : nullptr);
  m.corner = is_simplex(type) ? corner.mean_ratio : corner.scaled_jacobian;
  m.min_dihedral = corner.min_dihedral_deg;
  m.max_dihedral = corner.max_dihedral_deg;
  QualityOptions qo;
  qo.angles = false;
  const CellQuality q = cell_quality(type, nodes, d == 2 ? up : nullptr, qo);
  m.pointwise_ratio = is_simplex(type) ? q.mean_ratio : kNaN;
  // det J at the default rule's points (every node of a quadratic cell).
  double p[kMaxCellNodes * 3];
  for (int i = 0; i < info.num_nodes; ++i)
    for (int a = 0; a < d; ++a) p[d * i + a] = nodes[3 * i + a];
  double lo = kInf, hi = -kInf;
  for (const SamplePoint& s : sample_points(type, SampleRule::kDefault)) {
    double A[9];
    cell_jacobian(type, p, d, s.xi, A);
    const double det = d == 2 ? A[0] * A[3] - A[1] * A[2]
                              : A[0] * (A[4] * A[8] - A[5] * A[7]) -
                                    A[1] * (A[3] * A[8] - A[5] * A[6]) +
                                    A[2] * (A[3] * A[7] - A[4] * A[6]);
    lo = std::min(lo, det);
    hi = std::max(hi, det);
  }
  m.det_ratio = hi > 0 ? lo / hi : -1;
  // tri6 / tet10: the Bernstein certificate (cell_quality counts an unproven cell inverted);
  // the others: every sample point.
  m.valid = (type == CellType::kTri6 || type == CellType::kTet10) ? q.certified == 1 : lo > 0;
  return m;
}

Status improve_quadratic_shape(Mesh* mesh, const ShapeOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "shape";
  result->before = measure_mesh(*mesh, options.rule);
  RecipeGeometry own;
  const RecipeGeometry* geometry = nullptr;
  Status gs = resolve_recipe_geometry(*mesh, options.slide, options.boundary, options.geometry,
                                      &own, &geometry);
  if (!gs.ok()) return gs;

  const std::vector<double> original = mesh->coords;
  const QuadraticBaseline input = quadratic_baseline(*mesh, options.solver.threads);
  const std::vector<QuadraticCellMeasures>& m0 = input.cells;

  std::vector<char> fixed = options.fixed;
  if (fixed.empty()) {
    if (geometry)
      fixed.assign(mesh->num_vertices(), 0);
    else
      fixed = boundary_vertex_mask(*mesh);  // mid nodes included; region interfaces too
  }
  // A valid curved cell can have an inverted corner cell (an edge bulging out past the opposite
  // corner); the barrier corner stage cannot start from it, so such cells are left out of the
  // corner problem and held.
  std::vector<char> drop(mesh->num_cells(), 0);
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!is_quadratic_element(*mesh, c, mesh->dim()) || m0[c].corner > 0) continue;
    drop[c] = 1;
    for (int i = 0; i < mesh->cell_size(c); ++i) fixed[mesh->cell(c)[i]] = 1;
  }
  // The corner problem: corner cells, the same vertices; targets from a reference mesh come
  // from its corner mesh too. The caller's extra points belong to quadratic cells (certificate
  // points): a corner simplex has one Jacobian, so they add nothing there.
  Mesh linear = corner_mesh_without(*mesh, drop);
  Mesh reference_linear;
  ShapeOptions lo = options;
  lo.extra_points = SampleSet();
  lo.geometry = geometry;
  lo.input_baseline = nullptr;  // the caller's is of the quadratic mesh, not of its corners
  if (options.target.reference) {
    reference_linear = corner_mesh_without(*options.target.reference, drop);
    lo.target.reference = &reference_linear;
  }

  const std::vector<char> boundary = fixed;  // before the guard holds any cell
  const int max_rounds = options.guard_rounds + 2;
  std::vector<char> placed;
  // The last state that kept every guarantee: the input, then a round's result stepped back
  // where it broke one; the next round starts from it (its held vertices fixed).
  std::vector<double> base = original;
  for (int round = 0; round <= max_rounds; ++round) {
    linear.coords = base;
    lo.fixed = fixed;
    RecipeResult lr;
    Status s = improve_shape(&linear, lo, &lr);
    if (s.ok() && lo.solver.progress.cancelled()) s = Status::Cancelled("shape: cancelled");
    if (!s.ok()) {  // failed or cancelled: the input
      mesh->coords = original;
      result->after = result->before;
      return s;
    }
    for (StageResult& st : lr.stages) {
      st.name += round == 0 ? " (corner mesh)"
                            : " (corner mesh, quadratic guard round " + std::to_string(round) + ")";
      result->stages.push_back(std::move(st));
    }
    mesh->coords = linear.coords;  // corners moved, every other node still at its input place
    place_nodes(original, mesh, &placed);
    if (geometry && geometry->constraints) project_sliding_nodes(*geometry, original, placed, mesh);

    std::vector<char> violates;
    std::string first;
    const int violators = quadratic_violators(*mesh, input, options, &violates, &first);
    if (violators == 0) break;
    StageResult& last = result->stages.back();
    {
      // Without a solve: the violators' corners back at the start of this round (their other
      // nodes placed again from the corners), blended over 8 rings of their neighbours, again
      // on the cells that then break one until none does (quadratic_guard.h). The next round
      // starts there with those corners held: it wins back what the step back cost. On t3 at
      // order 2, 44 of 34,028 cells break one after the first solve (dihedral angles, which the
      // corner mesh's guard does not see); holding them and solving again from the input (as
      // before) found new ones each round, 7 solves, tet10 mean 0.758 where the first had 0.800;
      // stepped back and warm started: 0.768, 0.777, 0.782, 0.783 after rounds 0..3.
      const std::vector<double> solved = mesh->coords;
      std::vector<char> unknown(placed.size());
      for (std::size_t v = 0; v < placed.size(); ++v) unknown[v] = !placed[v];
      auto apply = [&](const std::vector<double>& t) {
        for (int v = 0; v < mesh->num_vertices(); ++v)
          for (int a = 0; a < mesh->space_dim; ++a) {
            const std::size_t k = std::size_t(v) * mesh->space_dim + a;
            mesh->coords[k] = placed[v] ? original[k] : base[k] + t[v] * (solved[k] - base[k]);
          }
        // Every other node placed again from the corners (from its input position).
        place_nodes(original, mesh, &placed);
        if (geometry && geometry->constraints)
          project_sliding_nodes(*geometry, original, placed, mesh);
      };
      std::vector<char> bad = violates, held;
      std::string why;
      int passes = 0;
      if (step_back_until_kept(mesh, input, options, unknown, apply, kMaxStepBackPasses, &bad,
                               &passes, &why, &held) &&
          mesh->coords != base) {
        base = mesh->coords;
        int newly_fixed = 0;
        for (int v = 0; v < mesh->num_vertices(); ++v) {
          newly_fixed += held[v] && !fixed[v];
          fixed[v] |= held[v];
        }
        last.termination += "; quadratic guard: " + std::to_string(violators) + " cells (" + first +
                            ") stepped back towards the round's start in " +
                            std::to_string(passes) + " passes, " + std::to_string(newly_fixed) +
                            " vertices held";
        if (newly_fixed == 0 || round == max_rounds) break;
        continue;
      }
      mesh->coords = solved;
    }
    int newly_fixed = 0;
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (!violates[c]) continue;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        newly_fixed += !f;
        f = 1;
      }
    }
    if (newly_fixed == 0 || round == max_rounds) {
      mesh->coords = base;
      last.termination += "; quadratic guard: " + std::to_string(violators) +
                          " cells would get worse (" + first +
                          (base == original ? "): input mesh kept"
                                            : "): the last round that kept every guarantee kept");
      break;
    }
    last.termination +=
        "; quadratic guard: " + std::to_string(violators) + " cells held (" + first + ")";
  }
  curve_interior_nodes(mesh, options, geometry, boundary, input, result);
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
