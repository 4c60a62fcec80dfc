#include "tmop/recipes/guard.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "tmop/mesh/topology.h"
#include "tmop/recipes/vertex_moves.h"

namespace tmop {

namespace {

// Puts the vertices of the cells that break a guarantee back at their input positions, again on
// the cells that break one then (a put-back vertex changes its neighbours), at most `passes`
// times, without a solve. True when every guarantee then holds; *values is the mesh's.
bool revert_violators(Mesh* mesh, const std::vector<double>& original,
                      const GuaranteeBaseline& baseline, const GuardOptions& options, int passes,
                      GuaranteeValues* values) {
  GuaranteeOptions g = options.guarantees;
  g.mean_cover = 1;
  for (int pass = 0; pass < passes; ++pass) {
    const std::vector<int> bad = guard_violators(baseline, *values, g);
    if (bad.empty()) return true;
    int moved = 0;
    for (int c : bad)
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        const std::size_t v = static_cast<std::size_t>(mesh->cell(c)[i]) * mesh->space_dim;
        for (int a = 0; a < mesh->space_dim; ++a) {
          moved += mesh->coords[v + a] != original[v + a];
          mesh->coords[v + a] = original[v + a];
        }
      }
    if (moved == 0) return false;
    *values = guarantee_values(*mesh, options.threads);
  }
  return guard_violators(baseline, *values, g).empty();
}

// The vertex-by-vertex repair (vertex_moves.h), from mesh->coords (guarantee values `kept`):
// the moves towards `target` (the first round's result) kept one vertex at a time where they keep
// every guarantee, then the interior free vertices whose move was not kept moved uphill on the
// measures. Only the `held` vertices move (empty: all). Where the violators are most of the mesh
// (pripyrtet's wedges and pyramids), putting them back gives the input back; this keeps the good
// part of the move. Returns the result's score and its coordinates in *out (-inf when nothing
// moved); mesh->coords is restored.
double repair_by_vertices(Mesh* mesh, const std::vector<double>& target,
                          const std::vector<char>& free_at_start, const std::vector<char>& held,
                          const GuaranteeBaseline& baseline, const GuardOptions& options,
                          GuaranteeValues kept, std::vector<double>* out) {
  const std::vector<double> start = mesh->coords;
  // Whole moves only where a vertex may slide (a part of its move leaves its curve or surface):
  // the boundary, or every vertex of a surface mesh; those do not climb either.
  VertexMoveOptions moves;
  moves.whole_only = mesh->space_dim != mesh->dim() ? std::vector<char>(mesh->num_vertices(), 1)
                                                    : boundary_vertex_mask(*mesh);
  moves.only = held;
  int changed = accept_vertex_moves(mesh, target, baseline, options.guarantees, moves, &kept);
  std::vector<char> climb(mesh->num_vertices(), 0);
  int climbers = 0;
  for (int v = 0; v < mesh->num_vertices(); ++v) {
    if (free_at_start[v] == 0 || moves.whole_only[v] || (!held.empty() && !held[v])) continue;
    for (int a = 0; a < mesh->space_dim && !climb[v]; ++a) {
      const std::size_t i = static_cast<std::size_t>(v) * mesh->space_dim + a;
      climb[v] = mesh->coords[i] != target[i];
    }
    climbers += climb[v];
  }
  // Bounded work: about a second plus 16 cell measures per cell.
  const std::int64_t budget = 1000000 + 16 * static_cast<std::int64_t>(mesh->num_cells());
  if (climbers > 0)
    changed += climb_vertex_measures(mesh, climb, baseline, options.guarantees, 4, budget, &kept);
  *out = mesh->coords;
  mesh->coords = start;
  return changed > 0 ? guarantee_score(baseline, kept) : -std::numeric_limits<double>::infinity();
}

}  // namespace

Status guarded_solve(Mesh* mesh, const GuaranteeBaseline& baseline, const GuardOptions& options,
                     std::vector<char> fixed, const GuardSolve& solve, RecipeResult* result) {
  const std::vector<double> original = mesh->coords;
  std::vector<char> free_at_start(fixed.size());
  for (std::size_t v = 0; v < fixed.size(); ++v) free_at_start[v] = !fixed[v];
  std::vector<double> weight;  // empty: 1 for every cell, until a soft round raises some
  result->guard_held_cells = 0;
  auto note = [&](const std::string& text) {
    if (!result->stages.empty()) result->stages.back().termination += "; " + text;
  };
  bool warm = false;  // this round starts from a warm start, not from the input
  // The best repaired result (no solve: violators put back, good vertex moves kept, climbed).
  // Kept only when it beats the input by more than the tolerance.
  std::vector<double> best;
  const double input_score =
      guarantee_score(baseline, baseline.input) + options.guarantees.tolerance;
  double best_score = input_score;
  std::vector<double> first_solved;  // the first round's result, when it broke a guarantee
  // The vertex-by-vertex repair (repair_by_vertices) from `start_values`' mesh (mesh->coords;
  // null: from the best repaired result, or the input), moving only the `held` vertices (empty:
  // all). A result that scores higher than its start and the best so far becomes the best;
  // mesh->coords is left at the start.
  auto repair = [&](const std::vector<char>& held, const GuaranteeValues* start_values) {
    if (first_solved.empty()) return;
    if (!start_values) mesh->coords = best.empty() ? original : best;
    GuaranteeValues kept = start_values   ? *start_values
                           : best.empty() ? baseline.input
                                          : guarantee_values(*mesh, options.threads);
    const double start_score = guarantee_score(baseline, kept);
    std::vector<double> out;
    const double score = repair_by_vertices(mesh, first_solved, free_at_start, held, baseline,
                                            options, std::move(kept), &out);
    if (score > std::max({best_score, input_score, start_score}))
      best = std::move(out), best_score = score;
  };
  for (int round = 0;; ++round) {
    Status s = solve(fixed, weight, round);
    if (options.progress.cancelled()) return Status::Cancelled("guard: cancelled");
    if (!s.ok() && warm) {
      // A start the stage refuses (e.g. a surface cell folded against the geometry's normal,
      // which the plane-wise validity check above cannot see): the round again from the input.
      mesh->coords = original;
      s = solve(fixed, weight, round);
    }
    warm = false;
    if (!s.ok()) {
      mesh->coords = original;
      return s;
    }
    if (!options.enabled) return Status::Ok();
    const GuaranteeValues values = guarantee_values(*mesh, options.threads);
    // Each round covers a fallen mean 4x more generously: the deficit otherwise only halves.
    GuaranteeOptions g = options.guarantees;
    for (int k = 0; k <= round; ++k) g.mean_cover *= 4;
    const std::vector<int> bad = guard_violators(baseline, values, g);
    if (bad.empty()) {
      // Rounds that ended by holding every vertex give the input back: an earlier round's
      // repaired result keeps the guarantees and some of the gain.
      if (mesh->coords == original) {
        repair({}, nullptr);
        mesh->coords = best.empty() ? original : best;
        if (!best.empty()) note("guard: an earlier round's repaired result kept");
      } else if (round > 0) {
        // The held vertices take the good part of their first-round move (vertex_moves.h).
        std::vector<char> held(fixed.size(), 0);
        for (std::size_t v = 0; v < fixed.size(); ++v) held[v] = fixed[v] && free_at_start[v];
        const std::vector<double> before = best;
        repair(held, &values);
        if (best != before) {
          mesh->coords = best;
          note("guard: the held vertices kept the good part of their moves");
        }
      }
      return Status::Ok();
    }
    {
      // This round's result with its violators put back: often most of the gain for a few
      // cells (a type mean that fell by 2e-4 on a 1,015-hex mesh), where holding the cells
      // and solving again moves the losses to their neighbours.
      const std::vector<double> solved = mesh->coords;
      if (first_solved.empty()) first_solved = solved;
      GuaranteeValues reverted = values;
      if (revert_violators(mesh, original, baseline, options, 8, &reverted)) {
        const double score = guarantee_score(baseline, reverted);
        if (score > std::max(best_score, input_score)) best = mesh->coords, best_score = score;
      }
      mesh->coords = solved;
    }
    if (options.verbose) {
      const std::vector<GuaranteeViolation> broken =
          check_guarantees(baseline, values, options.guarantees);
      for (std::size_t i = 0; i < broken.size() && i < 8; ++i)
        std::printf("guard round %d: %s\n", round, broken[i].message().c_str());
      std::printf("guard round %d: %zu cells held\n", round, bad.size());
    }
    result->guard_held_cells = static_cast<int>(bad.size());
    if (round < options.soft_rounds) {
      if (weight.empty()) weight.assign(mesh->num_cells(), 1.0);
      for (int c : bad) weight[c] *= options.soft_factor;
      note("guard: " + std::to_string(bad.size()) +
           " cells would break a guarantee, their shape weighted up");
      mesh->coords = original;
      continue;
    }
    int newly_fixed = 0;
    for (int c : bad)
      for (int i = 0; i < mesh->cell_size(c); ++i) {
        char& f = fixed[mesh->cell(c)[i]];
        newly_fixed += !f;
        f = 1;
      }
    if (newly_fixed > 0 && round < options.rounds) {
      note("guard: " + std::to_string(bad.size()) + " cells would break a guarantee, " +
           std::to_string(newly_fixed) + " more vertices held");
      // Warm start: the result with the held vertices back at their input positions, when that
      // mesh is valid (a barrier stage needs a valid start); else the input.
      for (int v = 0; v < mesh->num_vertices(); ++v)
        if (fixed[v])
          for (int a = 0; a < mesh->space_dim; ++a) {
            const std::size_t i = static_cast<std::size_t>(v) * mesh->space_dim + a;
            mesh->coords[i] = original[i];
          }
      const GuaranteeValues start = guarantee_values(*mesh, options.threads);
      bool valid = true;
      for (std::size_t c = 0; c < start.inverted.size() && valid; ++c)
        valid = !start.inverted[c] || baseline.input.inverted[c];
      warm = valid && options.warm_start;
      if (!warm) mesh->coords = original;
      continue;
    }
    const std::vector<double> last = mesh->coords;
    repair({}, nullptr);
    if (!best.empty()) {
      mesh->coords = best;
      note("guard: " + std::to_string(bad.size()) +
           " cells still broke a guarantee; kept an earlier round's repaired result");
      return Status::Ok();
    }
    // Out of rounds: step back towards the input along the last result's displacement.
    for (double t = 0.5; t >= 1.0 / 64; t *= 0.5) {
      for (std::size_t i = 0; i < last.size(); ++i)
        mesh->coords[i] = original[i] + t * (last[i] - original[i]);
      if (check_guarantees(baseline, guarantee_values(*mesh, options.threads), options.guarantees)
              .empty()) {
        note("guard: " + std::to_string(bad.size()) + " cells still broke a guarantee; kept " +
             std::to_string(t) + " of the step from the input");
        return Status::Ok();
      }
    }
    mesh->coords = original;
    note("guard: no result kept every guarantee: input mesh kept");
    return Status::Ok();
  }
}

}  // namespace tmop
