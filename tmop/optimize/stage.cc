#include "tmop/optimize/stage.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <utility>

#include "tmop/geometry/boundary_constraints.h"
#include "tmop/metric/untangle.h"
#include "tmop/optimize/locality_order.h"
#include "tmop/optimize/partitioned_stage.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/stage_callback.h"
#include "tmop/optimize/stage_problem.h"
#include "tmop/optimize/stage_spec.h"
#include "tmop/quality/parallel_for.h"

namespace tmop {
namespace {

std::string list_cells(const std::vector<int>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < 10; ++i)
    s += (i ? ", " : "") + std::to_string(cells[i]);
  if (cells.size() > 10) s += ", ... (" + std::to_string(cells.size()) + " in all)";
  return s;
}

// Surface meshes: per-cell tangent frames from the geometry's normals at the cell's corners, as
// the cell's own patch sees them (a cell with no geometry normal at its corners: its own plane).
void update_surface_frames(const Mesh& mesh, const BoundaryConstraints& boundary, Frames* frames) {
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const int k = cell_info(mesh.cell_type(c)).num_corners;
    double n[3] = {0, 0, 0};
    for (int i = 0; i < k; ++i) {
      const int v = mesh.cell(c)[i];
      double nv[3];
      if (boundary.cell_normal(c, i, mesh.cell(c), mesh.vertex(v), nv))
        for (int a = 0; a < 3; ++a) n[a] += nv[a];
    }
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
      own_frame(mesh, c, frames->F.data() + 6 * c);  // not own_frames: a pass per such cell
      continue;
    }
    frame_from_normal(n, frames->F.data() + 6 * c);
  }
}

// What the whole-mesh solve tells the stage's summary.
struct WholeSolveInfo {
  std::string reason;  // why the (last) solve stopped
  bool nothing_free = false;
  int untangle_rounds = 0;
  // Untangling that ended worse than an earlier round (or its start) returned that round's
  // state: the round (0 = the start) and the last round's inverted count.
  int kept_round = -1, last_round_inverted = 0;
  bool spread = false;  // stopped early: the tangle spread (StageSpec::untangle_spread_rounds)
};

// The whole-mesh solve: one ceres::Problem over every free vertex, solved once, or in surface
// frame rounds, or on untangling's eps schedule. Leaves the state it keeps in `mesh`; a
// failure leaves the mesh for the caller to restore.
Status solve_whole(Mesh* mesh, StageContext& ctx, const IdealTable& table,
                   const UntangleMetric* untangle_metric,
                   std::chrono::steady_clock::time_point start, std::vector<char>* in_problem,
                   StageResult* result, WholeSolveInfo* info) {
  const StageSpec& spec = *ctx.spec;
  const int d = ctx.d;
  ceres::Problem problem(ProblemAssembly::problem_options());
  ProblemAssembly assembly(ctx, *mesh, table);
  {
    // Residual blocks in space-filling-curve order of their cells: Ceres numbers the parameter
    // blocks by first appearance, so neighbouring blocks touch neighbouring columns of J and
    // the products of its CGNR stay in cache (docs/benchmarks.md).
    const std::vector<std::int32_t> order = locality_order(*mesh, ctx.point_cell);
    assembly.add(
        order, [&](int v) { return !ctx.fixed[v]; }, [&](int v) { return mesh->vertex(v); },
        [&](int v) { (*in_problem)[v] = 1; }, &problem);
  }
  std::vector<int> free_vertices;
  for (int v = 0; v < mesh->num_vertices(); ++v) {
    if (!(*in_problem)[v]) continue;
    if (ctx.fixed[v]) {
      problem.SetParameterBlockConstant(mesh->vertex(v));
      continue;
    }
    free_vertices.push_back(v);
    // Ceres takes a non-const pointer but only calls const methods of a manifold.
    if (spec.boundary && spec.boundary->manifold(v))
      problem.SetManifold(mesh->vertex(v),
                          const_cast<ceres::Manifold*>(spec.boundary->manifold(v)));
  }
  result->num_free_vertices = static_cast<int>(free_vertices.size());
  if (free_vertices.empty()) {
    info->nothing_free = true;
    return Status::Ok();
  }
  const int threads = spec.solver.threads > 0
                          ? spec.solver.threads
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  ceres::Solver::Options so = stage_solver_options(
      spec, d, static_cast<int>(free_vertices.size()) * d, threads, &result->linear_solver);
  StageCallback callback(
      mesh, spec, table, ctx.frames, free_vertices, ctx.shortest, ctx.num_elements,
      [&] { return stage_objective(*mesh, ctx); }, result);
  callback.set_power_scale(result->power_scale);
  so.callbacks.push_back(&callback);

  ceres::Solver::Summary summary;
  // The stage's caps hold over all its solves (untangling and ctx.surface frame rounds): each solve
  // gets what is left of the iterations and the time. Returns false when nothing is left.
  // Surface frame rounds under a power may use 4x the iterations (surface_budget below).
  const int stage_iterations =
      spec.solver.max_iterations * (ctx.surface && !spec.untangle && ctx.powered ? 4 : 1);
  auto budget = [&]() {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const int iterations_left = stage_iterations - result->iterations;
    if (result->solves > 0 && (iterations_left <= 0 || elapsed >= spec.solver.max_seconds))
      return false;
    so.max_num_iterations = std::min(so.max_num_iterations, std::max(iterations_left, 0));
    so.max_solver_time_in_seconds = std::max(spec.solver.max_seconds - elapsed, 1e-9);
    return true;
  };
  auto solve = [&]() {
    StageResult::Times& t = result->times;
    if (result->solves == 0)
      t.setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ceres::Solve(so, &problem, &summary);
    t.preprocessor += summary.preprocessor_time_in_seconds;
    t.minimizer += summary.minimizer_time_in_seconds;
    t.residual_evaluation += summary.residual_evaluation_time_in_seconds;
    t.jacobian_evaluation += summary.jacobian_evaluation_time_in_seconds;
    t.linear_solver += summary.linear_solver_time_in_seconds;
    t.residual_evaluations += summary.num_residual_evaluations;
    t.jacobian_evaluations += summary.num_jacobian_evaluations;
    t.linear_solves += summary.num_linear_solves;
    for (const ceres::IterationSummary& it : summary.iterations) {
      if (it.iteration == 0) continue;  // the starting point: no step
      t.linear_iterations += it.linear_solver_iterations;
      ++t.recorded_linear_solves;
    }
    if (std::getenv("TMOP_CERES_REPORT"))
      std::fprintf(stderr, "%s\n", summary.FullReport().c_str());
    ++result->solves;
    result->iterations += static_cast<int>(summary.iterations.size()) - 1;
    return summary.termination_type != ceres::FAILURE;
  };
  // Untangling that ends worse than an earlier round (or its start) returns that round's state:
  // the round (0 = the start) and the last round's inverted count.
  // Surface meshes solve in rounds: the tangent frames are held fixed during a solve and
  // refreshed at the new positions after it. A ctx.barrier round is kept only if no cell is folded
  // in the refreshed frames, i.e. against the ctx.surface where the cell now lies: a long solve can
  // carry cells across curved parts of the ctx.surface in frames that went stale (lat-long sphere
  // sliding on its own triangulation: 36 triangles folded inward). A round that folds is undone
  // and redone with half the iterations; rounds end when a solve converges within its cap
  // (under a power: and lowered the objective by at most 0.1 %), or after the budget.
  const bool surface_rounds = ctx.surface && !spec.untangle;
  const int frame_rounds = ctx.surface ? std::max(1, surface_rounds ? spec.surface_max_rounds
                                                                    : spec.surface_frame_rounds)
                                       : 1;
  int round_cap = surface_rounds ? std::max(1, spec.surface_round_iterations) : 0;
  int surface_iterations = 0;
  // The iteration budget of all rounds. A power objective settles over more frame rounds
  // (sphere of 16 x 32 triangles: worst quality 0.24 within max_iterations, 0.27 within 4x).
  const int surface_budget = spec.solver.max_iterations * (ctx.powered ? 4 : 1);
  std::vector<double> round_start;
  for (int frame_round = 0; frame_round < frame_rounds; ++frame_round) {
    if (spec.solver.progress.cancelled()) break;  // no further round after a cancel
    if (frame_round > 0) {
      const std::vector<double> previous_frames = ctx.frames.F;
      update_surface_frames(*mesh, *spec.boundary, &ctx.frames);
      if (ctx.barrier &&
          !(min_target_det(*mesh, ctx.point_cell, ctx.G[0], nullptr, ctx.frames) > 0)) {
        ctx.frames.F = previous_frames;
        if (!surface_rounds || round_cap <= 1) {
          if (surface_rounds) mesh->coords = round_start;
          break;
        }
        mesh->coords = round_start;  // where previous_frames were made: the same frames again
        round_cap /= 2;
      } else if (surface_rounds && ((summary.termination_type != ceres::NO_CONVERGENCE &&
                                     (!ctx.powered || summary.initial_cost - summary.final_cost <=
                                                          1e-3 * summary.initial_cost)) ||
                                    surface_iterations >= surface_budget)) {
        break;  // converged (or out of iterations) in frames that are still valid
      }
    }
    if (surface_rounds) round_start = mesh->coords;
    if (spec.untangle) {
      // eps schedule: after each solve, sigma = max(1 - E_final / E_initial, sigma_min) (the
      // relative decrease the solve achieved, at least sigma_min),
      // mu = (1 - sigma) chi(min det, eps); eps = 2 sqrt(mu (mu - min det)) while min det < mu.
      std::vector<std::unique_ptr<UntangleMetric>> metrics;  // alive while costs point to them
      const double theta = untangle_metric->theta();
      double eps = untangle_metric->eps();
      so.max_num_iterations = spec.untangle_round_iterations;
      // The best state reached: fewest inverted cells at the stage's points, then the largest
      // min det. The schedule can end worse than it started (eps driven towards 0 around cells
      // that cannot be repaired drags their neighbours over); the stage then returns that state.
      std::vector<int> now_bad;
      double det_now = min_target_det(*mesh, ctx.point_cell, ctx.G[0], &now_bad, ctx.frames);
      std::size_t best_bad = now_bad.size();
      double best_det = det_now;
      int best_round = 0;
      std::vector<double> best_coords = mesh->coords;
      const int max_rounds = det_now > 0 ? 0 : spec.untangle_max_rounds;
      int solved_rounds = 0;
      int spreading = 0;  // rounds in a row that spread the tangle (StageSpec)
      const std::vector<int> start_bad = now_bad;
      std::size_t fewest_left = start_bad.size();  // of them still inverted after a round
      for (int round = 0; round < max_rounds; ++round) {
        metrics.push_back(std::make_unique<UntangleMetric>(d, eps, theta));
        for (SamplePointCost& cost : assembly.costs()) cost.set_metric(0, metrics.back().get());
        so.max_num_iterations = spec.untangle_round_iterations;
        if (spec.solver.progress.cancelled() || !budget()) break;
        if (!solve()) return Status::Failure("solver failed: " + summary.message);
        result->final_eps = eps;
        solved_rounds = info->untangle_rounds = round + 1;
        const double det_min =
            min_target_det(*mesh, ctx.point_cell, ctx.G[0], &now_bad, ctx.frames);
        det_now = det_min;
        if (det_min > 0) break;
        if (now_bad.size() < best_bad || (now_bad.size() == best_bad && det_min > best_det)) {
          best_bad = now_bad.size();
          best_det = det_min;
          best_round = round + 1;
          best_coords = mesh->coords;
          spreading = 0;
        } else if (spec.untangle_patience > 0 && round + 1 - best_round >= spec.untangle_patience) {
          break;
        } else if (spec.untangle_spread_rounds > 0 &&
                   static_cast<double>(now_bad.size()) >=
                       spec.untangle_spread_factor * static_cast<double>(best_bad)) {
          // The start's inverted cells: were more of them repaired than before?
          std::size_t left = 0;
          for (int c : start_bad) left += std::binary_search(now_bad.begin(), now_bad.end(), c);
          spreading = left < fewest_left ? 0 : spreading + 1;
          fewest_left = std::min(fewest_left, left);
          if (spreading >= spec.untangle_spread_rounds) {
            info->spread = true;
            break;
          }
        } else {
          spreading = 0;
        }
        const double energy = summary.final_cost;
        const double sigma = std::max(1 - energy / summary.initial_cost, spec.untangle_sigma_min);
        const double mu = (1 - sigma) * UntangleMetric::chi(det_min, eps);
        eps = det_min < mu ? 2 * std::sqrt(mu * (mu - det_min)) : 1e-12;
        if (std::getenv("TMOP_DEBUG_EPS"))
          std::fprintf(stderr, "round %d E %g det_min %g mu %g eps %g inverted %zu\n", round,
                       energy, det_min, mu, eps, now_bad.size());
      }
      if (!(det_now > 0) && best_round < solved_rounds) {
        info->kept_round = best_round;
        info->last_round_inverted = static_cast<int>(now_bad.size());
        mesh->coords = best_coords;
      }
    } else {
      // One solve (a power mean too: its loss keeps the exact model, power_loss.h); ctx.surface
      // rounds cap it and go on in the next frame round.
      so.max_num_iterations = spec.solver.max_iterations;
      if (surface_rounds) so.max_num_iterations = std::min(so.max_num_iterations, round_cap);
      so.function_tolerance = spec.solver.function_tolerance;
      if (surface_rounds && !budget()) break;
      if (!solve()) return Status::Failure("solver failed: " + summary.message);
      if (surface_rounds) surface_iterations += static_cast<int>(summary.iterations.size()) - 1;
    }
  }

  info->reason = callback.reason().empty() ? summary.message : callback.reason();
  return Status::Ok();
}

}  // namespace

IterationRecord measure_mesh(const Mesh& mesh, SampleRule rule) {
  const int d = mesh.dim();
  if (d < 2 || (mesh.space_dim != d && d != 2)) return IterationRecord();
  IdealTable table(validity_rule(rule), d);
  return measure(mesh, table, own_frames(mesh));
}

Status optimize_stage(Mesh* mesh, const StageSpec& spec, StageResult* result) {
  *result = StageResult();
  result->name = spec.name;
  const auto start = std::chrono::steady_clock::now();
  const int d = mesh->dim();
  Status checked = check_stage_spec(*mesh, spec);
  if (!checked.ok()) return checked;
  StageContext ctx;
  ctx.spec = &spec;
  ctx.d = d;
  ctx.surface = mesh->space_dim != d;
  checked = stage_fixed_vertices(*mesh, spec, &ctx.fixed);
  if (!checked.ok()) return checked;

  // Sample points: the rule's canonical set, then the stage's extra points. Untangling always
  // samples at the corners (validity_rule): an energy that sees only centroids or Gauss points
  // cannot unfold a corner.
  const SampleRule rule = spec.untangle ? validity_rule(spec.rule) : spec.rule;
  SampleSet points = canonical_sample_set(*mesh, rule);
  for (std::size_t k = 0; k < spec.extra_points.size(); ++k) {
    const int c = spec.extra_points.cell[k];
    if (c < 0 || c >= mesh->num_cells() || !mesh->is_element(c, d))
      return Status::Failure("extra sample point " + std::to_string(k) + ": cell " +
                             std::to_string(c) + " is not an element");
    const double w = spec.extra_points.weight[k];
    if (!(std::isfinite(w) && w >= 0))
      return Status::Failure("extra sample point " + std::to_string(k) +
                             ": its weight is negative or not finite");
    points.add(c, &spec.extra_points.xi[3 * k], w);
  }
  ctx.num_elements = mesh->num_elements();
  const std::size_t P = points.cell.size();
  for (const TermSpec& t : spec.terms) {
    if (!t.weights.empty() && t.weights.size() != P)
      return Status::Failure("trade-off weights: " + std::to_string(P) +
                             " expected (one per sample point), got " +
                             std::to_string(t.weights.size()));
    for (std::size_t p = 0; p < t.weights.size(); ++p)
      if (t.weights[p] < 0 || !std::isfinite(t.weights[p]))
        return Status::Failure("trade-off weight of sample point " + std::to_string(p) +
                               " is negative or not finite");
  }
  result->num_elements = ctx.num_elements;
  result->num_sample_points = static_cast<int>(P);

  // Solve in normalised coordinates; keep the original to restore on failure.
  const std::vector<double> original = mesh->coords;
  const CoordinateFrame frame = spec.boundary ? spec.frame : normalizing_frame(*mesh);
  if (!(frame.length > 0)) return Status::Failure("the mesh has no edge of positive length");
  to_frame(frame, mesh);
  const std::vector<double> mapped_start = mesh->coords;  // to tell the vertices that moved
  if (ctx.surface) {
    ctx.frames.F.assign(6 * mesh->num_cells(), 0);
    update_surface_frames(*mesh, *spec.boundary, &ctx.frames);
  }
  auto fail = [&](const std::string& message) {
    mesh->coords = original;
    return Status::Failure(message);
  };
  element_edge_lengths(*mesh, &ctx.shortest);

  // Targets -> G per term per point (GTable: identical blocks shared).
  Status targets = build_stage_targets(*mesh, spec, points, frame, &ctx.G);
  if (!targets.ok()) return fail(targets.message());
  ctx.point_cell = std::move(points.cell);
  ctx.point_weight = std::move(points.weight);
  // The points' reference coordinates live on in G only: released before Ceres allocates
  // (24 MB at 1M tets).
  std::vector<double>().swap(points.xi);

  // Validity (inverted counts, the barrier's start check) is judged at points that include
  // every corner, whatever the stage samples (validity_rule).
  IdealTable table(validity_rule(spec.rule), d);
  // The three read-only passes over the mesh run side by side (1M tets: 0.47 s -> 0.25 s).
  const bool concurrent = spec.solver.threads != 1;
  IterationRecord before;
  std::vector<int> bad;
  double initial_excess = 0;  // the power objective's scale comes from it (below)
  side_by_side(
      concurrent, [&] { before = measure(*mesh, table, ctx.frames); },
      [&] {
        result->initial_objective = stage_objective(*mesh, ctx, &initial_excess);
        result->min_det_before = min_target_det(*mesh, ctx.point_cell, ctx.G[0], &bad, ctx.frames);
      });
  result->inverted_before = before.inverted;
  result->min_quality_before = before.min_quality;
  for (const TermSpec& t : spec.terms) ctx.barrier |= t.metric->barrier();
  if (ctx.barrier && bad.empty() && before.inverted > 0)
    bad = inverted_cells(*mesh, table, ctx.frames);
  if (ctx.barrier && !bad.empty())
    return fail("barrier metric on an inverted mesh (untangle first): inverted cells " +
                list_cells(bad));
  const UntangleMetric* untangle_metric =
      spec.untangle ? dynamic_cast<const UntangleMetric*>(spec.terms[0].metric.get()) : nullptr;
  if (spec.untangle && !untangle_metric)
    return fail("an untangling stage needs an UntangleMetric as its first term");
  if (spec.untangle) {
    // T at a sample point depends only on the nodes whose G_i there is not zero (a quadratic
    // cell's corner point does not see the mid nodes of the edges away from that corner). An
    // inverted point whose such nodes are all fixed cannot be repaired by moving nodes.
    std::vector<int> stuck;
    for (std::size_t p = 0; p < P; ++p) {
      const int c = ctx.point_cell[p];
      if (!stuck.empty() && stuck.back() == c) continue;
      const int n = mesh->cell_size(c);
      const double* G = ctx.G[0].at(p);
      double g_max = 0;
      for (int k = 0; k < n * d; ++k) g_max = std::max(g_max, std::abs(G[k]));
      bool all_fixed = true;
      for (int i = 0; i < n && all_fixed; ++i) {
        bool seen = false;
        for (int b = 0; b < d; ++b) seen |= std::abs(G[i * d + b]) > 1e-12 * g_max;
        all_fixed = !seen || ctx.fixed[mesh->cell(c)[i]] != 0;
      }
      if (!all_fixed) continue;
      double T[9];
      compute_T(n, d, *mesh, mesh->cell(c), G, T, ctx.frames.cell(c));
      if (!(det_d(T, d) > 0)) stuck.push_back(c);
    }
    std::sort(stuck.begin(), stuck.end());  // a cell's points need not be contiguous
    stuck.erase(std::unique(stuck.begin(), stuck.end()), stuck.end());
    // Only the default fixed boundary can be released: sliding keeps corners and feature
    // curves, and a caller's own flags are its choice.
    if (!stuck.empty())
      return fail("cannot untangle: " + std::to_string(stuck.size()) + " cells inverted with " +
                  (spec.fixed.empty() && !spec.boundary
                       ? "every node on the fixed boundary (try --boundary=slide): "
                       : "every node fixed: ") +
                  list_cells(stuck));
  }
  // A power objective's scale m is a fraction of the input's mean excess per element
  // (stage.h); an exact input (excess 0) has nothing to weigh: any positive scale will do, 1.
  ctx.powered = spec.power > 1 && !spec.untangle;
  if (ctx.powered) {
    const double scaled = spec.power_scale_fraction * initial_excess;
    if (std::isfinite(scaled) && scaled > 0) ctx.power_scale = scaled;
  }
  result->power_scale = ctx.powered ? ctx.power_scale : 0.0;
  // Barrier stages sampled away from the corners guard the corners (SamplePointCost::set_guard).
  ctx.guard = ctx.barrier && validity_rule(rule) != rule;

  std::vector<char> in_problem(mesh->num_vertices(), 0);
  WholeSolveInfo info;
  const bool partitioned = use_partitions(*mesh, spec);
  Status solved =
      partitioned
          ? solve_partitioned(mesh, ctx, table, start, &in_problem, result, &info.reason)
          : solve_whole(mesh, ctx, table, untangle_metric, start, &in_problem, result, &info);
  if (!solved.ok()) return fail(solved.message());
  if (partitioned && result->num_free_vertices == 0) info.nothing_free = true;
  if (info.nothing_free) {
    result->final_objective = result->initial_objective;
    result->inverted_after = before.inverted;
    result->min_quality_after = before.min_quality;
    result->termination = "nothing to optimize: every vertex is fixed";
    mesh->coords = original;
    return Status::Ok();
  }

  // Ceres leaves the best parameters in place; the callback may have seen a later state.
  IterationRecord after;
  side_by_side(
      concurrent, [&] { after = measure(*mesh, table, ctx.frames); },
      [&] {
        result->min_det_after =
            min_target_det(*mesh, ctx.point_cell, ctx.G[0], &result->inverted_cells, ctx.frames);
        result->final_objective = stage_objective(*mesh, ctx);
      });
  result->inverted_after = after.inverted;
  result->min_quality_after = after.min_quality;
  result->termination = info.reason;
  if (spec.untangle) {
    char eps_text[32];
    std::snprintf(eps_text, sizeof eps_text, "%.3g", result->final_eps);
    const int inverted = static_cast<int>(result->inverted_cells.size());
    result->termination =
        result->inverted_cells.empty()
            ? (info.untangle_rounds == 0 ? std::string("nothing inverted: no untangling needed")
                                         : "untangled in " + std::to_string(info.untangle_rounds) +
                                               " eps rounds (final eps " + eps_text + ")")
            : "still inverted after " + std::to_string(info.untangle_rounds) + " eps rounds" +
                  (info.spread ? std::string(" (stopped: the tangle spread)") : std::string()) +
                  (info.kept_round < 0 || info.last_round_inverted == inverted
                       ? std::string()
                       : "; the best state kept (" +
                             (info.kept_round == 0 ? std::string("the start")
                                                   : "round " + std::to_string(info.kept_round)) +
                             ": " + std::to_string(inverted) +
                             " cells inverted at sample points, the last round " +
                             std::to_string(info.last_round_inverted) + ")");
  }
  // Mapping back is not bit-exact: vertices that were never free or did not move keep their
  // input coordinates (a stage that moves nothing returns the input's bits).
  std::vector<char> keep(mesh->num_vertices());
  const int sd = mesh->space_dim;
  for (int v = 0; v < mesh->num_vertices(); ++v)
    keep[v] = ctx.fixed[v] || !in_problem[v] ||
              std::equal(mesh->vertex(v), mesh->vertex(v) + sd, &mapped_start[std::size_t(v) * sd]);
  from_frame(frame, mesh);
  for (int v = 0; v < mesh->num_vertices(); ++v)
    if (keep[v]) std::copy_n(&original[std::size_t(v) * sd], sd, mesh->vertex(v));
  if (ctx.barrier && after.inverted > 0)  // cannot happen: every accepted step was evaluated
    return fail("internal error: a barrier stage produced inverted elements");
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
