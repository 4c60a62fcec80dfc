#include "tmop/recipes/quadratic_shape.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/geometry/geometry_manifold.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/guarantees.h"
#include "tmop/quality/parallel_for.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

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

QuadraticCellMeasures cell_measures(const Mesh& mesh, int c) {
  double nodes[kMaxCellNodes * 3] = {};
  const int n = mesh.cell_size(c);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < mesh.space_dim; ++a) nodes[3 * i + a] = mesh.vertex(mesh.cell(c)[i])[a];
  return quadratic_cell_measures(mesh.cell_type(c), nodes);
}

// threads: as SolverOptions::threads (0 = all cores); the result does not depend on it.
std::vector<QuadraticCellMeasures> all_measures(const Mesh& mesh, int threads) {
  const int d = mesh.dim();
  std::vector<QuadraticCellMeasures> out(mesh.num_cells());
  parallel_chunks(mesh.num_cells(), 4096, threads,
                  [&](std::int64_t, std::int64_t b, std::int64_t e) {
                    for (std::int64_t c = b; c < e; ++c)
                      if (is_quadratic_element(mesh, static_cast<int>(c), d))
                        out[c] = cell_measures(mesh, static_cast<int>(c));
                  });
  return out;
}

bool is_sliver(const QuadraticCellMeasures& m) {
  return m.max_dihedral > 150 && m.min_dihedral < 10;  // false for NaN (not a tet)
}

// The measures whose worst and mean per type are guarded, as (getter index): corner,
// pointwise ratio, det ratio.
constexpr int kGuarded = 3;
double guarded(const QuadraticCellMeasures& m, int k) {
  return k == 0 ? m.corner : k == 1 ? m.pointwise_ratio : m.det_ratio;
}
const char* guarded_name(int k) {
  return k == 0 ? "corner quality" : k == 1 ? "pointwise mean ratio" : "det J ratio";
}

struct TypeBounds {
  int count = 0;
  double worst[kGuarded] = {kInf, kInf, kInf};
  double sum[kGuarded] = {0, 0, 0};
  double min_dihedral = kInf, max_dihedral = -kInf;
};

std::vector<TypeBounds> type_bounds(const Mesh& mesh, const std::vector<QuadraticCellMeasures>& m) {
  const int d = mesh.dim();
  std::vector<TypeBounds> out(kNumCellTypes);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    TypeBounds& b = out[static_cast<int>(mesh.cell_type(c))];
    ++b.count;
    for (int k = 0; k < kGuarded; ++k) {
      const double v = guarded(m[c], k);
      if (std::isnan(v)) continue;
      b.worst[k] = std::min(b.worst[k], v);
      b.sum[k] += v;
    }
    if (!std::isnan(m[c].min_dihedral)) {
      b.min_dihedral = std::min(b.min_dihedral, m[c].min_dihedral);
      b.max_dihedral = std::max(b.max_dihedral, m[c].max_dihedral);
    }
  }
  return out;
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

// The cells of `mesh` that break a guarantee of quadratic_shape.h against the input (m0, b0):
// flags them in *violates and returns their count; *first describes one.
int find_violators(const Mesh& mesh, const std::vector<QuadraticCellMeasures>& m0,
                   const std::vector<TypeBounds>& b0, const GuaranteeBaseline& g0,
                   const ShapeOptions& options, std::vector<char>* out, std::string* first_out) {
  const bool guard_worst = options.guard_worst;
  const double tol = options.guard_tolerance;
  const int threads = options.solver.threads;
  const int d = mesh.dim();
  const std::vector<QuadraticCellMeasures> m1 = all_measures(mesh, threads);
  std::vector<char>& violates = *out;
  violates.assign(mesh.num_cells(), 0);
  int violators = 0;
  std::string& first = *first_out;
  first.clear();
  auto flag = [&](int c, const std::string& why) {
    if (violates[c]) return;
    violates[c] = 1;
    ++violators;
    if (first.empty()) first = "cell " + std::to_string(c) + " " + why;
  };
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    const TypeBounds& b = b0[static_cast<int>(mesh.cell_type(c))];
    if (m0[c].valid && !m1[c].valid) flag(c, "not certified valid");
    if (!guard_worst) continue;
    for (int k = 0; k < kGuarded; ++k)
      if (guarded(m1[c], k) < b.worst[k] - tol)
        flag(c, std::string(guarded_name(k)) + " below the input's worst");
    if (m1[c].min_dihedral < b.min_dihedral - 1e-6 || m1[c].max_dihedral > b.max_dihedral + 1e-6)
      flag(c, "dihedral angle outside the input's range");
    if (is_sliver(m1[c]) && !is_sliver(m0[c])) flag(c, "became a sliver");
  }
  if (violators == 0 && guard_worst) {
    // Means per type: where one fell, the cells whose own measure fell most are held, until
    // what they give back covers the shortfall (with a margin: their neighbours move too).
    // Holding every cell whose measure fell would also hold cells the worst depends on (t5
    // at order 2: 899 cells, the worst corner tet among them), and cells that fell by
    // round-off only (100k tet10: 46,000 straight cells whose det J ratio is 1 - 1e-16).
    // Cells whose input was worse than this round's worst (of any guarded measure), and cells
    // sharing a vertex with them, are protected: held, they would go back to their input and
    // lower the worst again.
    const std::vector<TypeBounds> b1 = type_bounds(mesh, m1);
    std::vector<char> protect(mesh.num_vertices(), 0);
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (!is_quadratic_element(mesh, c, d)) continue;
      const TypeBounds& b = b1[static_cast<int>(mesh.cell_type(c))];
      bool low = false;
      for (int k = 0; k < kGuarded; ++k) low |= guarded(m0[c], k) < b.worst[k];
      if (low)
        for (int i = 0; i < mesh.cell_size(c); ++i) protect[mesh.cell(c)[i]] = 1;
    }
    auto is_protected = [&](int c) {
      for (int i = 0; i < mesh.cell_size(c); ++i)
        if (protect[mesh.cell(c)[i]]) return true;
      return false;
    };
    for (int t = 0; t < kNumCellTypes; ++t) {
      if (b0[t].count == 0) continue;
      for (int k = 0; k < kGuarded; ++k) {
        const double shortfall = b0[t].sum[k] - b1[t].sum[k];
        if (!(shortfall > tol * b0[t].count)) continue;
        // Candidates: cells whose measure fell (beyond round-off), the unprotected ones first,
        // each group largest fall first; the protected ones only when the others give back less
        // than half the shortfall (the mean is a guarantee; held, they still end at least at the
        // input's worst). 100k tet10 t5: holding them in the first round kept the worst corner
        // mean ratio at the input's 0.367, from the third round 0.39.
        std::vector<std::tuple<bool, double, int>> fell;
        for (int c = 0; c < mesh.num_cells(); ++c) {
          if (!is_quadratic_element(mesh, c, d) || static_cast<int>(mesh.cell_type(c)) != t)
            continue;
          const double delta = guarded(m0[c], k) - guarded(m1[c], k);
          if (delta > 1e-9) fell.emplace_back(is_protected(c), -delta, c);
        }
        std::sort(fell.begin(), fell.end());
        double unprotected = 0;
        for (const auto& [is_prot, minus_delta, c] : fell)
          if (!is_prot) unprotected -= minus_delta;
        const bool with_protected = unprotected < 0.5 * shortfall;
        double given_back = 0;
        for (const auto& [is_prot, minus_delta, c] : fell) {
          if (given_back >= 1.25 * shortfall + tol * b0[t].count) break;
          if (is_prot && !with_protected) break;
          given_back -= minus_delta;
          flag(c, std::string("mean ") + guarded_name(k) + " of " +
                      cell_name(static_cast<CellType>(t)) + " fell");
        }
      }
    }
  }
  if (guard_worst) {
    // The guarantees as tmop_optimize checks them (quality/guarantees.h): per region too.
    GuaranteeOptions g;
    g.tolerance = tol;
    g.means = options.guard_means;
    const GuaranteeValues values = guarantee_values(mesh, threads);
    for (int c : guard_violators(g0, values, g))
      flag(c, "breaks a guarantee of its type or region");
  }
  return violators;
}

// The stage over curved interior nodes: mid-edge, mid-face and centre nodes off the corners'
// interpolation (curved by the input or by untangling; this recipe never curves a straight
// edge) and not on the boundary (`boundary` or a sliding geometry) move, everything else is
// fixed. Terms: the caller's shape metric and target at every sample point (the pointwise mean
// ratio) and the size barrier toward the straight-sided cell's Jacobian (det J toward its
// constant: the det J ratio), so curvature the cells do not need is relaxed. The same guard as
// the corner stage; when its rounds run out the nodes stay as they were.
void relax_curved_nodes(Mesh* mesh, const ShapeOptions& options, const RecipeGeometry* geometry,
                        const std::vector<char>& boundary,
                        const std::vector<QuadraticCellMeasures>& m0,
                        const std::vector<TypeBounds>& b0, const GuaranteeBaseline& g0,
                        RecipeResult* result) {
  const int d = mesh->dim();
  std::vector<char> fixed(mesh->num_vertices(), 1);
  Mesh straight = *mesh;
  int free_nodes = 0;
  double N[kMaxCellNodes];
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!is_quadratic_element(*mesh, c, d)) continue;
    const CellType t = mesh->cell_type(c);
    const CellInfo& info = cell_info(t);
    const std::int32_t* nodes = mesh->cell(c);
    double longest = 0;
    for (int e = 0; e < info.num_edges; ++e)
      longest = std::max(longest, (point(*mesh, mesh->coords, nodes[info.edges[e][1]]) -
                                   point(*mesh, mesh->coords, nodes[info.edges[e][0]]))
                                      .norm());
    for (int k = info.num_corners; k < info.num_nodes; ++k) {
      const int v = nodes[k];
      shape_values(info.linear, reference_node(t, k), N);
      Vec3 x(0, 0, 0);
      for (int i = 0; i < info.num_corners; ++i) x += N[i] * point(*mesh, mesh->coords, nodes[i]);
      set_point(&straight, v, x);
      const bool on_boundary =
          boundary[v] || (geometry && geometry->constraints &&
                          geometry->constraints->kind(v) != VertexKind::kInterior);
      if (on_boundary || !fixed[v]) continue;
      if ((point(*mesh, mesh->coords, v) - x).norm() > 1e-9 * longest) {
        fixed[v] = 0;
        ++free_nodes;
      }
    }
  }
  if (free_nodes == 0) return;
  StageSpec st;
  st.rule = options.rule;
  st.extra_points = options.extra_points;
  st.solver = options.solver;
  st.power = options.power > 0 ? options.power : 2.0;
  // Two terms: the shape metric toward the ideal element (the pointwise mean ratio) and the
  // size barrier toward the straight-sided cell (det J toward its constant: the det J ratio).
  std::string error;
  TermSpec shape;
  shape.metric = recipe_metric(options.metric, d, 1.0, &error);
  shape.target = options.target;
  TermSpec size;
  size.metric = recipe_metric("size_barrier", d, 1.0, &error);
  size.target.type = TargetType::kReference;
  size.target.reference = &straight;
  if (!shape.metric || !size.metric || options.target.reference) return;
  // The size term's weight: on the untangled gear tri6 (high_order_untangle_test) 1 / 0.3 / 0.1
  // give det J ratio worst 0.08 -> 0.30 / 0.18 / 0.11 but pointwise mean ratio mean
  // 0.890 -> 0.885 / 0.892 / 0.895: 0.3 is the largest measured that lets neither mean fall.
  const double w = 0.3;
  size.weights.assign(
      canonical_sample_set(*mesh, options.rule).size() + options.extra_points.size(), w);
  st.terms.push_back(shape);
  st.terms.push_back(size);
  const std::vector<double> start = mesh->coords;
  for (int round = 0; round <= options.guard_rounds; ++round) {
    st.name = round == 0
                  ? "shape (curved nodes)"
                  : "shape (curved nodes, quadratic guard round " + std::to_string(round) + ")";
    st.fixed = fixed;
    StageResult sr;
    if (!optimize_stage(mesh, st, &sr).ok()) {
      mesh->coords = start;
      return;
    }
    result->stages.push_back(sr);
    if (st.solver.progress.cancelled()) {  // cancelled: the curved nodes where this pass began
      mesh->coords = start;
      return;
    }
    std::vector<char> violates;
    std::string first;
    const int violators = find_violators(*mesh, m0, b0, g0, options, &violates, &first);
    if (violators == 0) return;
    int newly_fixed = 0;
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (!violates[c]) continue;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        newly_fixed += !f;
        f = 1;
      }
    }
    mesh->coords = start;
    StageResult& last = result->stages.back();
    if (newly_fixed == 0 || round == options.guard_rounds) {
      last.termination += "; quadratic guard: " + std::to_string(violators) +
                          " cells would get worse (" + first + "): curved nodes kept";
      return;
    }
    last.termination +=
        "; quadratic guard: " + std::to_string(violators) + " cells held (" + first + ")";
  }
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
  const std::vector<QuadraticCellMeasures> m0 = all_measures(*mesh, options.solver.threads);
  const std::vector<TypeBounds> b0 = type_bounds(*mesh, m0);
  const GuaranteeBaseline g0 = guarantee_baseline(*mesh, options.solver.threads);

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
  if (options.target.reference) {
    reference_linear = corner_mesh_without(*options.target.reference, drop);
    lo.target.reference = &reference_linear;
  }

  const std::vector<char> boundary = fixed;  // before the guard holds any cell
  const int max_rounds = options.guard_rounds + 2;
  std::vector<char> placed;
  for (int round = 0; round <= max_rounds; ++round) {
    linear.coords = original;
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
    const int violators = find_violators(*mesh, m0, b0, g0, options, &violates, &first);
    if (violators == 0) break;
    int newly_fixed = 0;
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (!violates[c]) continue;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        newly_fixed += !f;
        f = 1;
      }
    }
    StageResult& last = result->stages.back();
    if (newly_fixed == 0 || round == max_rounds) {
      // Without a solve: the violators' corners back at their input positions (their other
      // nodes placed again from the corners), repeated on the cells that then break one.
      int left = violators;
      for (int pass = 0; pass < 8 && left > 0; ++pass) {
        int moved = 0;
        for (int c = 0; c < mesh->num_cells(); ++c) {
          if (!violates[c]) continue;
          for (int i = 0; i < cell_info(mesh->cell_type(c)).num_corners; ++i) {
            const std::size_t v = std::size_t(mesh->cell(c)[i]) * mesh->space_dim;
            for (int a = 0; a < mesh->space_dim; ++a) {
              moved += mesh->coords[v + a] != original[v + a];
              mesh->coords[v + a] = original[v + a];
            }
          }
        }
        if (moved == 0) break;
        // place_nodes leaves the nodes of unmoved corners where they are: start them all from
        // their input positions.
        for (int v = 0; v < mesh->num_vertices(); ++v)
          if (placed[v])
            std::copy_n(&original[std::size_t(v) * mesh->space_dim], mesh->space_dim,
                        mesh->vertex(v));
        place_nodes(original, mesh, &placed);
        if (geometry && geometry->constraints)
          project_sliding_nodes(*geometry, original, placed, mesh);
        left = find_violators(*mesh, m0, b0, g0, options, &violates, &first);
      }
      if (left == 0 && mesh->coords != original) {
        last.termination += "; quadratic guard: " + std::to_string(violators) +
                            " cells would get worse: put back at their input shape";
        break;
      }
      mesh->coords = original;
      last.termination += "; quadratic guard: " + std::to_string(violators) +
                          " cells would get worse (" + first + "): input mesh kept";
      break;
    }
    last.termination +=
        "; quadratic guard: " + std::to_string(violators) + " cells held (" + first + ")";
  }
  relax_curved_nodes(mesh, options, geometry, boundary, m0, b0, g0, result);
  result->after = measure_mesh(*mesh, options.rule);
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
