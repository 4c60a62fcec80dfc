#include "tmop/optimize/part_solve.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <new>

#include "tmop/geometry/boundary_constraints.h"
#include "tmop/optimize/locality_order.h"

namespace tmop {

CellPoints cell_points(const Mesh& mesh, const std::vector<std::int32_t>& point_cell) {
  CellPoints cp;
  cp.offset.assign(static_cast<std::size_t>(mesh.num_cells()) + 1, 0);
  for (const std::int32_t c : point_cell) ++cp.offset[c + 1];
  for (int c = 0; c < mesh.num_cells(); ++c) cp.offset[c + 1] += cp.offset[c];
  cp.identity = std::is_sorted(point_cell.begin(), point_cell.end());
  if (cp.identity) return cp;
  cp.point.resize(point_cell.size());
  std::vector<std::int32_t> next(cp.offset.begin(), cp.offset.end() - 1);
  for (std::size_t p = 0; p < point_cell.size(); ++p)
    cp.point[next[point_cell[p]]++] = static_cast<std::int32_t>(p);
  return cp;
}

namespace {

// The stage's stopping rules (StageCallback, stage_callback.h) on one part: the relative
// gradient (not under a power), three small movements in a row, two small decreases of the
// mean metric per element of the part in a row.
class PartCallback final : public ceres::IterationCallback {
 public:
  PartCallback(const StageContext& ctx, const std::vector<double>& x, const std::vector<int>& free,
               const std::vector<int>& free_local, int elements)
      : ctx_(ctx), x_(x), free_(free), free_local_(free_local), elements_(std::max(1, elements)) {
    previous_.resize(free_local.size() * ctx.d);
    save();
  }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    const SolverOptions& so = ctx_.spec->solver;
    // A cancel (a signal, another thread) ends the part at its last accepted iterate, as it ends
    // a whole-mesh solve (StageCallback), instead of after the part's last iteration.
    if (so.progress.cancelled()) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    if (s.iteration == 0) {
      initial_gradient_ = s.gradient_max_norm;
      return ceres::SOLVER_CONTINUE;
    }
    if (!ctx_.powered && initial_gradient_ > 0 &&
        s.gradient_max_norm <= so.gradient_tolerance * initial_gradient_)
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    if (!s.step_is_successful) return ceres::SOLVER_CONTINUE;
    const int d = ctx_.d;
    double worst = 0;
    for (std::size_t k = 0; k < free_local_.size(); ++k) {
      double m2 = 0;
      for (int a = 0; a < d; ++a) {
        const double t = x_[std::size_t(free_local_[k]) * d + a] - previous_[k * d + a];
        m2 += t * t;
      }
      worst = std::max(worst, std::sqrt(m2) / ctx_.shortest[free_[k]]);
    }
    save();
    small_steps_ = worst <= so.movement_tolerance ? small_steps_ + 1 : 0;
    if (small_steps_ >= 3) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    double scale = 1.0;  // the power's phi'(v) divided out (StageCallback)
    if (ctx_.powered) {
      const double p = ctx_.spec->power, objective = 2 * s.cost / elements_;
      scale = std::pow(1 + p * std::max(0.0, objective) / ctx_.power_scale, (p - 1) / p);
    }
    const double decrease = 2 * s.cost_change / (elements_ * scale);
    small_decreases_ = decrease < so.objective_tolerance ? small_decreases_ + 1 : 0;
    return small_decreases_ >= 2 ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  void save() {
    const int d = ctx_.d;
    for (std::size_t k = 0; k < free_local_.size(); ++k)
      for (int a = 0; a < d; ++a) previous_[k * d + a] = x_[std::size_t(free_local_[k]) * d + a];
  }
  const StageContext& ctx_;
  const std::vector<double>& x_;
  const std::vector<int>& free_;
  const std::vector<int>& free_local_;
  const int elements_;
  std::vector<double> previous_;
  double initial_gradient_ = 0;
  int small_steps_ = 0, small_decreases_ = 0;
};

}  // namespace

PartOutcome solve_part(const Mesh& mesh, const std::vector<double>& start, const StageContext& ctx,
                       const IdealTable& table, const VertexCells& vc, const CellPoints& cp,
                       const std::vector<int>& free, double seconds, double function_tolerance,
                       PartScratch* scratch, std::vector<double>* out) {
  PartOutcome outcome;
  const int sd = mesh.space_dim;
  std::vector<int> vertices;  // local index -> vertex
  try {
    // The elements around the free vertices, and every node of them.
    const int stamp = ++scratch->stamp;
    std::vector<int> cells;
    for (const int v : free)
      for (const std::int32_t* c = vc.begin(v); c != vc.end(v); ++c)
        if (scratch->mark[*c] != stamp) {
          scratch->mark[*c] = stamp;
          cells.push_back(*c);
        }
    std::sort(cells.begin(), cells.end());
    outcome.elements = static_cast<int>(cells.size());
    for (const int c : cells)
      for (int i = 0; i < mesh.cell_size(c); ++i) {
        const int v = mesh.cell(c)[i];
        if (scratch->local[v] >= 0) continue;
        scratch->local[v] = static_cast<int>(vertices.size());
        vertices.push_back(v);
      }
    std::vector<double> x(vertices.size() * sd);
    for (std::size_t k = 0; k < vertices.size(); ++k)
      std::copy_n(&start[std::size_t(vertices[k]) * sd], sd, &x[k * sd]);
    std::vector<char> is_free(vertices.size(), 0);
    std::vector<int> free_local(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) {
      free_local[k] = scratch->local[free[k]];
      is_free[free_local[k]] = 1;
    }
    std::vector<std::int32_t> points, point_cell;
    for (const int c : cells)
      for (std::int64_t k = cp.offset[c]; k < cp.offset[c + 1]; ++k) {
        points.push_back(cp.at(k));
        point_cell.push_back(c);
      }
    // Space-filling-curve order within the part, as the whole-mesh problem (stage.cc).
    std::vector<std::int32_t> order = locality_order(mesh, point_cell);
    for (std::int32_t& k : order) k = points[k];

    ceres::Problem problem(ProblemAssembly::problem_options());
    ProblemAssembly assembly(ctx, mesh, table);
    const std::vector<int>& local = scratch->local;
    assembly.add(
        order, [&](int v) { return is_free[local[v]] != 0; },
        [&](int v) { return &x[std::size_t(local[v]) * sd]; }, [](int) {}, &problem);
    const StageSpec& spec = *ctx.spec;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      double* block = &x[k * sd];
      if (!problem.HasParameterBlock(block)) continue;
      if (!is_free[k]) {
        problem.SetParameterBlockConstant(block);
      } else if (spec.boundary && spec.boundary->manifold(vertices[k])) {
        problem.SetManifold(block,
                            const_cast<ceres::Manifold*>(spec.boundary->manifold(vertices[k])));
      }
    }
    ceres::Solver::Options so = stage_solver_options(
        spec, ctx.d, static_cast<int>(free.size()) * ctx.d, 1, &outcome.linear_solver);
    so.max_solver_time_in_seconds = std::max(seconds, 1e-9);
    so.function_tolerance = function_tolerance;
    PartCallback callback(ctx, x, free, free_local, outcome.elements);
    so.callbacks.push_back(&callback);
    // Cancelled while the problem was built: no Solve (its preprocessing cannot be interrupted);
    // the part stays at the phase's start.
    if (spec.solver.progress.cancelled()) {
      for (const int v : vertices) scratch->local[v] = -1;
      return outcome;
    }
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    if (summary.termination_type == ceres::FAILURE) {
      outcome.ok = false;
      outcome.error = "solver failed: " + summary.message;
    }
    outcome.initial_cost = summary.initial_cost;
    outcome.final_cost = summary.final_cost;
    outcome.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
    StageResult::Times& t = outcome.times;
    t.preprocessor = summary.preprocessor_time_in_seconds;
    t.minimizer = summary.minimizer_time_in_seconds;
    t.residual_evaluation = summary.residual_evaluation_time_in_seconds;
    t.jacobian_evaluation = summary.jacobian_evaluation_time_in_seconds;
    t.linear_solver = summary.linear_solver_time_in_seconds;
    t.residual_evaluations = summary.num_residual_evaluations;
    t.jacobian_evaluations = summary.num_jacobian_evaluations;
    t.linear_solves = summary.num_linear_solves;
    for (const ceres::IterationSummary& it : summary.iterations) {
      if (it.iteration == 0) continue;
      t.linear_iterations += it.linear_solver_iterations;
      ++t.recorded_linear_solves;
    }
    // Ceres leaves the best parameters in x: the part's free vertices go to the mesh.
    if (outcome.ok)
      for (std::size_t k = 0; k < free.size(); ++k)
        std::copy_n(&x[std::size_t(free_local[k]) * sd], sd, &(*out)[std::size_t(free[k]) * sd]);
  } catch (const std::bad_alloc&) {
    outcome.ok = false;
    outcome.error = "out of memory in a part of " + std::to_string(free.size()) + " vertices";
  }
  for (const int v : vertices) scratch->local[v] = -1;
  return outcome;
}

}  // namespace tmop
