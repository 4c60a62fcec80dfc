// tmop/optimize/stage.h
// One optimization stage: minimise F(x) = sum_e sum_k w_k sum_t c_tk mu_t(A_k W_tk^-1) over the
// free vertex coordinates of `mesh`, in place, with Ceres (one residual block per sample point,
// parameter blocks = the mesh's own coordinates). Recipes chain stages.
//
// Inputs: the mesh (modified in place), the stage's terms (metric + target + optional per-point
// trade-off weights c_k), the sample rule, which vertices are fixed, solver options.
// Output: StageResult. A failing stage (bad input, a barrier metric on an inverted mesh) returns
// a Status and leaves the mesh unchanged.
#ifndef TMOP_OPTIMIZE_STAGE_H_
#define TMOP_OPTIMIZE_STAGE_H_

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/element/sample_points.h"
#include "tmop/mesh/mesh.h"
#include "tmop/metric/metric.h"
#include "tmop/optimize/coordinate_frame.h"
#include "tmop/optimize/solver_options.h"
#include "tmop/target/target.h"

namespace tmop {

class BoundaryConstraints;  // geometry/boundary_constraints.h

struct TermSpec {
  std::shared_ptr<const Metric> metric;  // dimension must equal the mesh's element dimension
  TargetSpec target;
  // Per-sample-point trade-off weights c_k in the canonical order (target.h) followed by the
  // stage's extra points; empty means 1.
  std::vector<double> weights;
};

struct StageSpec {
  std::string name = "stage";
  SampleRule rule = SampleRule::kDefault;
  // Extra sample points appended after the canonical ones of `rule` (e.g. where a validity
  // certificate of a quadratic cell failed). Their weights add to their cells' contributions.
  SampleSet extra_points;
  std::vector<TermSpec> terms;  // 1 or 2 terms
  // Per-vertex flags (1 = fixed). Empty: every boundary vertex is fixed, unless `boundary` is
  // given (then its corners are fixed and the other boundary vertices slide).
  std::vector<char> fixed;
  // Sliding boundary vertices and surface geometry: the constraints must have been built on the
  // mesh mapped by `frame` (so several stages share one geometry built from the input: no
  // drift), and the stage then solves in that frame. Required for surface meshes (2D cells in
  // 3D), whose Jacobians are reduced to 2 x 2 in the tangent frame of the geometry's normal so
  // that a folded triangle has det T <= 0. Not owned. Null: nothing slides.
  const BoundaryConstraints* boundary = nullptr;
  CoordinateFrame frame;
  // Surface meshes: the tangent frames are held fixed during a Ceres solve (exact derivatives
  // for that frame) and refreshed at the new positions between solves, this many solves.
  int surface_frame_rounds = 3;  // untangling stages
  // Barrier and other stages on surface meshes: solves of at most surface_round_iterations
  // Ceres iterations each, refreshing the frames between them, at most surface_max_rounds
  // (stage.cc explains the undo of a round that folds a cell).
  int surface_round_iterations = 20;
  int surface_max_rounds = 40;
  SolverOptions solver;
  // Power order p >= 1: weight the worst points up. The objective is
  //   sum_k w_k (m / p) ((1 + v_k / m)^p - 1),   v_k = sum_t c_t |r_t|^2
  // (|r_t|^2 = mu_t - mu_t,min for metrics with exact residuals, a surrogate otherwise)
  // (w_k the point weights, c_t the trade-offs, m = power_scale_fraction x the input's mean v
  // per element): the plain
  // mean for p = 1; for p > 1 points near or below m count as in the plain mean and points far
  // above it as (v_k / m)^(p-1) times more, so the worst are pulled up while no point is
  // neglected (a pure sum of v^p lets the rest of the mesh pay for elements that cannot be
  // fixed: lat-long sphere mean ratio 0.80 instead of 0.97). One Ceres solve: each block's power
  // and weight are a Ceres loss (PowerLoss, power_loss.h) whose second-order correction keeps
  // the exact Gauss-Newton model. Untangling stages ignore it. Not finite or < 1: fails.
  double power = 1.0;
  // m as a fraction of the input's mean (inputs are worse than results: the results' mean is
  // the scale that matters). 0.25 measured against 1 and 0.5 (docs/benchmarks.md): part 100k
  // worst mean ratio 0.430 / 0.437 / 0.443, mean 0.850 / 0.849 / 0.847; quad sphere 0.21 at 1.
  double power_scale_fraction = 0.25;
  // Beyond v_k = power_model_cutoff x m a point's Gauss-Newton model drops the power's
  // curvature (PowerLoss::model_cutoff): the objective and gradient are unchanged, the worst
  // elements take longer steps (part 100k tets, p = 2: 14 -> 9 iterations, the same result).
  // +infinity keeps the exact model everywhere. <= 0 or NaN: fails.
  double power_model_cutoff = 50;  // PowerLoss::kDefaultModelCutoff (50 vs 10 / 30 / 100)

  // Untangling schedule (DESIGN.md section 7). When true, terms[0].metric must be an
  // UntangleMetric (metric/untangle.h); the stage solves repeatedly, lowering its eps between
  // solves from the current minimum of det T (Garanzha et al. 2021), until no sample point is
  // inverted or untangle_max_rounds solves were made. Each solve is capped at
  // untangle_round_iterations Ceres iterations. A schedule that ends with inverted points
  // returns the best state it reached (fewest inverted cells, then the largest min det; its
  // start included), not its last.
  bool untangle = false;
  int untangle_max_rounds = 60;
  int untangle_round_iterations = 40;
  // The schedule also stops after this many rounds in a row that do not improve on the best state
  // (fewer inverted cells, or as many with a larger min det); 0: no such stop. Around cells that
  // cannot be repaired, later rounds only drag neighbours over (t5 at -order 2 with pushed cells).
  int untangle_patience = 8;
  // A spreading tangle stops sooner: after untangle_spread_rounds rounds in a row without a better
  // state whose inverted count is at least untangle_spread_factor x the best state's and whose min
  // det is no larger than the best's. The repair then only folds neighbours over (Gmsh t16 at
  // -order 2 with --boundary=slide: 2 inverted boundary cells, 276 inverted after one round, 339
  // after two, 1,113 after eight; 152 s of rounds before, 2 rounds now). 0: no such stop.
  int untangle_spread_rounds = 2;
  double untangle_spread_factor = 4;
  // Lower bound of sigma, the fraction by which eps's target mu = (1 - sigma) chi(min det, eps)
  // undercuts the current regularised minimum. The published schedule uses 0.1 with solves run
  // to convergence; with short rounds the energy barely moves in a round, sigma sits at its
  // floor, and 0.1 lowers eps by only ~7 % per round (LIM armadillo: 22 rounds, 4.7 s; 0.5:
  // 8 rounds, 1.8 s, the same untangled result; docs/benchmarks.md).
  double untangle_sigma_min = 0.5;
};

struct StageResult {
  std::string name;
  double initial_objective = 0;  // mean exact metric value per element
  double final_objective = 0;
  int iterations = 0;
  std::string termination;  // why the solver stopped, in words
  double seconds = 0;
  int inverted_before = 0, inverted_after = 0;
  double min_quality_before = 0, min_quality_after = 0;
  int num_elements = 0, num_sample_points = 0, num_free_vertices = 0;
  std::string linear_solver;
  // Partitioned stages (SolverOptions::part_size): the parts of the first partition, the
  // sweeps made, and the work: elements x iterations summed over the part solves (0 for one
  // problem, whose work is num_elements x iterations).
  int parts = 0, sweeps = 0;
  std::int64_t part_element_iterations = 0;
  int solves = 0;  // Ceres solves (1, or the surface frame rounds or untangling rounds)
  double min_det_before = 0, min_det_after = 0;  // min det T over sample points (term 0)
  double final_eps = 0;                          // untangling: eps of the last solve
  double power_scale = 0;  // power > 1: the scale m of the power objective (StageSpec), else 0
  std::vector<int> inverted_cells;  // cells still inverted after the stage
  std::vector<IterationRecord> history;
  // Where the time went (seconds of wall time). setup: tmop's own work before the first solve
  // (targets, measures, problem construction); the rest from Ceres's summaries, summed over the
  // stage's solves (the work between solves - frame updates, eps rounds - is in none of them).
  // linear_iterations counts the inner iterations (CGNR; 1 per solve for Cholesky) of the
  // recorded steps only: a solve that ends on Ceres's function tolerance has run one more linear
  // solve, for a step it does not take or record, so linear_solves can exceed
  // recorded_linear_solves by one per solve.
  struct Times {
    double setup = 0, preprocessor = 0, minimizer = 0;
    double residual_evaluation = 0, jacobian_evaluation = 0, linear_solver = 0;
    int residual_evaluations = 0, jacobian_evaluations = 0, linear_solves = 0;
    int recorded_linear_solves = 0;
    long linear_iterations = 0;
  } times;
};

Status optimize_stage(Mesh* mesh, const StageSpec& spec, StageResult* result);

// The worst shape quality and the inverted count of a mesh, measured exactly as the progress
// line measures them (sample points of validity_rule(rule), which include every corner;
// quality = d det(T)^(2/d) / |T|^2 with T relative to the ideal element: the mean ratio for
// simplices).
IterationRecord measure_mesh(const Mesh& mesh, SampleRule rule);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_STAGE_H_
