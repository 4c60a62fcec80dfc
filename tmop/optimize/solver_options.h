// tmop/optimize/solver_options.h
// How one optimization stage is solved. Every stopping rule is dimensionless, so results do not
// change when the mesh is translated, scaled or rotated (the stage also solves in normalised
// coordinates: centred on the vertex centroid, lengths divided by the mean element edge length).
#ifndef TMOP_OPTIMIZE_SOLVER_OPTIONS_H_
#define TMOP_OPTIMIZE_SOLVER_OPTIONS_H_

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace tmop {

class PartExchange;

struct IterationRecord {
  int iteration = 0;
  // The stage's objective in StageResult's units (initial_objective / final_objective): the mean
  // over elements of sum_t c_t mu_t, exact mu. Measured only when the progress is reported
  // (verbose or a progress callback: a pass over the mesh), NaN otherwise.
  double objective = std::numeric_limits<double>::quiet_NaN();
  // What the solver minimises, per element: 2 x Ceres's cost / elements. It differs from
  // `objective` under a power p > 1 (the power objective), for metrics whose minimum is not 0
  // (residuals carry mu - mu_min) and by the points whose nodes are all fixed (not in the
  // problem). Recorded at every iteration.
  double solver_objective = 0;
  double min_quality = 0;  // worst shape quality over sample points (1 ideal, <= 0 inverted)
  int inverted = 0;        // elements with det A <= 0 at a sample point
  double seconds = 0;      // wall time since the stage started
};

// What a progress callback sees: the iteration's record and the stage it belongs to ("untangle",
// "shape", "shape (guard round 1)", "laplace", ...: StageSpec::name). A callback that takes a
// const IterationRecord& accepts it too.
struct ProgressRecord : IterationRecord {
  std::string stage;
};

// SolverOptions::progress: called after every iteration of every stage it is given to. It may
// return void (only watch) or bool: false cancels the run. Cancelling is sticky and shared by
// every copy of the callback (a recipe copies its SolverOptions into each stage, so one callback
// set once sees every stage and one false stops them all): the stage that is running ends at
// this iteration (Ceres terminates with the last accepted iterate, so a barrier stage never
// leaves an inverted mesh), later iterations and stages are not reported, and the recipe returns
// Status::Cancelled. cancel() does the same from outside the callback (another thread).
class ProgressCallback {
 public:
  ProgressCallback() = default;
  ProgressCallback(std::nullptr_t) {}  // NOLINT: `progress = nullptr` clears it
  template <typename F,
            typename = std::enable_if_t<std::is_invocable_v<F&, const ProgressRecord&> &&
                                        !std::is_same_v<std::decay_t<F>, ProgressCallback>>>
  ProgressCallback(F f)  // NOLINT: lambdas convert implicitly, as to std::function
      : state_(std::make_shared<State>()) {
    if constexpr (std::is_void_v<std::invoke_result_t<F&, const ProgressRecord&>>)
      state_->call = [f = std::move(f)](const ProgressRecord& r) mutable {
        f(r);
        return true;
      };
    else
      state_->call = [f = std::move(f)](const ProgressRecord& r) mutable {
        return static_cast<bool>(f(r));
      };
  }
  explicit operator bool() const { return state_ != nullptr; }
  // Reports one record; false when the run is (or now becomes) cancelled.
  bool operator()(const ProgressRecord& record) const {
    if (!state_ || cancelled()) return !state_;
    if (!state_->call(record)) state_->cancelled.store(true);
    return !state_->cancelled.load();
  }
  // True once cancelled: a callback returned false, cancel() was called, or the watched flag
  // (watch()) is raised, which takes effect at the next check without waiting for a record.
  bool cancelled() const {
    if (!state_) return false;
    if (state_->watched && state_->watched->load()) state_->cancelled.store(true);
    return state_->cancelled.load();
  }
  void cancel() const {
    if (state_) state_->cancelled.store(true);
  }
  // Also cancelled as soon as *flag is true (e.g. RecipeOptions::cancel, raised by a signal or
  // another thread). Not owned; must outlive every copy of the callback. Needs a callback set.
  void watch(const std::atomic<bool>* flag) const {
    if (state_) state_->watched = flag;
  }

 private:
  struct State {
    std::function<bool(const ProgressRecord&)> call;
    std::atomic<bool> cancelled{false};
    const std::atomic<bool>* watched = nullptr;
  };
  std::shared_ptr<State> state_;
};

// The default limits of SolverOptions::cholesky_max_free_coordinates_2d / _3d (-1).
constexpr int kCholeskyMaxFreeCoordinates2d = 1000;
constexpr int kCholeskyMaxFreeCoordinates3d = 200;

struct SolverOptions {
  enum class Method {
    kLevenbergMarquardt,  // default: robust, fewest rejected steps near barriers
    kDogleg,              // cheaper steps near barriers; needs sparse Cholesky (kAuto picks it)
  };
  enum class LinearSolver {
    kAuto,            // sparse Cholesky for small problems, CGNR + Jacobi otherwise
    kSparseCholesky,  // SPARSE_NORMAL_CHOLESKY (SuiteSparse): exact steps, memory grows fast
    kCgnr,            // CGNR + Jacobi preconditioner: matrix-free, O(N) memory
  };
  Method method = Method::kLevenbergMarquardt;
  LinearSolver linear_solver = LinearSolver::kAuto;
  // Problems with at most this many free coordinates use sparse Cholesky under kAuto; -1 (the
  // default) means kCholeskyMaxFreeCoordinates2d / 3d below, or the recipe's own choice
  // (equal_edge keeps Cholesky longer). On this project's machines CHOLMOD (AMD ordering,
  // Debian's ATLAS BLAS) loses to CGNR + Jacobi from a few hundred free coordinates on, for the
  // same iterations and results (shape, p = 2): 3D 1,413 free coordinates 0.24-0.27 -> 0.09-0.12
  // s, part 10k tets (2,703) 0.45-0.50 -> 0.26-0.29 s; 2D 4,238 0.14-0.18 -> 0.05-0.08 s, 16,982
  // 0.76-0.84 -> 0.33-0.39 s. The limits are where the two measured alike (3D 201 and 738, 2D
  // 1,048 free coordinates; docs/benchmarks.md, 2026-12-02; they were 20,000 and 4,000 before).
  int cholesky_max_free_coordinates_2d = -1;
  int cholesky_max_free_coordinates_3d = -1;
  // CGNR inner iterations per outer step (Ceres's max_linear_solver_iterations), by the mesh's
  // element dimension. Large 2D meshes hit the cap in their last steps, which only polish
  // (plate 200k triangles: 50 -> 30 took 4.2 s -> 2.9 s, objective 0.0010130 -> 0.0010131, the
  // same min quality), but 10 stops them early (objective +0.3 %, min quality 0.854 -> 0.851).
  // 3D shape steps take 2-9 until Levenberg-Marquardt's damping has faded, then 13-21 at 1M
  // tets for steps that change the objective by < 1e-4: 30 -> 10 took part 1M p = 2 from 43.1 s
  // to 33.7 s (10 -> 11 iterations, objective +9e-6 relative, the same min quality); 100k and
  // 10k tets and untangling do not change (docs/benchmarks.md).
  int cgnr_max_iterations_2d = 30;
  int cgnr_max_iterations_3d = 10;

  // Ceres's non-monotonic trust-region steps (accept a temporary increase of the objective).
  // Off by default: with sliding boundaries they let the objective drift up over several
  // accepted steps (part mesh: stopped at 0.2006 instead of converging to 0.1963).
  bool nonmonotonic_steps = false;

  // Outer (Ceres) iterations and wall-clock seconds of the whole stage, over all its solves
  // (untangling's eps rounds, surface frame rounds; surface rounds under a power may use 4x the
  // iterations). Untangling rounds are also capped at StageSpec::untangle_round_iterations each.
  int max_iterations = 200;
  double max_seconds = 1e9;
  // Stop when the objective decreases by less than this fraction of itself in a step. 1e-5 ends
  // within ~1e-4 of the converged objective (100k tets: 9 iterations, mean mu_303 0.191943 vs
  // 0.191929 fully converged); 1e-7 needs ~3x the iterations, spent mostly on the few worst
  // elements (min quality 0.36 -> 0.39 there; docs/benchmarks.md).
  double function_tolerance = 1e-5;
  // Stop when two successive steps each lower the mean metric value per element by less than
  // this (metric values are dimensionless: 1e-5 is far below any visible change of quality).
  // Relative rules alone keep going where the mesh is nearly ideal and the objective tiny
  // (200k triangles at mean mu ~1e-3). Not applied to untangling rounds. 0 disables it.
  double objective_tolerance = 1e-5;
  // Stop when the largest gradient entry falls below this fraction of its initial value.
  double gradient_tolerance = 1e-9;
  // Stop when no vertex moves by more than this fraction of its shortest incident edge.
  double movement_tolerance = 1e-9;

  // Partitioned stages (DESIGN.md section 12, optimize/partitioned_stage.h): a shape stage on a
  // volume or planar mesh of at least 2 x part_size elements is solved as METIS parts of about
  // part_size elements, side by side on `threads` workers (one Ceres problem of one thread
  // each, the cut vertices held), then the cuts in the parts of a second partition whose cuts
  // avoid the first's, in sweeps until a sweep lowers the solver's objective by less than
  // sweep_tolerance of itself or max_sweeps were made. 0: one problem over the whole mesh.
  // Untangling and surface stages always solve one problem. The default (meshes of 200k
  // elements and more are partitioned) is measured in docs/partitioning.md: less time and
  // memory than one problem from 300k tets up, more time below.
  int part_size = 100000;
  // Parts by count instead (at least 64 elements each): 0 uses part_size; 1 one problem; K >= 2
  // K parts whatever the mesh's size.
  int partitions = 0;
  int max_sweeps = 4;
  double sweep_tolerance = 5e-3;
  // The first sweep's phase A solves its parts to this relative decrease per step (Ceres's
  // function_tolerance) instead of function_tolerance: the bands around its cuts are re-solved by
  // phases B and C and revisited by later sweeps, so its last, costliest steps (10 CG steps
  // each) bought little (docs/partitioning.md: part_1m). 0: function_tolerance.
  double first_sweep_tolerance = 3e-4;
  // Sweeps after the first re-solve, in each phase, only the free vertices within sweep_rings
  // rings of elements of a vertex that moved since that phase last ran, in the parts where
  // that at least halves the part (an approximation: docs/partitioning.md has its cost).
  // 0: whole phases again.
  int sweep_rings = 2;

  int threads = 0;  // 0: all hardware threads
  // Partitioned stages shared among processes (part_exchange.h: MPI, tmop/parallel/): this
  // process solves its share of each phase's parts. Null: every part here. Not owned.
  PartExchange* exchange = nullptr;
  // Called after every iteration (also iteration 0) when set, with the stage's name; returning
  // false cancels (ProgressCallback above). verbose prints a line to stderr. Without either, the
  // per-iteration history records the solver's objective only (the objective, worst quality and
  // inverted count cost passes over the mesh; they are measured before and after the stage).
  ProgressCallback progress;
  bool verbose = false;
};

// "lm" / "dogleg"; "auto" / "cholesky" / "cgnr". false when unknown.
bool solver_method_from_name(const std::string& name, SolverOptions::Method* method);
bool linear_solver_from_name(const std::string& name, SolverOptions::LinearSolver* solver);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_SOLVER_OPTIONS_H_
