// tmop_optimize: improve a mesh by moving its nodes (Target-Matrix Optimization Paradigm).
//
//   tmop_optimize --input=IN --output=OUT [--recipe=auto|shape|untangle] [--metric=NAME]
//                 [--target=NAME] [--reference=FILE] [--sample_points=RULE] [--power=P]
//                 [--solver=lm|dogleg] [--linear_solver=auto|cholesky|cgnr]
//                 [--max_iterations=N] [--threads=N] [--report=FILE.json] [--verbose]
//
// Exit status: 0 success; 1 the optimization could not reach its goal; 2 bad input or usage.
// Errors are one line on stderr. OUT is written atomically and only on success; IN is never
// opened for writing.
#include <gflags/gflags.h>
#include <glog/logging.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/validate.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/untangle.h"

DEFINE_string(input, "", "Input mesh (.msh .vtk .vtu .mesh .obj .off .ply .stl).");
DEFINE_string(output, "", "Output mesh; format by extension. Written only on success.");
DEFINE_string(recipe, "auto",
              "auto: untangle if anything is inverted, then improve shape; "
              "shape: shape improvement with a barrier metric (the input must be valid); "
              "untangle: untangle only.");
DEFINE_bool(write_on_failure, false,
            "When untangling fails, still write the best mesh reached to --output.");
DEFINE_string(metric, "", "Metric name (default: the recipe's); see --list_metrics.");
DEFINE_bool(list_metrics, false, "Print the metric names for 2D and 3D meshes and exit.");
DEFINE_string(target, "equal_size",
              "Target construction: ideal_unit, equal_size, local_size, reference, "
              "lambda_identity, size_field.");
DEFINE_string(reference, "",
              "Mesh with the same vertices and cells whose Jacobians are the targets "
              "(implies --target=reference).");
DEFINE_string(size_field, "", "Point-data array of target edge lengths (--target=size_field).");
DEFINE_string(sample_points, "default", "Sample rule: default, corners, nodes, centroid, gauss.");
DEFINE_double(power, 1.0,
              "Power order of the objective: 1 = plain mean; > 1 weights the worst elements up.");
DEFINE_string(solver, "lm", "Trust-region method: lm (Levenberg-Marquardt) or dogleg.");
DEFINE_string(linear_solver, "auto", "auto, cholesky (sparse normal Cholesky) or cgnr.");
DEFINE_int32(max_iterations, 200, "Maximum solver iterations per stage.");
DEFINE_double(max_seconds, 1e9, "Wall-clock limit per stage, seconds.");
DEFINE_int32(threads, 0, "Threads for evaluation and linear algebra (0 = all cores).");
DEFINE_string(report, "", "Write a JSON report of the run to this file.");
DEFINE_bool(binary, false, "Write binary output where the format has a binary form.");
DEFINE_string(boundary, "fixed", "Boundary vertices: fixed (sliding comes with geometry).");
DEFINE_bool(verbose, false, "Print a progress line per solver iteration.");

namespace {

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "tmop_optimize: %s\n", message.c_str());
  return code;
}

bool write_text_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) return false;
    out << text << "\n";
    if (!out.good()) return false;
  }
  return std::rename(tmp.c_str(), path.c_str()) == 0;
}

void print_measure(const char* label, const tmop::IterationRecord& r, int elements) {
  std::printf("%-7s elements %d  inverted %d  worst shape quality %.6f\n", label, elements,
              r.inverted, r.min_quality);
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "improve a mesh by node movement\n"
      "  tmop_optimize --input=IN --output=OUT [--recipe=auto|shape] [flags]");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  // Ceres reports through glog; the tool reports itself (one line on failure).
  FLAGS_minloglevel = FLAGS_verbose ? 1 : 3;
  google::InitGoogleLogging(argv[0]);
  using namespace tmop;

  if (FLAGS_list_metrics) {
    for (int d = 2; d <= 3; ++d) {
      std::printf("%dD:", d);
      for (const std::string& n : metric_names(d)) std::printf(" %s", n.c_str());
      std::printf("\n");
    }
    return 0;
  }
  if (FLAGS_input.empty() || FLAGS_output.empty())
    return fail(2, "--input and --output are required (see --help)");
  if (FLAGS_recipe != "auto" && FLAGS_recipe != "shape" && FLAGS_recipe != "untangle")
    return fail(2, "unknown --recipe '" + FLAGS_recipe + "' (known: auto, shape, untangle)");
  if (FLAGS_boundary != "fixed")
    return fail(2, "--boundary=" + FLAGS_boundary + " is not available yet (only fixed)");

  ShapeOptions opt;
  opt.metric = FLAGS_metric;
  opt.power = FLAGS_power;
  if (!sample_rule_from_name(FLAGS_sample_points, &opt.rule))
    return fail(2, "unknown --sample_points '" + FLAGS_sample_points + "'");
  std::string target = FLAGS_reference.empty() ? FLAGS_target : "reference";
  if (!target_type_from_name(target, &opt.target.type))
    return fail(2, "unknown --target '" + target + "'");
  opt.target.size_field = FLAGS_size_field;
  if (!solver_method_from_name(FLAGS_solver, &opt.solver.method))
    return fail(2, "unknown --solver '" + FLAGS_solver + "' (lm, dogleg)");
  if (!linear_solver_from_name(FLAGS_linear_solver, &opt.solver.linear_solver))
    return fail(2, "unknown --linear_solver '" + FLAGS_linear_solver + "'");
  opt.solver.max_iterations = FLAGS_max_iterations;
  opt.solver.max_seconds = FLAGS_max_seconds;
  opt.solver.threads = FLAGS_threads;
  opt.solver.verbose = FLAGS_verbose;

  Mesh mesh;
  Status s = read_mesh(FLAGS_input, &mesh);
  if (!s.ok()) return fail(2, s.message());
  s = validate_mesh(mesh);
  if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  Mesh reference;
  if (!FLAGS_reference.empty()) {
    s = read_mesh(FLAGS_reference, &reference);
    if (!s.ok()) return fail(2, s.message());
    opt.target.reference = &reference;
  }

  // A mesh written with the opposite orientation convention is not "all inverted": optimize it
  // in tmop's convention and write it back in its own.
  const OrientationReport orientation = check_orientation(mesh);
  const bool flipped = orientation.opposite_convention();
  if (flipped) {
    std::printf(
        "note: %s uses the opposite orientation convention (%d of %d cells negative); "
        "handled\n",
        FLAGS_input.c_str(), orientation.negative,
        orientation.positive + orientation.negative + orientation.mixed_or_zero);
    reorient(&mesh);
    if (opt.target.reference) reorient(&reference);
  }

  RecipeResult result;
  const IterationRecord before = measure_mesh(mesh, opt.rule);
  const int elements = mesh.num_elements();
  print_measure("before:", before, elements);
  bool write_anyway = false;
  if (FLAGS_recipe == "shape") {
    if (before.inverted > 0)
      return fail(1, FLAGS_input + ": " + std::to_string(before.inverted) +
                         " inverted elements: recipe shape needs a valid mesh (use --recipe=auto "
                         "or untangle)");
    s = improve_shape(&mesh, opt, &result);
  } else {
    UntangleOptions u;
    u.target = opt.target;  // untangle toward the reference when one is given
    if (opt.target.type != TargetType::kReference) u.target.type = TargetType::kIdealEqualSize;
    u.rule = opt.rule;
    u.solver = opt.solver;
    u.improve_shape_after = FLAGS_recipe == "auto";
    u.shape = opt;
    s = untangle(&mesh, u, &result);
    write_anyway = !s.ok() && FLAGS_write_on_failure && !result.stages.empty();
  }
  for (const StageResult& st : result.stages)
    std::printf("stage %s: objective %.6g -> %.6g in %d iterations (%d solves), %.2f s (%s)\n",
                st.name.c_str(), st.initial_objective, st.final_objective, st.iterations, st.solves,
                st.seconds, st.termination.c_str());
  if (!s.ok() && !write_anyway) return fail(1, FLAGS_input + ": " + s.message());
  print_measure("after:", result.after, elements);
  if (result.certified >= 0)
    std::printf("certified valid everywhere (Bernstein bound): %d of %d quadratic cells\n",
                result.certified, result.certified + result.uncertified);

  if (flipped) reorient(&mesh);
  WriteOptions wopt;
  wopt.binary = FLAGS_binary;
  s = write_mesh(FLAGS_output, mesh, wopt);
  if (!s.ok()) return fail(2, s.message());
  std::printf("wrote %s\n", FLAGS_output.c_str());
  if (!FLAGS_report.empty() && !write_text_atomically(FLAGS_report, recipe_json(result)))
    return fail(2, FLAGS_report + ": cannot write the report");
  if (write_anyway) return fail(1, FLAGS_input + ": " + s.message() + " (best mesh written)");
  return 0;
}
