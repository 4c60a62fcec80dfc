#include "tmop/recipes/vertex_moves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "tmop/mesh/topology.h"
#include "tmop/quality/element_scan.h"

namespace tmop {

double guarantee_score(const GuaranteeBaseline& baseline, const GuaranteeValues& values) {
  double score = 0;
  for (std::size_t c = 0; c < values.cell.size(); ++c)
    for (int m = 0; m < kNumGuaranteeMeasures; ++m) {
      const double v = values.cell[c][m];
      if (baseline.cell_group[c][m] >= 0 &&
          guarantee_measure_has_mean(static_cast<GuaranteeMeasure>(m)) && v == v)
        score += v;
    }
  return score;
}

namespace {

// What the acceptance of one vertex's move needs to know of the groups.
struct Groups {
  std::vector<int> mean_of;    // per worst group: its (type, measure) mean group, or -1
  std::vector<double> floor;   // per mean group: the input's sum
  std::vector<double> sum;     // per mean group: the current sum
  std::vector<double> change;  // per mean group: the move's change (scratch)
  std::vector<char> listed;    // per mean group: in `touched` (scratch)
  std::vector<int> touched;    // mean groups the move changed (scratch)
};

Groups make_groups(const GuaranteeBaseline& b, const GuaranteeValues& values) {
  Groups g;
  std::map<std::pair<int, int>, int> index;
  for (std::size_t i = 0; i < b.mean_groups.size(); ++i)
    index[{static_cast<int>(b.mean_groups[i].type), static_cast<int>(b.mean_groups[i].measure)}] =
        static_cast<int>(i);
  g.mean_of.assign(b.worst_groups.size(), -1);
  for (std::size_t i = 0; i < b.worst_groups.size(); ++i) {
    const auto it = index.find(
        {static_cast<int>(b.worst_groups[i].type), static_cast<int>(b.worst_groups[i].measure)});
    if (it != index.end()) g.mean_of[i] = it->second;
  }
  g.floor.assign(b.mean_groups.size(), 0);
  g.sum.assign(b.mean_groups.size(), 0);
  g.change.assign(b.mean_groups.size(), 0);
  g.listed.assign(b.mean_groups.size(), 0);
  for (std::size_t c = 0; c < values.cell.size(); ++c)
    for (int m = 0; m < kNumGuaranteeMeasures; ++m) {
      const int w = b.cell_group[c][m];
      if (w < 0 || g.mean_of[w] < 0) continue;
      g.floor[g.mean_of[w]] += b.input.cell[c][m];
      g.sum[g.mean_of[w]] += values.cell[c][m];
    }
  return g;
}

// Whether cell c's new row keeps its guarantees (old: its row before the move); adds its
// changes of the mean groups' sums to g (all of them, kept or not).
bool cell_keeps(const GuaranteeBaseline& b, const GuaranteeOptions& o, int c,
                const GuaranteeValues& now, const std::array<double, kNumGuaranteeMeasures>& old,
                bool old_inverted, Groups* g) {
  bool keeps = !(now.inverted[c] && !old_inverted && !b.input.inverted[c]) &&
               !(o.slivers && now.sliver[c] && !b.input.sliver[c]);
  for (int m = 0; m < kNumGuaranteeMeasures; ++m) {
    const int w = b.cell_group[c][m];
    if (w < 0) continue;
    const double v = now.cell[c][m];
    if (!(v >= std::min(b.worst_groups[w].worst, old[m]))) keeps = false;  // NaN too
    const int mg = g->mean_of[w];
    if (mg < 0) continue;
    if (!g->listed[mg]) g->touched.push_back(mg), g->listed[mg] = 1;
    g->change[mg] += v - old[m];
  }
  return keeps;
}

// Tries positions of single vertices against the guarantees and keeps the good ones.
class MoveJudge {
 public:
  MoveJudge(Mesh* mesh, const GuaranteeBaseline& baseline, const GuaranteeOptions& guarantees,
            GuaranteeValues* values)
      : mesh_(mesh),
        b_(baseline),
        o_(guarantees),
        values_(values),
        cells_(vertex_to_cells(*mesh)),
        planar_(is_planar_2d(*mesh)),
        d_(mesh->dim()),
        g_(make_groups(baseline, *values)) {}

  // Vertex v at x (space_dim coordinates): when every guarantee holds and the score rises by
  // more than round-off (and `keep`), the move is kept; else v goes back. *gain: the rise of
  // the score of v's cells (-inf when a cell's measure is undefined or it inverts).
  bool try_position(int v, const double* x, bool keep, double* gain) {
    return try_positions(&v, 1, x, keep, gain);
  }

  // The same for n vertices moved together (x: n x space_dim coordinates).
  bool try_positions(const int* vs, int n, const double* x, bool keep, double* gain) {
    const int sd = mesh_->space_dim, d = d_;
    from_.assign(static_cast<std::size_t>(n) * sd, 0);
    cells_touched_.clear();
    for (int j = 0; j < n; ++j) {
      double* p = mesh_->vertex(vs[j]);
      for (int a = 0; a < sd; ++a) from_[j * sd + a] = p[a], p[a] = x[j * sd + a];
      for (std::int64_t k = cells_.offsets[vs[j]]; k < cells_.offsets[vs[j] + 1]; ++k)
        cells_touched_.push_back(cells_.items[k]);
    }
    if (n > 1) {
      std::sort(cells_touched_.begin(), cells_touched_.end());
      cells_touched_.erase(std::unique(cells_touched_.begin(), cells_touched_.end()),
                           cells_touched_.end());
    }
    const std::size_t m = cells_touched_.size();
    measured_ += static_cast<std::int64_t>(m);
    rows_.clear();
    flags_.clear();
    for (int c : cells_touched_) {
      rows_.push_back(values_->cell[c]);
      flags_.push_back(values_->sliver[c]);
      flags_.push_back(values_->inverted[c]);
    }
    bool ok = true, defined = true;
    g_.touched.clear();
    for (std::size_t k = 0; k < m && defined; ++k) {
      const int c = cells_touched_[k];
      if (cell_dim(mesh_->cell_type(c)) != d) continue;
      measure_guarantee_cell(*mesh_, c, planar_, values_);
      ok = cell_keeps(b_, o_, c, *values_, rows_[k], flags_[2 * k + 1] != 0, &g_) && ok;
      defined = !(values_->inverted[c] && !flags_[2 * k + 1]);
    }
    double rise = 0;
    for (int mg : g_.touched) {
      rise += g_.change[mg];
      if (o_.means && g_.change[mg] < 0 && g_.sum[mg] + g_.change[mg] < g_.floor[mg]) ok = false;
    }
    *gain = defined && rise == rise ? rise : -std::numeric_limits<double>::infinity();
    // A rise above round-off: every kept move raises the score, so the passes end.
    const bool kept = keep && ok && rise > 1e-12 * static_cast<double>(m);
    if (kept) {
      for (int mg : g_.touched) g_.sum[mg] += g_.change[mg];
    } else {
      for (int j = 0; j < n; ++j)
        for (int a = 0; a < sd; ++a) mesh_->vertex(vs[j])[a] = from_[j * sd + a];
      for (std::size_t k = 0; k < m; ++k) {
        const int c = cells_touched_[k];
        values_->cell[c] = rows_[k];
        values_->sliver[c] = flags_[2 * k];
        values_->inverted[c] = flags_[2 * k + 1];
      }
    }
    for (int mg : g_.touched) g_.change[mg] = 0, g_.listed[mg] = 0;
    return kept;
  }

  // Cells measured so far (the work done).
  std::int64_t measured() const { return measured_; }

  // The shortest distance from v to another node of its cells.
  double shortest(int v) const {
    const int sd = mesh_->space_dim;
    double best = std::numeric_limits<double>::infinity();
    for (std::int64_t k = cells_.offsets[v]; k < cells_.offsets[v + 1]; ++k) {
      const int c = cells_.items[k];
      for (int i = 0; i < mesh_->cell_size(c); ++i) {
        const int u = mesh_->cell(c)[i];
        if (u == v) continue;
        double l2 = 0;
        for (int a = 0; a < sd; ++a) l2 += std::pow(mesh_->vertex(u)[a] - mesh_->vertex(v)[a], 2);
        best = std::min(best, std::sqrt(l2));
      }
    }
    return best;
  }

 private:
  Mesh* mesh_;
  const GuaranteeBaseline& b_;
  const GuaranteeOptions& o_;
  GuaranteeValues* values_;
  Adjacency cells_;
  bool planar_;
  int d_;  // the mesh's dimension (Mesh::dim() is O(cells))
  Groups g_;
  std::vector<std::array<double, kNumGuaranteeMeasures>> rows_;
  std::vector<std::uint8_t> flags_;
  std::vector<double> from_;
  std::vector<int> cells_touched_;
  std::int64_t measured_ = 0;
};

}  // namespace

int accept_vertex_moves(Mesh* mesh, const std::vector<double>& target,
                        const GuaranteeBaseline& baseline, const GuaranteeOptions& guarantees,
                        const VertexMoveOptions& options, GuaranteeValues* values) {
  const int sd = mesh->space_dim;
  if (mesh->dim() < 2 || target.size() != mesh->coords.size()) return 0;
  MoveJudge judge(mesh, baseline, guarantees, values);
  int kept = 0;
  for (int pass = 0; pass < options.passes; ++pass) {
    int kept_in_pass = 0;
    for (int v = 0; v < mesh->num_vertices(); ++v) {
      if (!options.only.empty() && !options.only[v]) continue;
      const double* x = mesh->vertex(v);
      const double* y = &target[static_cast<std::size_t>(v) * sd];
      bool moves = false;
      for (int a = 0; a < sd; ++a) moves |= x[a] != y[a];
      if (!moves) continue;
      const bool whole = !options.whole_only.empty() && options.whole_only[v];
      double from[3] = {0, 0, 0}, to[3] = {0, 0, 0}, gain;
      for (int a = 0; a < sd; ++a) from[a] = x[a];
      for (double f = 1; f >= 0.25 && !(whole && f < 1); f *= 0.5) {
        for (int a = 0; a < sd; ++a) to[a] = f < 1 ? from[a] + f * (y[a] - from[a]) : y[a];
        if (judge.try_position(v, to, true, &gain)) {
          ++kept_in_pass;
          break;
        }
      }
    }
    kept += kept_in_pass;
    if (kept_in_pass == 0) break;
  }
  return kept;
}

namespace {

// Unit direction number dir of the 26 axis and diagonal directions (0..26; 13 is none, and in
// 2D only those with z = 0). False for the ones that do not count.
bool direction(int dir, int sd, double* u) {
  if (dir == 13 || (sd == 2 && dir / 9 != 1)) return false;
  u[0] = dir % 3 - 1, u[1] = (dir / 3) % 3 - 1, u[2] = dir / 9 - 1;
  const double l = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (int a = 0; a < 3; ++a) u[a] /= l;
  return true;
}

}  // namespace

namespace {

// One uphill move of the n (1 or 2) vertices vs translated together, if any: along the central-
// difference gradient of their cells' score (1e-4 of the shortest edge h), steps h/8, h/32,
// h/128; at a kink of the measures (a minimum over corners: both sides of every axis lower the
// score) the gradient says nothing, and the axis and diagonal directions are tried at h/8, h/32.
bool climb_group(Mesh* mesh, MoveJudge* judge, const int* vs, int n) {
  const int sd = mesh->space_dim;
  double h = std::numeric_limits<double>::infinity();
  for (int j = 0; j < n; ++j) h = std::min(h, judge->shortest(vs[j]));
  if (!(h > 0) || !std::isfinite(h)) return false;
  double x[6] = {0, 0, 0, 0, 0, 0}, trial[6], grad[3] = {0, 0, 0}, up, down, gain;
  for (int j = 0; j < n; ++j)
    for (int a = 0; a < sd; ++a) x[j * sd + a] = mesh->vertex(vs[j])[a];
  auto place = [&](const double* u, double s) {
    for (int j = 0; j < n; ++j)
      for (int a = 0; a < sd; ++a) trial[j * sd + a] = x[j * sd + a] + s * u[a];
  };
  const double e = 1e-4 * h;
  bool defined = true;
  for (int a = 0; a < sd && defined; ++a) {
    double u[3] = {0, 0, 0};
    u[a] = 1;
    place(u, e);
    judge->try_positions(vs, n, trial, false, &up);
    place(u, -e);
    judge->try_positions(vs, n, trial, false, &down);
    defined = std::isfinite(up) && std::isfinite(down);
    grad[a] = (up - down) / (2 * e);
  }
  double norm = 0;
  for (int a = 0; a < sd; ++a) norm += grad[a] * grad[a];
  norm = std::sqrt(norm);
  if (defined && norm > 0) {
    for (int a = 0; a < sd; ++a) grad[a] /= norm;
    for (double s = h / 8; s >= h / 128; s /= 4) {
      place(grad, s);
      if (judge->try_positions(vs, n, trial, true, &gain)) return true;
    }
  }
  for (int dir = 0; dir < 27; ++dir) {
    double u[3];
    if (!direction(dir, sd, u)) continue;
    for (double s = h / 8; s >= h / 32; s /= 4) {
      place(u, s);
      if (judge->try_positions(vs, n, trial, true, &gain)) return true;
    }
  }
  return false;
}

}  // namespace

int climb_vertex_measures(Mesh* mesh, const std::vector<char>& movable,
                          const GuaranteeBaseline& baseline, const GuaranteeOptions& guarantees,
                          int passes, std::int64_t budget, GuaranteeValues* values) {
  if (mesh->dim() < 2 || static_cast<int>(movable.size()) != mesh->num_vertices()) return 0;
  MoveJudge judge(mesh, baseline, guarantees, values);
  std::vector<std::array<std::int32_t, 2>> edges;
  for (const auto& e : mesh_edges(*mesh))
    if (movable[e[0]] && movable[e[1]]) edges.push_back(e);
  std::vector<char> stuck(mesh->num_vertices(), 0);
  int kept = 0;
  for (int pass = 0; pass < passes && judge.measured() < budget; ++pass) {
    int kept_in_pass = 0;
    for (int v = 0; v < mesh->num_vertices() && judge.measured() < budget; ++v) {
      if (!movable[v]) continue;
      const bool moved = climb_group(mesh, &judge, &v, 1);
      stuck[v] = !moved;
      kept_in_pass += moved;
    }
    // Then the edges between two vertices that could not move alone, both ends translated
    // together (the copies of one vertex in two extruded layers keep their prism right).
    for (std::size_t k = 0; k < edges.size() && judge.measured() < budget; ++k) {
      const int vs[2] = {edges[k][0], edges[k][1]};
      if (!stuck[vs[0]] || !stuck[vs[1]]) continue;
      if (climb_group(mesh, &judge, vs, 2)) ++kept_in_pass, stuck[vs[0]] = stuck[vs[1]] = 0;
    }
    kept += kept_in_pass;
    if (kept_in_pass == 0) break;
  }
  return kept;
}

}  // namespace tmop
