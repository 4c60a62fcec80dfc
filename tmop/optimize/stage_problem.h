// tmop/optimize/stage_problem.h (internal: optimize/ only; not part of tmop.h)
// What a stage's Ceres problems are made of, shared by the whole-mesh solve (stage.cc) and the
// partitioned one (partitioned_stage.cc):
// - StageContext: everything computed once for the whole mesh (in the stage's normalised frame)
//   and handed to every problem: fixed vertices, sample points and their weights, the G tables
//   of the targets, the validity table, surface frames, the power scale, the shortest edges.
//   Parts are pieces of one objective, not separate problems (DESIGN.md section 12).
// - ProblemAssembly: adds the residual blocks of a set of sample points to a ceres::Problem,
//   with the parameter block of each vertex wherever the caller keeps it (the mesh's own
//   storage, or a part's copy), sharing identical cost objects and power losses.
#ifndef TMOP_OPTIMIZE_STAGE_PROBLEM_H_
#define TMOP_OPTIMIZE_STAGE_PROBLEM_H_

#include <ceres/ceres.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/element/sample_points.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/g_table.h"
#include "tmop/optimize/power_loss.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/sample_point_cost.h"
#include "tmop/optimize/stage.h"

namespace tmop {

struct StageContext {
  const StageSpec* spec = nullptr;
  int d = 0;
  bool surface = false;  // 2D cells in 3D: per-cell tangent frames
  bool barrier = false;  // some term is a barrier metric
  bool powered = false;  // power > 1 and not untangling
  bool guard = false;    // barrier sampled away from the corners: corner guards per cell
  int num_elements = 0;
  std::vector<char> fixed;  // per vertex
  std::vector<std::int32_t> point_cell;
  std::vector<double> point_weight;
  std::vector<GTable> G;  // per term
  Frames frames;          // surface meshes; empty otherwise
  double power_scale = 1.0;
  std::vector<double> shortest;  // shortest incident edge per vertex (movement rule)
};

// The targets' G tables of every term at `points` of `mesh` (already in `frame`). Releases
// nothing; fails with a one-line Status (a singular target, a bad target spec).
Status build_stage_targets(const Mesh& mesh, const StageSpec& spec, const SampleSet& points,
                           const CoordinateFrame& frame, std::vector<GTable>* G);

// The exact mean of sum_t c_t mu_t over elements (point weights of a cell sum to 1); when
// `excess` is given, the mean of sum_t c_t (mu_t - mu_t,min) in the same pass.
double stage_objective(const Mesh& mesh, const StageContext& ctx, double* excess = nullptr);

// What the stage's Ceres problem would report as its cost at the mesh's coordinates (half the
// sum over the points with a free node of their squared residuals, through the power loss),
// without building the problem: +infinity when a barrier point is invalid.
double stage_solver_cost(const Mesh& mesh, const StageContext& ctx);

// Ceres's options for a stage's problem with `free_coordinates` free coordinates on `threads`
// threads (> 0): the trust-region method, the linear solver (sparse Cholesky for small problems
// under kAuto, CGNR + Jacobi otherwise; its name in *linear_solver), caps and tolerances of
// spec.solver. The stage's own stopping rules are a callback added by the caller.
ceres::Solver::Options stage_solver_options(const StageSpec& spec, int d, int free_coordinates,
                                            int threads, std::string* linear_solver);

class ProblemAssembly {
 public:
  ProblemAssembly(const StageContext& ctx, const Mesh& mesh, const IdealTable& table);
  ProblemAssembly(const ProblemAssembly&) = delete;
  ProblemAssembly& operator=(const ProblemAssembly&) = delete;

  // Adds one residual block per sample point of `points` (indices into ctx.point_cell, in
  // this order: Ceres numbers parameter blocks by first appearance) whose cell has a node with
  // is_free(v); vertex v's parameter block is vertex(v), and used(v) is called for each node of
  // an added block.
  void add(const std::vector<std::int32_t>& points, const std::function<bool(int)>& is_free,
           const std::function<double*(int)>& vertex, const std::function<void(int)>& used,
           ceres::Problem* problem);
  std::deque<SamplePointCost>& costs() { return costs_; }

  // The options every stage problem is made with (costs, losses and manifolds not owned).
  static ceres::Problem::Options problem_options();

 private:
  struct Key {
    int n, nt;
    const Metric* metric[kMaxTerms];
    const double* G[kMaxTerms];
    double w[kMaxTerms];
    bool operator==(const Key& o) const;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const;
  };
  ceres::LossFunction* loss_for(double w);

  const StageContext& ctx_;
  const Mesh& mesh_;
  const IdealTable& table_;
  bool share_;
  std::deque<SamplePointCost> costs_;
  std::unordered_map<Key, SamplePointCost*, KeyHash> shared_;
  std::deque<PowerLoss> losses_;
  std::unordered_map<double, PowerLoss*> loss_of_weight_;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_STAGE_PROBLEM_H_
