#include "tmop/optimize/stage_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "tmop/element/shape.h"
#include "tmop/target/target.h"

namespace tmop {

Status build_stage_targets(const Mesh& mesh, const StageSpec& spec, const SampleSet& points,
                           const CoordinateFrame& frame, std::vector<GTable>* G) {
  const int d = mesh.dim();
  const std::size_t P = points.cell.size();
  G->assign(spec.terms.size(), GTable());
  for (std::size_t t = 0; t < spec.terms.size(); ++t) {
    TargetSpec target = spec.terms[t].target;
    Mesh reference_copy;
    if ((target.type == TargetType::kReference || target.type == TargetType::kComposed) &&
        target.reference) {
      reference_copy = *target.reference;
      if (reference_copy.num_vertices() == mesh.num_vertices()) {
        to_frame(frame, &reference_copy);  // the mesh's transform: targets stay consistent
      }
      target.reference = &reference_copy;
    }
    // Sizes, directions and positions the user gives are in the input's frame.
    for (int a = 0; a < 3; ++a) target.frame.centre[a] = frame.centre[a];
    target.frame.length = frame.length;
    for (int a = 0; a < 9; ++a) target.frame.rotation[a] = frame.rotation[a];
    std::vector<double> W;
    Status s = build_targets(mesh, points, target, &W);
    if (!s.ok()) return s;
    double grad[kMaxCellNodes * 3], Winv[9], block[kMaxCellNodes * 3];
    GTableBuilder builder(&(*G)[t], P);
    for (std::size_t p = 0; p < P; ++p) {
      const CellType type = mesh.cell_type(points.cell[p]);
      if (!inverse_d(W.data() + p * d * d, d, Winv))
        return Status::Failure("cell " + std::to_string(points.cell[p]) +
                               ": singular target matrix");
      shape_gradients(type, &points.xi[3 * p], grad);
      const int n = cell_num_nodes(type);
      make_G(n, d, grad, Winv, block);
      builder.add(block, n * d);
    }
  }
  return Status::Ok();
}

double stage_objective(const Mesh& mesh, const StageContext& ctx, double* excess) {
  const StageSpec& spec = *ctx.spec;
  const int d = mesh.dim();
  double sum = 0, sum_min = 0;
  for (std::size_t p = 0; p < ctx.point_cell.size(); ++p) {
    const int c = ctx.point_cell[p];
    const int n = mesh.cell_size(c);
    for (std::size_t t = 0; t < spec.terms.size(); ++t) {
      const double c_t = spec.terms[t].weights.empty() ? 1.0 : spec.terms[t].weights[p];
      if (c_t == 0) continue;
      double T[9];
      compute_T(n, d, mesh, mesh.cell(c), ctx.G[t].at(p), T, ctx.frames.cell(c));
      const Metric& metric = *spec.terms[t].metric;
      sum += ctx.point_weight[p] * c_t * metric.value(T);
      sum_min += ctx.point_weight[p] * c_t * metric.min_value();
    }
  }
  const int elements = std::max(1, ctx.num_elements);
  if (excess) *excess = (sum - sum_min) / elements;
  return sum / elements;
}

double stage_solver_cost(const Mesh& mesh, const StageContext& ctx) {
  const StageSpec& spec = *ctx.spec;
  const int d = ctx.d;
  double cost = 0;
  const double* x[kMaxCellNodes];
  double r[kMaxTerms * kMaxMetricResiduals];
  for (std::size_t p = 0; p < ctx.point_cell.size(); ++p) {
    const int c = ctx.point_cell[p];
    const int n = mesh.cell_size(c);
    bool any_free = false;
    for (int i = 0; i < n; ++i) {
      x[i] = mesh.vertex(mesh.cell(c)[i]);
      any_free |= !ctx.fixed[mesh.cell(c)[i]];
    }
    if (!any_free) continue;
    SamplePointTerm terms[kMaxTerms];
    int nt = 0;
    for (std::size_t t = 0; t < spec.terms.size(); ++t, ++nt) {
      const double c_t = spec.terms[t].weights.empty() ? 1.0 : spec.terms[t].weights[p];
      terms[nt].metric = spec.terms[t].metric.get();
      terms[nt].G = ctx.G[t].at(p);
      terms[nt].sqrt_weight =
          std::sqrt((ctx.powered ? 1.0 : ctx.point_weight[p]) * std::max(c_t, 0.0));
    }
    const SamplePointCost block(n, d, nt, terms);
    if (!block.Evaluate(x, r, nullptr)) return std::numeric_limits<double>::infinity();
    double s2 = 0;
    for (int k = 0; k < block.num_residuals(); ++k) s2 += r[k] * r[k];
    if (ctx.powered) {
      double rho[3];
      PowerLoss(spec.power, ctx.point_weight[p], ctx.power_scale, spec.power_model_cutoff)
          .Evaluate(s2, rho);
      s2 = rho[0];
    }
    cost += 0.5 * s2;
  }
  return cost;
}

ceres::Solver::Options stage_solver_options(const StageSpec& spec, int d, int free_coordinates,
                                            int threads, std::string* linear_solver) {
  ceres::Solver::Options so;
  const bool dogleg = spec.solver.method == SolverOptions::Method::kDogleg;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = dogleg ? ceres::DOGLEG : ceres::LEVENBERG_MARQUARDT;
  int cholesky_limit = d == 2 ? spec.solver.cholesky_max_free_coordinates_2d
                              : spec.solver.cholesky_max_free_coordinates_3d;
  if (cholesky_limit < 0)
    cholesky_limit = d == 2 ? kCholeskyMaxFreeCoordinates2d : kCholeskyMaxFreeCoordinates3d;
  const bool cholesky = spec.solver.linear_solver == SolverOptions::LinearSolver::kSparseCholesky ||
                        (spec.solver.linear_solver == SolverOptions::LinearSolver::kAuto &&
                         (dogleg || free_coordinates <= cholesky_limit));
  if (cholesky) {
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    *linear_solver = "sparse_normal_cholesky";
  } else {
    so.linear_solver_type = ceres::CGNR;
    so.preconditioner_type = ceres::JACOBI;
    so.max_linear_solver_iterations =
        d == 2 ? spec.solver.cgnr_max_iterations_2d : spec.solver.cgnr_max_iterations_3d;
    *linear_solver = "cgnr_jacobi";
  }
  so.use_nonmonotonic_steps = spec.solver.nonmonotonic_steps;
  so.initial_trust_region_radius = 1e2;
  so.max_num_iterations = spec.solver.max_iterations;
  so.max_solver_time_in_seconds = spec.solver.max_seconds;
  so.function_tolerance = spec.solver.function_tolerance;
  so.gradient_tolerance = 0;       // relative rule in the callback instead
  so.parameter_tolerance = 1e-16;  // movement rule in the callback instead
  so.num_threads = threads;
  so.logging_type =
      std::getenv("TMOP_CERES_PROGRESS") ? ceres::PER_MINIMIZER_ITERATION : ceres::SILENT;
  so.minimizer_progress_to_stdout = std::getenv("TMOP_CERES_PROGRESS") != nullptr;
  so.update_state_every_iteration = true;
  // The stage solves in normalised coordinates (unit mean edge length), so the columns of J
  // are already of one scale: Ceres's Jacobi column scaling would only add two passes over J
  // per iteration (30 % of an iteration at 100k tets, the same iterates; docs/benchmarks.md).
  so.jacobi_scaling = false;
  return so;
}

bool ProblemAssembly::Key::operator==(const Key& o) const {
  if (n != o.n || nt != o.nt) return false;
  for (int k = 0; k < nt; ++k)
    if (metric[k] != o.metric[k] || G[k] != o.G[k] || w[k] != o.w[k]) return false;
  return true;
}

std::size_t ProblemAssembly::KeyHash::operator()(const Key& k) const {
  std::size_t h = std::hash<int>()(k.n * 8 + k.nt);
  for (int t = 0; t < k.nt; ++t) {
    h = h * 1000003 ^ std::hash<const void*>()(k.metric[t]);
    h = h * 1000003 ^ std::hash<const void*>()(k.G[t]);
    h = h * 1000003 ^ std::hash<double>()(k.w[t]);
  }
  return h;
}

ProblemAssembly::ProblemAssembly(const StageContext& ctx, const Mesh& mesh, const IdealTable& table)
    : ctx_(ctx),
      mesh_(mesh),
      table_(table),
      // Blocks whose data coincide share one cost object (DESIGN.md section 9) - uniform
      // targets make that every block of a cell type and point - unless a block carries its
      // own state: a surface frame or a corner guard.
      share_(!ctx.surface && !ctx.guard) {}

ceres::Problem::Options ProblemAssembly::problem_options() {
  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  popts.enable_fast_removal = false;
  popts.disable_all_safety_checks = true;
  popts.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;       // BoundaryConstraints owns them
  popts.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // the assembly owns them
  return popts;
}

// A power objective (p > 1) puts each point's weight and power into a Ceres loss
// (power_loss.h): one per distinct point weight, shared by the blocks.
ceres::LossFunction* ProblemAssembly::loss_for(double w) {
  if (!ctx_.powered) return nullptr;
  auto it = loss_of_weight_.find(w);
  if (it == loss_of_weight_.end()) {
    const StageSpec& spec = *ctx_.spec;
    losses_.emplace_back(spec.power, w, ctx_.power_scale, spec.power_model_cutoff);
    it = loss_of_weight_.emplace(w, &losses_.back()).first;
  }
  return it->second;
}

void ProblemAssembly::add(const std::vector<std::int32_t>& points,
                          const std::function<bool(int)>& is_free,
                          const std::function<double*(int)>& vertex,
                          const std::function<void(int)>& used, ceres::Problem* problem) {
  const StageSpec& spec = *ctx_.spec;
  const int d = ctx_.d;
  std::vector<double*> blocks;
  for (const std::int32_t pi : points) {
    const std::size_t p = static_cast<std::size_t>(pi);
    const int c = ctx_.point_cell[p];
    const int n = mesh_.cell_size(c);
    const std::int32_t* nodes = mesh_.cell(c);
    bool any_free = false;
    for (int i = 0; i < n && !any_free; ++i) any_free = is_free(nodes[i]);
    if (!any_free) continue;
    SamplePointTerm terms[kMaxTerms];
    int nt = 0;
    for (std::size_t t = 0; t < spec.terms.size(); ++t) {
      const double c_t = spec.terms[t].weights.empty() ? 1.0 : spec.terms[t].weights[p];
      // A term of zero weight still guards its barrier: residuals() is evaluated. Under a
      // power the point weight goes to the loss (PowerLoss: w phi(sum_t c_t |r_t|^2)).
      terms[nt].metric = spec.terms[t].metric.get();
      terms[nt].G = ctx_.G[t].at(p);
      terms[nt].sqrt_weight =
          std::sqrt((ctx_.powered ? 1.0 : ctx_.point_weight[p]) * std::max(c_t, 0.0));
      ++nt;
    }
    blocks.clear();
    for (int i = 0; i < n; ++i) {
      blocks.push_back(vertex(nodes[i]));
      used(nodes[i]);
    }
    ceres::LossFunction* loss = loss_for(ctx_.point_weight[p]);
    if (share_) {
      // One cost object for every block with the same node count, metrics, G and weights.
      Key key{n, nt, {}, {}, {}};
      for (int k = 0; k < nt; ++k) {
        key.metric[k] = terms[k].metric;
        key.G[k] = terms[k].G;
        key.w[k] = terms[k].sqrt_weight;
      }
      auto it = shared_.find(key);
      if (it == shared_.end()) {
        costs_.emplace_back(n, d, nt, terms);
        it = shared_.emplace(key, &costs_.back()).first;
      }
      problem->AddResidualBlock(it->second, loss, blocks);
      continue;
    }
    costs_.emplace_back(n, d, nt, terms);
    if (ctx_.surface) costs_.back().set_surface_frame(ctx_.frames.cell(c));
    if (ctx_.guard && (p == 0 || ctx_.point_cell[p - 1] != c)) {  // one guarded block per cell
      const std::vector<double>& g = table_.G[static_cast<int>(mesh_.cell_type(c))];
      costs_.back().set_guard(g.data(), static_cast<int>(g.size()) / (n * d));
    }
    problem->AddResidualBlock(&costs_.back(), loss, blocks);
  }
}

}  // namespace tmop
