// tmop_bench: one reproducible, measured run with a JSON record (docs/benchmarks.md).
//
//   tmop_bench --input=MESH --task=TASK [--threads=N] [--repeat=K] [--json=FILE]
//              [--reference=FILE] [--max_iterations=N] [--max_seconds=S]
//
// Tasks:
//   read      read_mesh (the mesh is read K times)
//   quality   measure_mesh (the optimizer's per-iteration measure) and compute_quality (the full
//             report of tmop_quality), each timed
//   shape     the improve_shape recipe with its defaults (what tmop_optimize --recipe=shape runs)
//   untangle  the untangle recipe (untangle only; --then_shape adds the shape stage)
//   evaluate  the cost of one residual + Jacobian pass through Ceres: a ceres::Problem built like
//             optimize_stage's (one SamplePointCost per sample point with a free node, parameter
//             blocks = the vertex coordinates, boundary constant), timed with
//             Problem::Evaluate(cost, gradient) K times (Ceres evaluates every block's residuals
//             and Jacobians and sums J^T r); also the problem-construction time, and one Ceres
//             iteration measured as optimize_stage(max_iterations=1) - optimize_stage(0); and
//             the floor below, so the record carries the ratio.
//   floor     a hand-written lower bound of that pass without Ceres: T = sum_i x_i G_i^T with
//             precomputed G_i = W^-T grad N_i, the metric's residuals and dr/dT (tmop::Metric),
//             dF/dT = sum_k r_k dr_k/dT, gradient accumulated into a vertex array; one thread.
//   perturb   writes --output: interior vertices moved in a random direction by --amount x their
//             shortest incident edge (fixed --seed); --keep_valid retries (20 tries) moves that
//             would invert an incident element, otherwise the move is kept whatever it does.
//
// Timings: wall (steady clock) and CPU (getrusage user+sys, all threads) around the measured
// part only (reading the mesh is outside, except for --task=read); peak RSS is the process's
// (ru_maxrss). With --repeat=K the task runs K times on fresh copies of the input; the record
// gives the median and the minimum and every run's wall time. The load average at the start is
// recorded because shared machines make wall times noisy.
#include <ceres/ceres.h>
#include <gflags/gflags.h>
#include <glog/logging.h>
#include <sys/resource.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <deque>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/topology.h"
#include "tmop/mesh/validate.h"
#include "tmop/optimize/sample_point_cost.h"
#include "tmop/optimize/stage.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/recipe_result.h"
#include "tmop/recipes/untangle.h"
#include "tmop/target/target.h"
#include "tools/bench/floor.h"
#include "tools/bench/perturb.h"
#include "tools/bench/record.h"
#include "tools/parse_flags.h"
#include "tools/print_error.h"

DEFINE_string(input, "", "Input mesh (any format read_mesh reads).");
DEFINE_string(task, "shape", "read, quality, shape, untangle, evaluate, floor or perturb.");
DEFINE_int32(threads, 0, "Threads for Ceres (0 = all hardware threads). floor is one thread.");
DEFINE_int32(part_size, -1,
             "Partitioned stages: elements per part; 0: one problem; -1: the default.");
DEFINE_double(part_first_tolerance, -1,
              "Partitioned stages: the first sweep's tolerance (0: function_tolerance; -1: the "
              "default).");
DEFINE_bool(isolated_hdf5_reads, true,
            "Read .cgns and netCDF-4 .exo files in a child process, as every tool does (false: in "
            "the process, to measure what the isolation costs: docs/formats.md).");
DEFINE_int32(repeat, 1, "Run the task this many times; times are reported per run.");
DEFINE_string(json, "", "Also write the JSON record to this file.");
DEFINE_string(reference, "", "Reference mesh: targets are its Jacobians (--target=reference).");
DEFINE_string(metric, "", "Metric (default: the recipe's shape metric).");
DEFINE_int32(max_iterations, 200, "Maximum Ceres iterations per stage (shape, untangle).");
DEFINE_double(max_seconds, 1e9, "Wall-clock cap per stage, seconds (shape, untangle).");
DEFINE_bool(then_shape, false, "untangle: run the shape stage after untangling (recipe auto).");
DEFINE_string(linear_solver, "auto", "auto, cholesky or cgnr (SolverOptions::LinearSolver).");
DEFINE_string(solver, "lm", "lm or dogleg.");
DEFINE_int32(cholesky_max_free_coordinates, -1,
             "auto picks sparse Cholesky up to this many free coordinates, 2D and 3D alike (-1: "
             "the library's defaults, SolverOptions::cholesky_max_free_coordinates_2d / _3d).");
DEFINE_int32(cgnr_max_iterations, 0,
             "CGNR inner iterations per step, for 2D and 3D meshes alike (0: the library's "
             "defaults, SolverOptions::cgnr_max_iterations_2d / _3d).");
DEFINE_double(power, 0,
              "Shape: power order of the objective (0: the recipe's default, 2; 1: plain mean).");
DEFINE_double(function_tolerance, -1,
              "Relative objective decrease that ends a solve (-1: the library's default).");
DEFINE_bool(verbose, false, "Print the solver's progress lines.");
DEFINE_string(output, "", "perturb: the perturbed mesh (binary .msh 4.1 when .msh).");
DEFINE_double(amount, 0.3, "perturb: move length as a fraction of the shortest incident edge.");
DEFINE_int64(seed, 1, "perturb: random seed.");
DEFINE_bool(keep_valid, true, "perturb: never invert an element (retry the move).");

namespace {

using namespace tmop_bench;  // NOLINT: the record and perturbation helpers of this tool

int fail(int code, const std::string& message) {
  tmop_tools::print_error("tmop_bench", message,
                          {FLAGS_input, FLAGS_output, FLAGS_reference, FLAGS_json});
  return code;
}

// ---- tasks -------------------------------------------------------------------------------------

struct Context {
  std::string path;
  tmop::Mesh mesh;  // as read (reoriented when it uses the opposite convention)
  tmop::Mesh reference;
  bool has_reference = false;
  int threads = 0;
};

void add_recipe(const tmop::RecipeResult& r, const tmop::Status& s, Json* j) {
  int iterations = 0, solves = 0;
  for (const tmop::StageResult& st : r.stages) {
    iterations += st.iterations;
    solves += st.solves;
  }
  std::string stages = "[";
  for (std::size_t i = 0; i < r.stages.size(); ++i) {
    const tmop::StageResult& st = r.stages[i];
    Json o;
    o.str("name", st.name)
        .str("linear_solver", st.linear_solver)
        .integer("iterations", st.iterations)
        .integer("solves", st.solves)
        .num("seconds", st.seconds)
        .num("seconds_per_iteration", st.iterations ? st.seconds / st.iterations : 0)
        .num("initial_objective", st.initial_objective)
        .num("final_objective", st.final_objective)
        .integer("sample_points", st.num_sample_points)
        .integer("free_vertices", st.num_free_vertices)
        .integer("parts", st.parts)
        .integer("sweeps", st.sweeps)
        .integer("element_iterations",
                 st.parts ? st.part_element_iterations
                          : static_cast<std::int64_t>(st.num_elements) * st.iterations)
        .str("termination", st.termination);
    // Ceres's own split of the time, and the scaling figures of docs/benchmarks.md: minimizer
    // time per element and iteration, linear-solver time per element and inner iteration.
    const tmop::StageResult::Times& t = st.times;
    const double elements = std::max(1, st.num_elements);
    Json times;
    times.num("setup", t.setup)
        .num("preprocessor", t.preprocessor)
        .num("minimizer", t.minimizer)
        .num("residual_evaluation", t.residual_evaluation)
        .integer("residual_evaluations", t.residual_evaluations)
        .num("jacobian_evaluation", t.jacobian_evaluation)
        .integer("jacobian_evaluations", t.jacobian_evaluations)
        .num("linear_solver", t.linear_solver)
        .integer("linear_solves", t.linear_solves)
        .integer("recorded_linear_solves", t.recorded_linear_solves)
        .integer("linear_iterations", t.linear_iterations);
    // Per inner iteration: the mean time of a linear solve over the mean inner iterations of the
    // recorded steps (Ceres does not record the last, untaken step's count; stage.h).
    const double per_solve = t.linear_solves ? t.linear_solver / t.linear_solves : 0;
    const double inner_per_solve =
        t.recorded_linear_solves ? double(t.linear_iterations) / t.recorded_linear_solves : 0;
    o.obj("times", times)
        .num("us_per_element_iteration",
             st.iterations ? 1e6 * t.minimizer / (elements * st.iterations) : 0)
        .num("us_per_element_evaluation",
             t.jacobian_evaluations
                 ? 1e6 * t.jacobian_evaluation / (elements * t.jacobian_evaluations)
                 : 0)
        .num("linear_iterations_per_step", inner_per_solve)
        .num("us_per_element_linear_iteration",
             inner_per_solve > 0 ? 1e6 * per_solve / (elements * inner_per_solve) : 0);
    stages += (i ? ", " : "") + o.text();
  }
  j->boolean("ok", s.ok())
      .str("message", s.message())
      .integer("iterations", iterations)
      .integer("solves", solves)
      .num("final_objective", r.stages.empty() ? 0 : r.stages.back().final_objective)
      .num("min_quality_before", r.before.min_quality)
      .num("min_quality_after", r.after.min_quality)
      .integer("inverted_before", r.before.inverted)
      .integer("inverted_after", r.after.inverted)
      .raw("stages", stages + "]");
}

tmop::SolverOptions solver_options(const Context& ctx) {
  tmop::SolverOptions so;
  so.max_iterations = FLAGS_max_iterations;
  so.max_seconds = FLAGS_max_seconds;
  so.threads = ctx.threads;
  if (FLAGS_part_size >= 0) so.part_size = FLAGS_part_size;
  if (FLAGS_part_first_tolerance >= 0) so.first_sweep_tolerance = FLAGS_part_first_tolerance;
  so.verbose = FLAGS_verbose;
  tmop::linear_solver_from_name(FLAGS_linear_solver, &so.linear_solver);
  tmop::solver_method_from_name(FLAGS_solver, &so.method);
  if (FLAGS_cholesky_max_free_coordinates >= 0) {
    so.cholesky_max_free_coordinates_2d = FLAGS_cholesky_max_free_coordinates;
    so.cholesky_max_free_coordinates_3d = FLAGS_cholesky_max_free_coordinates;
  }
  if (FLAGS_function_tolerance >= 0) so.function_tolerance = FLAGS_function_tolerance;
  if (FLAGS_cgnr_max_iterations > 0)
    so.cgnr_max_iterations_2d = so.cgnr_max_iterations_3d = FLAGS_cgnr_max_iterations;
  return so;
}

tmop::TargetSpec target_spec(const Context& ctx) {
  tmop::TargetSpec t;
  if (ctx.has_reference) {
    t.type = tmop::TargetType::kReference;
    t.reference = &ctx.reference;
  }
  return t;
}

// The last repeat takes the mesh itself, so peak_rss_mb counts one mesh, as tmop_optimize
// has (a copy of the 1M-tet mesh is 39 MB).
int run_recipe(Context* context, Json* j) {
  const Context& ctx = *context;
  Timing timing;
  tmop::RecipeResult result;
  tmop::Status s;
  for (int k = 0; k < FLAGS_repeat; ++k) {
    tmop::Mesh mesh = k + 1 < FLAGS_repeat ? ctx.mesh : std::move(context->mesh);
    tmop::ShapeOptions shape;
    shape.metric = FLAGS_metric;
    shape.power = FLAGS_power;
    shape.target = target_spec(ctx);
    shape.solver = solver_options(ctx);
    timing.start();
    if (FLAGS_task == "shape") {
      s = tmop::improve_shape(&mesh, shape, &result);
    } else {
      tmop::UntangleOptions u;
      u.target = shape.target;
      u.solver = shape.solver;
      u.improve_shape_after = FLAGS_then_shape;
      u.shape = shape;
      s = tmop::untangle(&mesh, u, &result);
    }
    timing.stop();
  }
  timing.add_to(j);
  add_recipe(result, s, j);
  return s.ok() ? 0 : 1;
}

int run_read(const Context& ctx, Json* j) {
  Timing timing;
  for (int k = 0; k < FLAGS_repeat; ++k) {
    tmop::Mesh mesh;
    timing.start();
    tmop::Status s = tmop::read_mesh(ctx.path, &mesh);
    timing.stop();
    if (!s.ok()) return fail(2, s.message());
  }
  timing.add_to(j);
  return 0;
}

int run_quality(const Context& ctx, Json* j) {
  Timing measure, full;
  tmop::IterationRecord rec;
  std::int64_t inverted = 0;
  for (int k = 0; k < FLAGS_repeat; ++k) {
    measure.start();
    rec = tmop::measure_mesh(ctx.mesh, tmop::SampleRule::kDefault);
    measure.stop();
    full.start();
    const tmop::QualityReport report = tmop::compute_quality(ctx.mesh);
    full.stop();
    inverted = report.inverted_cells;
  }
  full.add_to(j);
  Json m;
  measure.add_to(&m);
  j->obj("measure_mesh", m)
      .num("min_quality_before", rec.min_quality)
      .integer("inverted_before", rec.inverted)
      .integer("inverted_cells_report", inverted);
  return 0;
}

std::shared_ptr<const tmop::Metric> bench_metric(int d) {
  std::string error;
  auto m = tmop::recipe_metric(FLAGS_metric, d, 1.0, &error);
  if (!m) std::fprintf(stderr, "tmop_bench: %s\n", error.c_str());
  return m;
}

// The floor: K passes, one thread.
int run_floor(const Context& ctx, const PointTable& pt, const tmop::Metric& metric, Json* j,
              double* seconds, double* cpu = nullptr) {
  Timing timing;
  std::vector<double> gradient;
  double cost = 0;
  for (int k = 0; k < std::max(FLAGS_repeat, 3); ++k) {
    timing.start();
    if (!floor_pass(ctx.mesh, pt, metric, &gradient, &cost))
      return fail(1, "the metric failed at a sample point (inverted mesh and barrier metric)");
    timing.stop();
  }
  double gmax = 0;
  for (double g : gradient) gmax = std::max(gmax, std::abs(g));
  *seconds = median(timing.wall);
  if (cpu) *cpu = median(timing.cpu);
  timing.add_to(j);
  j->integer("sample_points", static_cast<long long>(pt.cell.size()))
      .num("points_per_second", pt.cell.size() / std::max(1e-12, *seconds))
      .num("points_per_cpu_second", pt.cell.size() / std::max(1e-12, median(timing.cpu)))
      .num("cost", cost)
      .num("gradient_max_norm", gmax);
  return 0;
}

int run_evaluate(const Context& ctx, Json* j) {
  tmop::Mesh mesh = ctx.mesh;
  const int d = mesh.dim();
  auto metric = bench_metric(d);
  if (!metric) return 2;
  const std::vector<char> fixed = tmop::boundary_vertex_mask(mesh);
  PointTable pt;
  auto t0 = Clock::now();
  tmop::Status s = build_points(mesh, target_spec(ctx), fixed, &pt);
  if (!s.ok()) return fail(2, s.message());
  const double targets_seconds = seconds_since(t0);

  // Problem construction, as optimize_stage does it.
  t0 = Clock::now();
  double c0 = cpu_seconds();
  ceres::Problem::Options popts;
  popts.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  popts.enable_fast_removal = false;
  popts.disable_all_safety_checks = true;
  ceres::Problem problem(popts);
  std::deque<tmop::SamplePointCost> costs;
  std::vector<double*> blocks;
  std::vector<char> in_problem(mesh.num_vertices(), 0);
  for (std::size_t p = 0; p < pt.cell.size(); ++p) {
    const int c = pt.cell[p], n = mesh.cell_size(c);
    tmop::SamplePointTerm term;
    term.metric = metric.get();
    term.G = pt.G.data() + pt.offset[p];
    term.sqrt_weight = pt.weight[p];
    costs.emplace_back(n, d, 1, &term);
    blocks.clear();
    for (int i = 0; i < n; ++i) {
      blocks.push_back(mesh.vertex(mesh.cell(c)[i]));
      in_problem[mesh.cell(c)[i]] = 1;
    }
    problem.AddResidualBlock(&costs.back(), nullptr, blocks);
  }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (in_problem[v] && fixed[v]) problem.SetParameterBlockConstant(mesh.vertex(v));
  const double construct_wall = seconds_since(t0), construct_cpu = cpu_seconds() - c0;

  ceres::Problem::EvaluateOptions eopts;
  eopts.num_threads = ctx.threads > 0 ? ctx.threads : std::thread::hardware_concurrency();
  Timing timing;
  double cost = 0;
  std::vector<double> gradient;
  for (int k = 0; k < std::max(FLAGS_repeat, 3); ++k) {
    timing.start();
    if (!problem.Evaluate(eopts, &cost, nullptr, &gradient, nullptr))
      return fail(1, "Ceres evaluation failed (inverted mesh and barrier metric?)");
    timing.stop();
  }
  const double eval_seconds = median(timing.wall);
  timing.add_to(j);
  j->integer("sample_points", static_cast<long long>(pt.cell.size()))
      .integer("evaluate_threads", eopts.num_threads)
      .num("points_per_second", pt.cell.size() / std::max(1e-12, eval_seconds))
      .num("points_per_cpu_second", pt.cell.size() / std::max(1e-12, median(timing.cpu)))
      .num("cost", cost)
      .num("targets_seconds", targets_seconds)
      .num("problem_construction_seconds", construct_wall)
      .num("problem_construction_cpu_seconds", construct_cpu);

  Json floor;
  double floor_seconds = 0, floor_cpu = 0;
  if (int rc = run_floor(ctx, pt, *metric, &floor, &floor_seconds, &floor_cpu)) return rc;
  // On a loaded machine the CPU-time ratio is the trustworthy one (floor is one thread).
  j->obj("floor", floor)
      .num("ratio_to_floor", eval_seconds / std::max(1e-12, floor_seconds))
      .num("ratio_to_floor_cpu", median(timing.cpu) / std::max(1e-12, floor_cpu));

  // One Ceres iteration inside optimize_stage: (max_iterations = 1) - (max_iterations = 0).
  // Both include the stage's set-up (targets, problem, measures) and Ceres's preprocessing;
  // the difference is one trust-region step: linear solve, evaluations, callback.
  double stage_seconds[2] = {0, 0}, stage_cpu[2] = {0, 0};
  tmop::StageResult sr[2];
  for (int iters = 0; iters <= 1; ++iters) {
    tmop::StageSpec spec;
    spec.name = "evaluate";
    tmop::TermSpec term;
    term.metric = metric;
    term.target = target_spec(ctx);
    spec.terms.push_back(term);
    spec.solver = solver_options(ctx);
    spec.solver.max_iterations = iters;
    std::vector<double> times, cpus;
    for (int k = 0; k < std::max(FLAGS_repeat, 3); ++k) {
      tmop::Mesh m = ctx.mesh;
      t0 = Clock::now();
      c0 = cpu_seconds();
      s = tmop::optimize_stage(&m, spec, &sr[iters]);
      times.push_back(seconds_since(t0));
      cpus.push_back(cpu_seconds() - c0);
      if (!s.ok()) return fail(1, s.message());
    }
    stage_seconds[iters] = median(times);
    stage_cpu[iters] = median(cpus);
  }
  j->num("stage_seconds_0_iterations", stage_seconds[0])
      .num("stage_seconds_1_iteration", stage_seconds[1])
      .num("ceres_iteration_seconds", stage_seconds[1] - stage_seconds[0])
      .num("stage_cpu_seconds_0_iterations", stage_cpu[0])
      .num("ceres_iteration_cpu_seconds", stage_cpu[1] - stage_cpu[0])
      .str("linear_solver", sr[1].linear_solver);
  return 0;
}

int run_perturb(Context* ctx, Json* j) {
  if (FLAGS_output.empty()) return fail(2, "--task=perturb needs --output");
  const tmop::IterationRecord before = tmop::measure_mesh(ctx->mesh, tmop::SampleRule::kDefault);
  int moved = 0;
  Timing timing;
  timing.start();
  perturb(&ctx->mesh, FLAGS_amount, static_cast<std::uint64_t>(FLAGS_seed), FLAGS_keep_valid,
          &moved);
  timing.stop();
  const tmop::IterationRecord after = tmop::measure_mesh(ctx->mesh, tmop::SampleRule::kDefault);
  tmop::WriteOptions w;
  w.binary = true;
  tmop::Status s = tmop::write_mesh(FLAGS_output, ctx->mesh, w);
  if (!s.ok()) return fail(2, s.message());
  timing.add_to(j);
  const int elements = ctx->mesh.num_elements();
  j->str("output", FLAGS_output)
      .num("amount", FLAGS_amount)
      .integer("seed", FLAGS_seed)
      .boolean("keep_valid", FLAGS_keep_valid)
      .integer("moved_vertices", moved)
      .num("min_quality_before", before.min_quality)
      .num("min_quality_after", after.min_quality)
      .integer("inverted_before", before.inverted)
      .integer("inverted_after", after.inverted)
      .num("inverted_fraction", elements ? static_cast<double>(after.inverted) / elements : 0);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "reproducible speed/scale runs with a JSON record\n"
      "  tmop_bench --input=MESH --task=shape|untangle|read|quality|evaluate|floor|perturb");
  tmop_tools::parse_flags(&argc, &argv);
  tmop::set_isolated_hdf5_reads(FLAGS_isolated_hdf5_reads);
  tmop::remove_temporaries_on_signal("tmop_bench");
  FLAGS_minloglevel = FLAGS_verbose ? 1 : 3;
  google::InitGoogleLogging(argv[0]);
  if (FLAGS_input.empty()) return fail(2, "--input is required (see --help)");
  const std::string task = FLAGS_task;
  if (task != "read" && task != "quality" && task != "shape" && task != "untangle" &&
      task != "evaluate" && task != "floor" && task != "perturb")
    return fail(2, "unknown --task '" + task + "'");
  if (FLAGS_repeat < 1) return fail(2, "--repeat must be >= 1");
  {
    tmop::SolverOptions::LinearSolver ls;
    tmop::SolverOptions::Method method;
    if (!tmop::linear_solver_from_name(FLAGS_linear_solver, &ls))
      return fail(2, "unknown --linear_solver '" + FLAGS_linear_solver + "'");
    if (!tmop::solver_method_from_name(FLAGS_solver, &method))
      return fail(2, "unknown --solver '" + FLAGS_solver + "'");
  }

  Json j;
  j.str("tool", "tmop_bench")
      .str("task", task)
      .str("date", utc_now())
      .str("commit", git_commit())
      .str("built", __DATE__ " " __TIME__)
      .obj("machine", machine_json())
      .num("load_average_1min", load_average());

  Context ctx;
  ctx.path = FLAGS_input;
  ctx.threads = FLAGS_threads;
  const auto read_start = Clock::now();
  tmop::Status s = tmop::read_mesh(FLAGS_input, &ctx.mesh);
  if (!s.ok()) return fail(2, s.message());
  const double read_seconds = seconds_since(read_start);
  s = tmop::validate_mesh(ctx.mesh);
  if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  if (!FLAGS_reference.empty()) {
    s = tmop::read_mesh(FLAGS_reference, &ctx.reference);
    if (!s.ok()) return fail(2, s.message());
    ctx.has_reference = true;
  }
  // As tmop_optimize: a mesh in the opposite orientation convention is optimized reoriented.
  if (task != "perturb" && task != "read" &&
      tmop::check_orientation(ctx.mesh).opposite_convention()) {
    tmop::reorient(&ctx.mesh);
    if (ctx.has_reference) tmop::reorient(&ctx.reference);
    j.boolean("reoriented", true);
  }
  const int num_elements = ctx.mesh.num_elements();  // the last repeat may take the mesh
  j.obj("mesh", mesh_json(ctx.mesh, FLAGS_input))
      .num("read_seconds", read_seconds)
      .integer("threads", FLAGS_threads > 0 ? FLAGS_threads : std::thread::hardware_concurrency())
      .integer("repeat", FLAGS_repeat)
      .str("linear_solver_flag", FLAGS_linear_solver)
      .num("power_flag", FLAGS_power)
      .str("solver_flag", FLAGS_solver);

  int rc = 0;
  if (task == "read") {
    rc = run_read(ctx, &j);
  } else if (task == "quality") {
    rc = run_quality(ctx, &j);
  } else if (task == "shape" || task == "untangle") {
    rc = run_recipe(&ctx, &j);
  } else if (task == "evaluate") {
    rc = run_evaluate(ctx, &j);
  } else if (task == "floor") {
    auto metric = bench_metric(ctx.mesh.dim());
    if (!metric) return 2;
    PointTable pt;
    s = build_points(ctx.mesh, target_spec(ctx), tmop::boundary_vertex_mask(ctx.mesh), &pt);
    if (!s.ok()) return fail(2, s.message());
    double seconds = 0;
    rc = run_floor(ctx, pt, *metric, &j, &seconds);
  } else {
    rc = run_perturb(&ctx, &j);
  }
  if (rc == 2) return rc;
  j.num("peak_rss_mb", peak_rss_mb())
      .num("peak_rss_bytes_per_element", peak_rss_mb() * 1048576.0 / std::max(1, num_elements));
  const std::string text = j.text();
  std::printf("%s\n", text.c_str());
  if (!FLAGS_json.empty()) {
    const tmop::Status written = tmop::write_file_atomically(FLAGS_json, text + "\n");
    if (!written.ok()) return fail(2, written.message());
  }
  return rc;
}
