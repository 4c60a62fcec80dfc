#include "tmop/recipes/quadratic_curving.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tmop/element/shape.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/topology.h"
#include "tmop/metric/metric.h"
#include "tmop/metric/size_shape_orientation.h"
#include "tmop/optimize/stage.h"
#include "tmop/target/target.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;
// Passes of the step-back repair (quadratic_guard.h) before a round's result is given up.
constexpr int kMaxStepBackPasses = 64;

bool is_quadratic_element(const Mesh& mesh, int c, int d) {
  return mesh.is_element(c, d) && cell_info(mesh.cell_type(c)).order == 2;
}

Vec3 point(const Mesh& mesh, const std::vector<double>& coords, int v) {
  Vec3 x(0, 0, 0);
  for (int a = 0; a < mesh.space_dim; ++a)
    x[a] = coords[static_cast<std::size_t>(v) * mesh.space_dim + a];
  return x;
}

void copy_vertex(const std::vector<double>& from, int v, int sd, std::vector<double>* to) {
  for (int a = 0; a < sd; ++a)
    (*to)[static_cast<std::size_t>(v) * sd + a] = from[static_cast<std::size_t>(v) * sd + a];
}

QuadraticCellMeasures measures_of(const Mesh& mesh, int c) {
  double nodes[kMaxCellNodes * 3] = {};
  for (int i = 0; i < mesh.cell_size(c); ++i)
    for (int a = 0; a < mesh.space_dim; ++a) nodes[3 * i + a] = mesh.vertex(mesh.cell(c)[i])[a];
  return quadratic_cell_measures(mesh.cell_type(c), nodes);
}

// The mesh with every non-corner node of a quadratic element at its corners' interpolation (the
// straight-sided cells), and per vertex: 1 for such a node that is off that place by more than
// 1e-9 of its cell's longest edge (curved).
Mesh straight_sided(const Mesh& mesh, std::vector<char>* curved) {
  const int d = mesh.dim();
  Mesh straight = mesh;
  curved->assign(mesh.num_vertices(), 0);
  double N[kMaxCellNodes];
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    const CellType t = mesh.cell_type(c);
    const CellInfo& info = cell_info(t);
    const std::int32_t* nodes = mesh.cell(c);
    double longest = 0;
    for (int e = 0; e < info.num_edges; ++e)
      longest = std::max(longest, (point(mesh, mesh.coords, nodes[info.edges[e][1]]) -
                                   point(mesh, mesh.coords, nodes[info.edges[e][0]]))
                                      .norm());
    for (int k = info.num_corners; k < info.num_nodes; ++k) {
      const int v = nodes[k];
      shape_values(info.linear, reference_node(t, k), N);
      Vec3 x(0, 0, 0);
      for (int i = 0; i < info.num_corners; ++i) x += N[i] * point(mesh, mesh.coords, nodes[i]);
      for (int a = 0; a < mesh.space_dim; ++a) straight.vertex(v)[a] = x[a];
      if ((point(mesh, mesh.coords, v) - x).norm() > 1e-9 * longest) (*curved)[v] = 1;
    }
  }
  return straight;
}

// The nodes the stage moves (quadratic_curving.h): interior non-corner nodes that are curved,
// and those of the cells within `rings` rings of a cell with a curved still node or not valid.
std::vector<char> moving_nodes(const Mesh& mesh, const std::vector<char>& curved,
                               const std::vector<char>& still, const QuadraticBaseline& input,
                               int rings, int* count) {
  const int n = mesh.num_vertices(), d = mesh.dim();
  std::vector<char> corner(n, 0), non_corner(n, 0);
  std::vector<char> in(mesh.num_cells(), 0);
  std::vector<std::vector<int>> vertex_cells(n);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    const CellInfo& info = cell_info(mesh.cell_type(c));
    bool source = !input.cells[c].valid;
    for (int k = 0; k < info.num_nodes; ++k) {
      const int v = mesh.cell(c)[k];
      (k < info.num_corners ? corner : non_corner)[v] = 1;
      vertex_cells[v].push_back(c);
      source |= k >= info.num_corners && still[v] && curved[v];
    }
    in[c] = source;
  }
  for (int r = 0; r < rings; ++r) {
    std::vector<char> next = in;
    for (int c = 0; c < mesh.num_cells(); ++c)
      if (in[c])
        for (int i = 0; i < mesh.cell_size(c); ++i)
          for (int e : vertex_cells[mesh.cell(c)[i]]) next[e] = 1;
    in.swap(next);
  }
  std::vector<char> moving(n, 0);
  *count = 0;
  for (int v = 0; v < n; ++v) {
    if (!non_corner[v] || corner[v] || still[v]) continue;
    bool near = curved[v];
    for (int c : vertex_cells[v]) near |= in[c] != 0;
    if (near) moving[v] = 1, ++*count;
  }
  return moving;
}

// Per cell: the straight-sided cell's scale that gives it the area (volume) of the curved cell
// in `mesh` (1 for the other cells and where either is not positive).
std::vector<double> area_scales(const Mesh& mesh, const Mesh& straight) {
  const int d = mesh.dim();
  std::vector<double> s(mesh.num_cells(), 1.0);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    const double a = cell_equivalent_edge(mesh, c), b = cell_equivalent_edge(straight, c);
    if (a > 0 && b > 0) s[c] = a / b;
  }
  return s;
}

// A stage over the moving nodes with one term: `metric` toward the straight-sided cells, scaled
// by `scale` (empty: not scaled).
StageSpec curving_stage(const ShapeOptions& options, const Mesh& straight,
                        std::shared_ptr<const Metric> metric, double power,
                        std::vector<double> scale = {}) {
  StageSpec st;
  st.rule = options.rule;
  st.extra_points = options.extra_points;
  st.solver = options.solver;
  st.power = power;
  TermSpec term;
  term.metric = std::move(metric);
  term.target.type = TargetType::kReference;
  term.target.reference = &straight;
  term.target.cell_scale = std::move(scale);
  st.terms.push_back(term);
  return st;
}

// The worst and the sum of the det J ratio over the cells with a moving node, and whether every
// cell valid in the input still is.
struct Score {
  bool kept = true;  // every guarantee of the guard
  bool valid = true;
  double worst = 1, sum = 0;
  bool better_than(const Score& o) const {
    if (kept != o.kept) return kept;
    if (valid != o.valid) return valid;
    if (worst != o.worst) return worst > o.worst;
    return sum > o.sum;
  }
};
Score score(const Mesh& mesh, const std::vector<char>& moving, const QuadraticBaseline& input) {
  Score s;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!is_quadratic_element(mesh, c, d)) continue;
    bool touched = false;
    for (int i = 0; i < mesh.cell_size(c) && !touched; ++i) touched = moving[mesh.cell(c)[i]];
    if (!touched) continue;
    const QuadraticCellMeasures m = measures_of(mesh, c);
    s.valid &= m.valid || !input.cells[c].valid;
    s.worst = std::min(s.worst, m.det_ratio);
    s.sum += m.det_ratio;
  }
  return s;
}

// The moved mid-edge nodes back on their chords where that costs their cells at most kSnapLoss
// of a measure and no validity (quadratic_curving.h); then the guarantees, with the snaps of the
// cells that break one undone until none does. Returns the number of nodes put back.
int snap_to_chords(Mesh* mesh, const Mesh& straight, const std::vector<char>& moving,
                   const QuadraticBaseline& input, const ShapeOptions& options) {
  const int d = mesh->dim(), sd = mesh->space_dim;
  const std::vector<double> solved = mesh->coords;
  std::vector<std::vector<int>> vertex_cells(mesh->num_vertices());
  std::vector<std::pair<double, int>> order;  // (offset / chord, node) of the moved mid-edge nodes
  std::vector<char> listed(mesh->num_vertices(), 0);
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!is_quadratic_element(*mesh, c, d)) continue;
    const CellInfo& info = cell_info(mesh->cell_type(c));
    const std::int32_t* nodes = mesh->cell(c);
    for (int k = 0; k < info.num_nodes; ++k) vertex_cells[nodes[k]].push_back(c);
    for (int e = 0; e < info.num_edges; ++e) {
      const int v = nodes[info.num_corners + e];
      if (!moving[v] || listed[v]) continue;
      listed[v] = 1;
      const double chord = (point(*mesh, mesh->coords, nodes[info.edges[e][1]]) -
                            point(*mesh, mesh->coords, nodes[info.edges[e][0]]))
                               .norm();
      const double off =
          (point(*mesh, mesh->coords, v) - point(straight, straight.coords, v)).norm();
      if (off > 0 && chord > 0) order.emplace_back(off / chord, v);
    }
  }
  std::sort(order.begin(), order.end());
  std::vector<char> snapped(mesh->num_vertices(), 0);
  int count = 0;
  for (const auto& [offset, v] : order) {
    std::vector<QuadraticCellMeasures> before;
    for (int c : vertex_cells[v]) before.push_back(measures_of(*mesh, c));
    std::vector<double> keep(sd);
    for (int a = 0; a < sd; ++a)
      keep[a] = mesh->vertex(v)[a], mesh->vertex(v)[a] = straight.vertex(v)[a];
    bool ok = true;
    for (std::size_t i = 0; i < before.size() && ok; ++i) {
      const QuadraticCellMeasures m = measures_of(*mesh, vertex_cells[v][i]);
      ok = (m.valid || !before[i].valid) && m.det_ratio >= before[i].det_ratio - kSnapLoss &&
           !(m.pointwise_ratio < before[i].pointwise_ratio - kSnapLoss);
    }
    if (ok) {
      snapped[v] = 1;
      ++count;
    } else {
      for (int a = 0; a < sd; ++a) mesh->vertex(v)[a] = keep[a];
    }
  }
  // Undo the snaps of the cells that then break a guarantee, until none does; all of them when
  // that does not end it (a fallen mean can be flagged on cells that were not snapped).
  for (int pass = 0; count > 0; ++pass) {
    std::vector<char> violates;
    std::string first;
    if (quadratic_violators(*mesh, input, options, &violates, &first) == 0) break;
    int undone = 0;
    for (int c = 0; c < mesh->num_cells() && pass < kMaxStepBackPasses; ++c) {
      if (!violates[c]) continue;
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        const int v = mesh->cell(c)[i];
        if (!snapped[v]) continue;
        snapped[v] = 0;
        --count;
        ++undone;
        copy_vertex(solved, v, sd, &mesh->coords);
      }
    }
    if (undone == 0) {
      mesh->coords = solved;
      count = 0;
    }
  }
  return count;
}

// Round 0 of the stage (quadratic_curving.h): the measure from each start (the nodes where they
// are, the elastic start), under the caller's power and, when neither result keeps every
// guarantee, under the plain mean (power 1; the power's pull on the worst cells can lower a mean:
// a tet10 sphere in a box, det J ratio worst 0.756 but its mean 0.961 -> 0.954 and the pointwise
// mean ratio's 0.784 -> 0.783; power 1: 0.671, means kept). The best result by Score.
struct Probe {
  std::shared_ptr<const Metric> metric;
  double power = 1;
  std::vector<double> from, scale, result;  // result empty: no solve succeeded
  StageResult stage;
};
Probe probe_starts(Mesh* mesh, const ShapeOptions& options, const Mesh& straight,
                   const std::vector<char>& fixed, const std::vector<char>& moving,
                   const std::vector<double>& start, const std::vector<double>& elastic,
                   const QuadraticBaseline& input) {
  Probe best;
  best.metric.reset(make_metric("shape_barrier+size_barrier_quadratic", mesh->dim()).release());
  Score best_score;
  best_score.kept = best_score.valid = false;
  best_score.worst = -2;
  const double power = options.power > 0 ? options.power : 2.0;
  for (const double p : {power, 1.0}) {
    if (p != power && (best_score.kept || power == 1)) break;
    for (int k = 0; k < 2; ++k) {
      const std::vector<double>& s = k == 0 ? start : elastic;
      if (s.empty()) continue;
      mesh->coords = s;
      std::vector<double> scale = area_scales(*mesh, straight);
      StageSpec st = curving_stage(options, straight, best.metric, p, scale);
      st.fixed = fixed;
      st.name = std::string("shape (curved nodes") + (k == 1 ? ", from the elastic start" : "") +
                (p != power ? ", power 1)" : ")");
      StageResult sr;
      if (!optimize_stage(mesh, st, &sr).ok()) continue;
      if (options.solver.progress.cancelled()) break;
      Score sc = score(*mesh, moving, input);
      std::vector<char> violates;
      std::string first;
      sc.kept = quadratic_violators(*mesh, input, options, &violates, &first) == 0;
      if (!sc.better_than(best_score)) continue;
      best_score = sc;
      best.power = p;
      best.from = s;
      best.scale = std::move(scale);
      best.result = mesh->coords;
      best.stage = sr;
    }
  }
  mesh->coords = start;
  return best;
}

}  // namespace

void curve_interior_nodes(Mesh* mesh, const ShapeOptions& options, const RecipeGeometry* geometry,
                          const std::vector<char>& boundary, const QuadraticBaseline& input,
                          RecipeResult* result) {
  const int d = mesh->dim(), sd = mesh->space_dim;
  if (options.target.reference) return;  // the caller's reference targets: the nodes stay
  std::vector<char> curved, still = boundary;
  if (geometry && geometry->constraints)
    for (int v = 0; v < mesh->num_vertices(); ++v)
      still[v] |= geometry->constraints->kind(v) != VertexKind::kInterior;
  const Mesh straight = straight_sided(*mesh, &curved);
  int free_nodes = 0;
  const std::vector<char> moving =
      moving_nodes(*mesh, curved, still, input, kCurvingRings, &free_nodes);
  if (free_nodes == 0) return;
  std::vector<char> fixed(mesh->num_vertices(), 1);
  for (int v = 0; v < mesh->num_vertices(); ++v) fixed[v] = !moving[v];
  const std::vector<double> start = mesh->coords;

  // The elastic start: the moving nodes on their chords, then |T - I|^2 toward the
  // straight-sided cells (not a barrier: it starts from cells the straight nodes invert).
  std::vector<double> elastic;
  {
    for (int v = 0; v < mesh->num_vertices(); ++v)
      if (moving[v]) copy_vertex(straight.coords, v, sd, &mesh->coords);
    StageSpec st = curving_stage(
        options, straight,
        std::shared_ptr<const Metric>(make_size_shape_orientation_metric(false, d).release()), 1.0);
    st.name = "shape (curved nodes, elastic start)";
    st.fixed = fixed;
    StageResult sr;
    if (optimize_stage(mesh, st, &sr).ok()) {
      result->stages.push_back(sr);
      elastic = mesh->coords;
    }
    mesh->coords = start;
    if (st.solver.progress.cancelled()) return;
  }
  const Probe probe = probe_starts(mesh, options, straight, fixed, moving, start, elastic, input);
  if (options.solver.progress.cancelled() || probe.result.empty()) return;
  const std::vector<double>& probed = probe.result;
  std::vector<double> from = probe.from;

  std::vector<double> stepped;  // the first round's result stepped back, if it kept every guarantee
  std::string stepped_note;
  auto finish = [&](const std::vector<double>& kept, StageResult* last, const std::string& note) {
    mesh->coords = kept;
    if (kept == start) return;
    const int snapped = snap_to_chords(mesh, straight, moving, input, options);
    if (last)
      last->termination +=
          note + "; " + std::to_string(snapped) + " mid-edge nodes put back on their chords";
  };
  for (int round = 0; round <= options.guard_rounds; ++round) {
    StageSpec st = curving_stage(options, straight, probe.metric, probe.power, probe.scale);
    st.name = round == 0
                  ? "shape (curved nodes)"
                  : "shape (curved nodes, quadratic guard round " + std::to_string(round) + ")";
    st.fixed = fixed;
    // This round's start: `from`, with the held nodes where they were.
    mesh->coords = from;
    for (int v = 0; v < mesh->num_vertices(); ++v)
      if (moving[v] && fixed[v]) copy_vertex(start, v, sd, &mesh->coords);
    StageResult sr;
    if (round == 0) {
      mesh->coords = probed;
      sr = probe.stage;
    } else if (!optimize_stage(mesh, st, &sr).ok()) {
      if (from == start) {
        mesh->coords = start;
        return;
      }
      from = start;  // the elastic start with nodes held may invert: from where they were
      mesh->coords = start;
      if (!optimize_stage(mesh, st, &sr).ok()) {
        mesh->coords = start;
        return;
      }
    }
    result->stages.push_back(sr);
    if (st.solver.progress.cancelled()) {  // cancelled: the curved nodes where this pass began
      mesh->coords = start;
      return;
    }
    std::vector<char> violates;
    std::string first;
    const int violators = quadratic_violators(*mesh, input, options, &violates, &first);
    StageResult& last = result->stages.back();
    if (violators == 0) {
      // Rounds that ended by holding every node give the start back: a stepped-back result
      // of an earlier round instead.
      if (mesh->coords == start && !stepped.empty()) {
        finish(stepped, &last, "; quadratic guard: " + stepped_note);
        return;
      }
      finish(mesh->coords, &last, "");
      return;
    }
    if (stepped.empty()) {
      // This round's result with the violators' nodes stepped back towards where the stage
      // began (quadratic_guard.h, no solve), kept for when the rounds give nothing.
      const std::vector<double> solved = mesh->coords;
      std::vector<char> unknown(fixed.size());
      for (std::size_t v = 0; v < fixed.size(); ++v) unknown[v] = !fixed[v];
      auto apply = [&](const std::vector<double>& t) {
        for (int v = 0; v < mesh->num_vertices(); ++v)
          for (int a = 0; a < sd; ++a) {
            const std::size_t k = std::size_t(v) * sd + a;
            mesh->coords[k] = start[k] + t[v] * (solved[k] - start[k]);
          }
      };
      std::vector<char> bad = violates, held;
      std::string why;
      int passes = 0;
      if (step_back_until_kept(mesh, input, options, unknown, apply, kMaxStepBackPasses, &bad,
                               &passes, &why, &held) &&
          mesh->coords != start) {
        stepped = mesh->coords;
        stepped_note = "round " + std::to_string(round) + "'s " + std::to_string(violators) +
                       " cells (" + first + ") stepped back towards their start in " +
                       std::to_string(passes) + " passes kept";
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
    if (newly_fixed == 0 || round == options.guard_rounds) {
      last.termination += "; quadratic guard: " + std::to_string(violators) +
                          " cells would get worse (" + first + "): ";
      last.termination += stepped.empty() ? "curved nodes kept" : stepped_note;
      finish(stepped.empty() ? start : stepped, &last, "");
      return;
    }
    last.termination +=
        "; quadratic guard: " + std::to_string(violators) + " cells held (" + first + ")";
  }
  mesh->coords = start;
}

void curve_untangled_nodes(Mesh* mesh, const ShapeOptions& shape, RecipeResult* result) {
  if (!use_quadratic_shape(*mesh)) return;
  ShapeOptions options = shape;
  options.guard_worst = false;
  options.guard_means = false;
  std::vector<char> boundary = options.fixed;
  if (boundary.empty()) {
    if (options.geometry)
      boundary.assign(mesh->num_vertices(), 0);
    else
      boundary = boundary_vertex_mask(*mesh);
  }
  const QuadraticBaseline input = quadratic_baseline(*mesh, options.solver.threads);
  curve_interior_nodes(mesh, options, options.geometry, boundary, input, result);
}

}  // namespace tmop
