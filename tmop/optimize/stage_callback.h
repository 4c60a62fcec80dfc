// tmop/optimize/stage_callback.h (internal: stage.cc only; not part of tmop.h)
// The Ceres iteration callback of a stage: each iteration's record (objective, worst quality,
// inverted count, seconds) for the verbose lines and SolverOptions::progress, and the stage's
// own stopping rules (stage.h: mean metric decrease per element, vertex movement relative to the
// local edge length, time and iteration caps).
#ifndef TMOP_OPTIMIZE_STAGE_CALLBACK_H_
#define TMOP_OPTIMIZE_STAGE_CALLBACK_H_

#include <ceres/ceres.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/stage.h"
#include "tmop/quality/parallel_for.h"

namespace tmop {

class StageCallback final : public ceres::IterationCallback {
 public:
  // exact_objective: the stage's objective at the current nodes (measured when reporting).
  StageCallback(Mesh* mesh, const StageSpec& spec, const IdealTable& table, const Frames& frames,
                const std::vector<int>& free_vertices, const std::vector<double>& shortest,
                int num_elements, std::function<double()> exact_objective, StageResult* result)
      : mesh_(mesh),
        spec_(spec),
        table_(table),
        frames_(frames),
        free_(free_vertices),
        shortest_(shortest),
        num_elements_(num_elements),
        exact_objective_(std::move(exact_objective)),
        result_(result),
        start_(std::chrono::steady_clock::now()) {
    previous_.resize(free_.size() * mesh->space_dim);
    save(&previous_);
  }

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    const bool report = spec_.solver.verbose || static_cast<bool>(spec_.solver.progress);
    IterationRecord rec;
    if (report) {
      double objective = 0;
      side_by_side(
          spec_.solver.threads != 1, [&] { rec = measure(*mesh_, table_, frames_); },
          [&] { objective = exact_objective_(); });
      rec.objective = objective;
    } else {
      rec.min_quality = std::numeric_limits<double>::quiet_NaN();
      rec.inverted = -1;
    }
    rec.iteration = s.iteration == 0 && !result_->history.empty()
                        ? result_->history.back().iteration  // a frame or eps round restarts
                        : (result_->history.empty() ? 0 : result_->history.back().iteration + 1);
    rec.solver_objective = 2 * s.cost / std::max(1, num_elements_);
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    result_->history.push_back(rec);
    if (spec_.solver.verbose)
      std::fprintf(stderr,
                   "  [%s] iter %4d  objective %.6e  (solver %.6e)  min quality %.4f  inverted %d"
                   "  %.2f s\n",
                   spec_.name.c_str(), rec.iteration, rec.objective, rec.solver_objective,
                   rec.min_quality, rec.inverted, rec.seconds);
    // Cancelled (now or in an earlier stage or round): stop with the last accepted iterate.
    if (spec_.solver.progress.cancelled() || !report_progress(rec)) {
      reason_ = "cancelled by the progress callback";
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }

    if (s.iteration == 0) {  // a new solve (frame or eps round): its own counts
      initial_gradient_ = s.gradient_max_norm;
      small_steps_ = 0;
      small_decreases_ = 0;
      save(&previous_);
      return ceres::SOLVER_CONTINUE;
    }
    // Not under a power: there the initial gradient is dominated by the worst point's weight
    // (v/m)^(p-1), so a fraction of it says nothing about the rest (1M tets: 1e-9 of it was
    // reached at iteration 13, the worst quality still rising 1.5x per iteration).
    if (power_scale_ == 0 && initial_gradient_ > 0 &&
        s.gradient_max_norm <= spec_.solver.gradient_tolerance * initial_gradient_) {
      reason_ = "gradient below tolerance (relative to the initial gradient)";
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (s.step_is_successful) {
      const int sd = mesh_->space_dim;
      double worst = 0;
      for (std::size_t k = 0; k < free_.size(); ++k) {
        const double* x = mesh_->vertex(free_[k]);
        double m2 = 0;
        for (int a = 0; a < sd; ++a) {
          const double t = x[a] - previous_[k * sd + a];
          m2 += t * t;
        }
        worst = std::max(worst, std::sqrt(m2) / shortest_[free_[k]]);
      }
      save(&previous_);
      // One small step may only mean the trust region collapsed after rejected steps (a
      // barrier, a manifold's projection); Levenberg-Marquardt widens it again after successes,
      // so only several small successful steps in a row mean convergence.
      small_steps_ = worst <= spec_.solver.movement_tolerance ? small_steps_ + 1 : 0;
      if (small_steps_ >= 3) {
        reason_ = "vertex movement below tolerance (relative to local edge length)";
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
      // The metrics are dimensionless, so the decrease of the mean metric per element is too.
      // Two in a row, like the movement rule (one may follow a collapsed trust region).
      // A power objective (stage.h) decreases by phi'(v) = (1 + v/m)^(p-1) times the mean
      // metric; the rule divides that out at the current point (v from the objective as if
      // every point were alike: objective = (m/p)((1 + v/m)^p - 1)), so it means the same
      // for every power.
      double scale = 1.0;
      if (power_scale_ > 0) {
        const double p = spec_.power, objective = 2 * s.cost / std::max(1, num_elements_);
        scale = std::pow(1 + p * std::max(0.0, objective) / power_scale_, (p - 1) / p);
      }
      const double decrease = 2 * s.cost_change / (std::max(1, num_elements_) * scale);
      small_decreases_ =
          !spec_.untangle && decrease < spec_.solver.objective_tolerance ? small_decreases_ + 1 : 0;
      if (small_decreases_ >= 2) {
        reason_ = "mean metric decrease per element below objective_tolerance";
        return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
      }
    }
    return ceres::SOLVER_CONTINUE;
  }

  const std::string& reason() const { return reason_; }
  // True when the run goes on (no callback, or the callback did not cancel).
  bool report_progress(const IterationRecord& rec) const {
    if (!spec_.solver.progress) return true;
    ProgressRecord p;
    static_cast<IterationRecord&>(p) = rec;
    p.stage = spec_.name;
    return spec_.solver.progress(p);
  }
  // The scale m of a power objective (0: the plain objective).
  void set_power_scale(double m) { power_scale_ = m; }

 private:
  void save(std::vector<double>* out) const {
    const int sd = mesh_->space_dim;
    for (std::size_t k = 0; k < free_.size(); ++k)
      for (int a = 0; a < sd; ++a) (*out)[k * sd + a] = mesh_->vertex(free_[k])[a];
  }

  Mesh* mesh_;
  const StageSpec& spec_;
  const IdealTable& table_;
  const Frames& frames_;
  const std::vector<int>& free_;
  const std::vector<double>& shortest_;
  int num_elements_;
  std::function<double()> exact_objective_;
  StageResult* result_;
  std::chrono::steady_clock::time_point start_;
  std::vector<double> previous_;
  double initial_gradient_ = 0;
  int small_steps_ = 0;
  int small_decreases_ = 0;
  double power_scale_ = 0;
  std::string reason_;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_STAGE_CALLBACK_H_
