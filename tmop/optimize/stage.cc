#include "tmop/optimize/stage.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <limits>
#include <thread>
#include <unordered_map>
#include <utility>

#include "tmop/element/ideal_element.h"
#include "tmop/element/shape.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/topology.h"
#include "tmop/metric/untangle.h"
#include "tmop/optimize/g_table.h"
#include "tmop/optimize/locality_order.h"
#include "tmop/optimize/power_loss.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/sample_point_cost.h"
#include "tmop/optimize/stage_callback.h"
#include "tmop/optimize/stage_spec.h"
#include "tmop/quality/parallel_for.h"

namespace tmop {
namespace {

// Exact mean of sum_t c_t mu_t over elements (weights of a cell's points sum to 1); in the
// same pass, when `excess` is given, the mean of sum_t c_t (mu_t - mu_t,min).
double exact_objective(const Mesh& mesh, const StageSpec& spec, const std::vector<GTable>& G,
                       const std::vector<std::int32_t>& cells,
                       const std::vector<double>& point_weight, int num_elements,
                       const Frames& frames, double* excess = nullptr) {
  const int d = mesh.dim();
  double sum = 0, sum_min = 0;
  for (std::size_t p = 0; p < cells.size(); ++p) {
    const int c = cells[p];
    const int n = mesh.cell_size(c);
    for (std::size_t t = 0; t < spec.terms.size(); ++t) {
      const double c_t = spec.terms[t].weights.empty() ? 1.0 : spec.terms[t].weights[p];
      if (c_t == 0) continue;
      double T[9];
      compute_T(n, d, mesh, mesh.cell(c), G[t].at(p), T, frames.cell(c));
      const Metric& metric = *spec.terms[t].metric;
      sum += point_weight[p] * c_t * metric.value(T);
      sum_min += point_weight[p] * c_t * metric.min_value();
    }
  }
  if (excess) *excess = (sum - sum_min) / std::max(1, num_elements);
  return sum / std::max(1, num_elements);
}

// What a SamplePointCost is made of (stage.cc shares identical ones).
struct CostKey {
  int n, nt;
  const Metric* metric[kMaxTerms];
  const double* G[kMaxTerms];
  double w[kMaxTerms];
  bool operator==(const CostKey& o) const {
    if (n != o.n || nt != o.nt) return false;
    for (int k = 0; k < nt; ++k)
      if (metric[k] != o.metric[k] || G[k] != o.G[k] || w[k] != o.w[k]) return false;
    return true;
  }
};
struct CostKeyHash {
  std::size_t operator()(const CostKey& k) const {
    std::size_t h = std::hash<int>()(k.n * 8 + k.nt);
    for (int t = 0; t < k.nt; ++t) {
      h = h * 1000003 ^ std::hash<const void*>()(k.metric[t]);
      h = h * 1000003 ^ std::hash<const void*>()(k.G[t]);
      h = h * 1000003 ^ std::hash<double>()(k.w[t]);
    }
    return h;
  }
};

std::string list_cells(const std::vector<int>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < 10; ++i)
    s += (i ? ", " : "") + std::to_string(cells[i]);
  if (cells.size() > 10) s += ", ... (" + std::to_string(cells.size()) + " in all)";
  return s;
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
  const bool surface = mesh->space_dim != d;
  const bool dogleg = spec.solver.method == SolverOptions::Method::kDogleg;
  std::vector<char> fixed;
  checked = stage_fixed_vertices(*mesh, spec, &fixed);
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
  const int num_elements = mesh->num_elements();
  const std::vector<std::int32_t>& point_cell = points.cell;
  const std::vector<double>& point_weight = points.weight;
  const std::size_t P = point_cell.size();
  for (const TermSpec& t : spec.terms)
    if (!t.weights.empty() && t.weights.size() != P)
      return Status::Failure("trade-off weights: " + std::to_string(P) +
                             " expected (one per sample point), got " +
                             std::to_string(t.weights.size()));
  result->num_elements = num_elements;
  result->num_sample_points = static_cast<int>(P);

  // Solve in normalised coordinates; keep the original to restore on failure.
  const std::vector<double> original = mesh->coords;
  const CoordinateFrame frame = spec.boundary ? spec.frame : normalizing_frame(*mesh);
  if (!(frame.length > 0)) return Status::Failure("the mesh has no edge of positive length");
  to_frame(frame, mesh);
  const std::vector<double> mapped_start = mesh->coords;  // to tell the vertices that moved
  // Surface meshes: per-cell tangent frames from the geometry's normals at the cell's corners.
  Frames frames;
  auto update_frames = [&]() {
    for (int c = 0; c < mesh->num_cells(); ++c) {
      if (!mesh->is_element(c, d)) continue;
      const int k = cell_info(mesh->cell_type(c)).num_corners;
      double n[3] = {0, 0, 0};
      for (int i = 0; i < k; ++i) {
        const int v = mesh->cell(c)[i];
        double nv[3];
        if (spec.boundary->normal(v, mesh->vertex(v), nv))
          for (int a = 0; a < 3; ++a) n[a] += nv[a];
      }
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
        const Frames own = own_frames(*mesh);  // no geometry normal here: the cell's own plane
        std::copy(own.cell(c), own.cell(c) + 6, frames.F.data() + 6 * c);
        continue;
      }
      frame_from_normal(n, frames.F.data() + 6 * c);
    }
  };
  if (surface) {
    frames.F.assign(6 * mesh->num_cells(), 0);
    update_frames();
  }
  auto fail = [&](const std::string& message) {
    mesh->coords = original;
    return Status::Failure(message);
  };
  std::vector<double> shortest;
  element_edge_lengths(*mesh, &shortest);

  // Targets -> G per term per point (GTable: identical blocks shared).
  std::vector<GTable> G(spec.terms.size());
  for (std::size_t t = 0; t < spec.terms.size(); ++t) {
    TargetSpec target = spec.terms[t].target;
    Mesh reference_copy;
    if ((target.type == TargetType::kReference || target.type == TargetType::kComposed) &&
        target.reference) {
      reference_copy = *target.reference;
      if (reference_copy.num_vertices() == mesh->num_vertices()) {
        to_frame(frame, &reference_copy);  // the mesh's transform: targets stay consistent
      }
      target.reference = &reference_copy;
    }
    // Sizes, directions and positions the user gives are in the input's frame.
    for (int a = 0; a < 3; ++a) target.frame.centre[a] = frame.centre[a];
    target.frame.length = frame.length;
    for (int a = 0; a < 9; ++a) target.frame.rotation[a] = frame.rotation[a];
    std::vector<double> W;
    Status s = build_targets(*mesh, points, target, &W);
    if (!s.ok()) return fail(s.message());
    double grad[kMaxCellNodes * 3], Winv[9], block[kMaxCellNodes * 3];
    GTableBuilder builder(&G[t], P);
    for (std::size_t p = 0; p < P; ++p) {
      const CellType type = mesh->cell_type(point_cell[p]);
      if (!inverse_d(W.data() + p * d * d, d, Winv))
        return fail("cell " + std::to_string(point_cell[p]) + ": singular target matrix");
      shape_gradients(type, &points.xi[3 * p], grad);
      const int n = cell_num_nodes(type);
      make_G(n, d, grad, Winv, block);
      builder.add(block, n * d);
    }
  }
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
      concurrent, [&] { before = measure(*mesh, table, frames); },
      [&] {
        result->initial_objective = exact_objective(*mesh, spec, G, point_cell, point_weight,
                                                    num_elements, frames, &initial_excess);
        result->min_det_before = min_target_det(*mesh, point_cell, G[0], &bad, frames);
      });
  result->inverted_before = before.inverted;
  result->min_quality_before = before.min_quality;
  bool barrier = false;
  for (const TermSpec& t : spec.terms) barrier |= t.metric->barrier();
  if (barrier && bad.empty() && before.inverted > 0) bad = inverted_cells(*mesh, table, frames);
  if (barrier && !bad.empty())
    return fail("barrier metric on an inverted mesh (untangle first): inverted cells " +
                list_cells(bad));
  const UntangleMetric* untangle_metric =
      spec.untangle ? dynamic_cast<const UntangleMetric*>(spec.terms[0].metric.get()) : nullptr;
  if (spec.untangle && !untangle_metric)
    return fail("an untangling stage needs an UntangleMetric as its first term");
  if (spec.untangle) {
    // An inverted point whose nodes are all fixed cannot be repaired by moving nodes.
    std::vector<int> stuck;
    for (std::size_t p = 0; p < P; ++p) {
      const int c = point_cell[p];
      if (!stuck.empty() && stuck.back() == c) continue;
      bool all_fixed = true;
      for (int i = 0; i < mesh->cell_size(c); ++i) all_fixed &= fixed[mesh->cell(c)[i]] != 0;
      if (!all_fixed) continue;
      double T[9];
      compute_T(mesh->cell_size(c), d, *mesh, mesh->cell(c), G[0].at(p), T, frames.cell(c));
      if (!(det_d(T, d) > 0)) stuck.push_back(c);
    }
    // Only the default fixed boundary can be released: sliding keeps corners and feature
    // curves, and a caller's own flags are its choice.
    if (!stuck.empty())
      return fail("cannot untangle: " + std::to_string(stuck.size()) + " cells inverted with " +
                  (spec.fixed.empty() && !spec.boundary
                       ? "every node on the fixed boundary (try --boundary=slide): "
                       : "every node fixed: ") +
                  list_cells(stuck));
  }

  // The Ceres problem: one residual block per sample point with a free node.
  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  popts.enable_fast_removal = false;
  popts.disable_all_safety_checks = true;
  popts.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;       // BoundaryConstraints owns them
  popts.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // `losses` below owns them
  // A power objective (p > 1) puts each point's weight and power into a Ceres loss
  // (power_loss.h): one per distinct point weight, shared by the blocks. Its scale m is a
  // fraction of the input's mean excess per element (stage.h).
  const bool powered = spec.power > 1 && !spec.untangle;
  double power_scale = 1.0;
  if (powered) {
    // An exact input (excess 0) has nothing to weigh: any positive scale will do, 1 is used.
    const double scaled = spec.power_scale_fraction * initial_excess;
    if (std::isfinite(scaled) && scaled > 0) power_scale = scaled;
  }
  result->power_scale = powered ? power_scale : 0.0;
  std::deque<PowerLoss> losses;
  std::unordered_map<double, PowerLoss*> loss_of_weight;
  auto loss_for = [&](double w) -> ceres::LossFunction* {
    if (!powered) return nullptr;
    auto it = loss_of_weight.find(w);
    if (it == loss_of_weight.end()) {
      losses.emplace_back(spec.power, w, power_scale, spec.power_model_cutoff);
      it = loss_of_weight.emplace(w, &losses.back()).first;
    }
    return it->second;
  };
  ceres::Problem problem(popts);
  // Barrier stages sampled away from the corners guard the corners (SamplePointCost::set_guard).
  const bool guard = barrier && validity_rule(rule) != rule;
  std::deque<SamplePointCost> costs;
  // Blocks whose data coincide share one cost object (DESIGN.md section 9) - uniform targets
  // make that every block of a cell type and point - unless a block carries its own state: a
  // surface frame or a corner guard.
  const bool share = !surface && !guard;
  std::unordered_map<CostKey, SamplePointCost*, CostKeyHash> shared_costs;
  std::vector<double*> blocks;
  std::vector<char> in_problem(mesh->num_vertices(), 0);
  // Residual blocks in space-filling-curve order of their cells: Ceres numbers the parameter
  // blocks by first appearance, so neighbouring blocks touch neighbouring columns of J and the
  // products of its CGNR stay in cache (docs/benchmarks.md).
  std::vector<std::int32_t> order = locality_order(*mesh, point_cell);
  for (const std::int32_t pi : order) {
    const std::size_t p = static_cast<std::size_t>(pi);
    const int c = point_cell[p];
    const int n = mesh->cell_size(c);
    const std::int32_t* nodes = mesh->cell(c);
    bool any_free = false;
    for (int i = 0; i < n; ++i) any_free |= !fixed[nodes[i]];
    if (!any_free) continue;
    SamplePointTerm terms[kMaxTerms];
    int nt = 0;
    for (std::size_t t = 0; t < spec.terms.size(); ++t) {
      const double c_t = spec.terms[t].weights.empty() ? 1.0 : spec.terms[t].weights[p];
      if (c_t < 0 || !std::isfinite(c_t))
        return fail("trade-off weight of sample point " + std::to_string(p) +
                    " is negative or not finite");
      // A term of zero weight still guards its barrier: residuals() is evaluated. Under a
      // power the point weight goes to the loss (PowerLoss: w phi(sum_t c_t |r_t|^2)).
      terms[nt].metric = spec.terms[t].metric.get();
      terms[nt].G = G[t].at(p);
      terms[nt].sqrt_weight = std::sqrt((powered ? 1.0 : point_weight[p]) * std::max(c_t, 0.0));
      ++nt;
    }
    blocks.clear();
    for (int i = 0; i < n; ++i) {
      blocks.push_back(mesh->vertex(nodes[i]));
      in_problem[nodes[i]] = 1;
    }
    if (share) {
      // One cost object for every block with the same node count, metrics, G and weights.
      CostKey key{n, nt, {}, {}, {}};
      for (int k = 0; k < nt; ++k) {
        key.metric[k] = terms[k].metric;
        key.G[k] = terms[k].G;
        key.w[k] = terms[k].sqrt_weight;
      }
      auto it = shared_costs.find(key);
      if (it == shared_costs.end()) {
        costs.emplace_back(n, d, nt, terms);
        it = shared_costs.emplace(key, &costs.back()).first;
      }
      problem.AddResidualBlock(it->second, loss_for(point_weight[p]), blocks);
      continue;
    }
    costs.emplace_back(n, d, nt, terms);
    if (surface) costs.back().set_surface_frame(frames.cell(c));
    if (guard && (p == 0 || point_cell[p - 1] != c)) {  // one guarded block per cell
      const std::vector<double>& g = table.G[static_cast<int>(mesh->cell_type(c))];
      costs.back().set_guard(g.data(), static_cast<int>(g.size()) / (n * d));
    }
    problem.AddResidualBlock(&costs.back(), loss_for(point_weight[p]), blocks);
  }
  std::vector<std::int32_t>().swap(order);  // 4 MB at 1M tets, not needed by the solve
  std::vector<int> free_vertices;
  for (int v = 0; v < mesh->num_vertices(); ++v) {
    if (!in_problem[v]) continue;
    if (fixed[v]) {
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
    result->final_objective = result->initial_objective;
    result->inverted_after = before.inverted;
    result->min_quality_after = before.min_quality;
    result->termination = "nothing to optimize: every vertex is fixed";
    from_frame(frame, mesh);
    mesh->coords = original;
    return Status::Ok();
  }

  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = spec.solver.method == SolverOptions::Method::kDogleg
                                      ? ceres::DOGLEG
                                      : ceres::LEVENBERG_MARQUARDT;
  const int free_coordinates = static_cast<int>(free_vertices.size()) * d;
  int cholesky_limit = d == 2 ? spec.solver.cholesky_max_free_coordinates_2d
                              : spec.solver.cholesky_max_free_coordinates_3d;
  if (cholesky_limit < 0)
    cholesky_limit = d == 2 ? kCholeskyMaxFreeCoordinates2d : kCholeskyMaxFreeCoordinates3d;
  bool cholesky = spec.solver.linear_solver == SolverOptions::LinearSolver::kSparseCholesky ||
                  (spec.solver.linear_solver == SolverOptions::LinearSolver::kAuto &&
                   (dogleg || free_coordinates <= cholesky_limit));
  if (cholesky) {
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    result->linear_solver = "sparse_normal_cholesky";
  } else {
    so.linear_solver_type = ceres::CGNR;
    so.preconditioner_type = ceres::JACOBI;
    so.max_linear_solver_iterations =
        d == 2 ? spec.solver.cgnr_max_iterations_2d : spec.solver.cgnr_max_iterations_3d;
    result->linear_solver = "cgnr_jacobi";
  }
  so.use_nonmonotonic_steps = spec.solver.nonmonotonic_steps;
  so.initial_trust_region_radius = 1e2;
  so.max_num_iterations = spec.solver.max_iterations;
  so.max_solver_time_in_seconds = spec.solver.max_seconds;
  so.function_tolerance = spec.solver.function_tolerance;
  so.gradient_tolerance = 0;       // relative rule in the callback instead
  so.parameter_tolerance = 1e-16;  // movement rule in the callback instead
  so.num_threads = spec.solver.threads > 0 ? spec.solver.threads
                                           : std::max(1u, std::thread::hardware_concurrency());
  so.logging_type =
      std::getenv("TMOP_CERES_PROGRESS") ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  so.minimizer_progress_to_stdout = std::getenv("TMOP_CERES_PROGRESS") != nullptr;
  so.update_state_every_iteration = true;
  // The stage solves in normalised coordinates (unit mean edge length), so the columns of J are
  // already of one scale: Ceres's Jacobi column scaling would only add two passes over J per
  // iteration (30 % of an iteration at 100k tets, the same iterates; docs/benchmarks.md).
  so.jacobi_scaling = false;
  StageCallback callback(
      mesh, spec, table, frames, free_vertices, shortest, num_elements,
      [&] {
        return exact_objective(*mesh, spec, G, point_cell, point_weight, num_elements, frames);
      },
      result);
  callback.set_power_scale(result->power_scale);
  so.callbacks.push_back(&callback);

  ceres::Solver::Summary summary;
  // The stage's caps hold over all its solves (untangling and surface frame rounds): each solve
  // gets what is left of the iterations and the time. Returns false when nothing is left.
  // Surface frame rounds under a power may use 4x the iterations (surface_budget below).
  const int stage_iterations =
      spec.solver.max_iterations * (surface && !spec.untangle && powered ? 4 : 1);
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
  int untangle_rounds = 0;
  // Untangling that ends worse than an earlier round (or its start) returns that round's state:
  // the round (0 = the start) and the last round's inverted count.
  int kept_round = -1, last_round_inverted = 0;
  // Surface meshes solve in rounds: the tangent frames are held fixed during a solve and
  // refreshed at the new positions after it. A barrier round is kept only if no cell is folded
  // in the refreshed frames, i.e. against the surface where the cell now lies: a long solve can
  // carry cells across curved parts of the surface in frames that went stale (lat-long sphere
  // sliding on its own triangulation: 36 triangles folded inward). A round that folds is undone
  // and redone with half the iterations; rounds end when a solve converges within its cap
  // (under a power: and lowered the objective by at most 0.1 %), or after the budget.
  const bool surface_rounds = surface && !spec.untangle;
  const int frame_rounds =
      surface ? std::max(1, surface_rounds ? spec.surface_max_rounds : spec.surface_frame_rounds)
              : 1;
  int round_cap = surface_rounds ? std::max(1, spec.surface_round_iterations) : 0;
  int surface_iterations = 0;
  // The iteration budget of all rounds. A power objective settles over more frame rounds
  // (sphere of 16 x 32 triangles: worst quality 0.24 within max_iterations, 0.27 within 4x).
  const int surface_budget = spec.solver.max_iterations * (powered ? 4 : 1);
  std::vector<double> round_start;
  for (int frame_round = 0; frame_round < frame_rounds; ++frame_round) {
    if (frame_round > 0) {
      const std::vector<double> previous_frames = frames.F;
      update_frames();
      if (barrier && !(min_target_det(*mesh, point_cell, G[0], nullptr, frames) > 0)) {
        frames.F = previous_frames;
        if (!surface_rounds || round_cap <= 1) {
          if (surface_rounds) mesh->coords = round_start;
          break;
        }
        mesh->coords = round_start;  // where previous_frames were made: the same frames again
        round_cap /= 2;
      } else if (surface_rounds && ((summary.termination_type != ceres::NO_CONVERGENCE &&
                                     (!powered || summary.initial_cost - summary.final_cost <=
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
      double det_now = min_target_det(*mesh, point_cell, G[0], &now_bad, frames);
      std::size_t best_bad = now_bad.size();
      double best_det = det_now;
      int best_round = 0;
      std::vector<double> best_coords = mesh->coords;
      const int max_rounds = det_now > 0 ? 0 : spec.untangle_max_rounds;
      int solved_rounds = 0;
      for (int round = 0; round < max_rounds; ++round) {
        metrics.push_back(std::make_unique<UntangleMetric>(d, eps, theta));
        for (SamplePointCost& cost : costs) cost.set_metric(0, metrics.back().get());
        so.max_num_iterations = spec.untangle_round_iterations;
        if (!budget()) break;
        if (!solve()) return fail("solver failed: " + summary.message);
        result->final_eps = eps;
        solved_rounds = untangle_rounds = round + 1;
        const double det_min = min_target_det(*mesh, point_cell, G[0], &now_bad, frames);
        det_now = det_min;
        if (det_min > 0) break;
        if (now_bad.size() < best_bad || (now_bad.size() == best_bad && det_min > best_det)) {
          best_bad = now_bad.size();
          best_det = det_min;
          best_round = round + 1;
          best_coords = mesh->coords;
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
        kept_round = best_round;
        last_round_inverted = static_cast<int>(now_bad.size());
        mesh->coords = best_coords;
      }
    } else {
      // One solve (a power mean too: its loss keeps the exact model, power_loss.h); surface
      // rounds cap it and go on in the next frame round.
      so.max_num_iterations = spec.solver.max_iterations;
      if (surface_rounds) so.max_num_iterations = std::min(so.max_num_iterations, round_cap);
      so.function_tolerance = spec.solver.function_tolerance;
      if (surface_rounds && !budget()) break;
      if (!solve()) return fail("solver failed: " + summary.message);
      if (surface_rounds) surface_iterations += static_cast<int>(summary.iterations.size()) - 1;
    }
  }

  // Ceres leaves the best parameters in place; the callback may have seen a later state.
  IterationRecord after;
  side_by_side(
      concurrent, [&] { after = measure(*mesh, table, frames); },
      [&] {
        result->min_det_after =
            min_target_det(*mesh, point_cell, G[0], &result->inverted_cells, frames);
        result->final_objective =
            exact_objective(*mesh, spec, G, point_cell, point_weight, num_elements, frames);
      });
  result->inverted_after = after.inverted;
  result->min_quality_after = after.min_quality;
  result->termination = callback.reason().empty() ? summary.message : callback.reason();
  if (spec.untangle) {
    char eps_text[32];
    std::snprintf(eps_text, sizeof eps_text, "%.3g", result->final_eps);
    result->termination =
        result->inverted_cells.empty()
            ? (untangle_rounds == 0 ? std::string("nothing inverted: no untangling needed")
                                    : "untangled in " + std::to_string(untangle_rounds) +
                                          " eps rounds (final eps " + eps_text + ")")
            : "still inverted after " + std::to_string(untangle_rounds) + " eps rounds" +
                  (kept_round < 0 ||
                           last_round_inverted == static_cast<int>(result->inverted_cells.size())
                       ? std::string()
                       : "; the best state kept (" +
                             (kept_round == 0 ? std::string("the start")
                                              : "round " + std::to_string(kept_round)) +
                             ": " + std::to_string(result->inverted_cells.size()) +
                             " cells inverted at sample points, the last round " +
                             std::to_string(last_round_inverted) + ")");
  }
  // Mapping back is not bit-exact: vertices that were never free or did not move keep their
  // input coordinates (a stage that moves nothing returns the input's bits).
  std::vector<char> keep(mesh->num_vertices());
  const int sd = mesh->space_dim;
  for (int v = 0; v < mesh->num_vertices(); ++v)
    keep[v] = fixed[v] || !in_problem[v] ||
              std::equal(mesh->vertex(v), mesh->vertex(v) + sd, &mapped_start[std::size_t(v) * sd]);
  from_frame(frame, mesh);
  for (int v = 0; v < mesh->num_vertices(); ++v)
    if (keep[v]) std::copy_n(&original[std::size_t(v) * sd], sd, mesh->vertex(v));
  if (barrier && after.inverted > 0)  // cannot happen: every accepted step was evaluated
    return fail("internal error: a barrier stage produced inverted elements");
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tmop
