// tools/optimize/flags.cc: tmop_optimize's flags and what they become (flags.h).
#include "tools/optimize/flags.h"

#include <sys/stat.h>

#include <string>

#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/metric/metric.h"
#include "tmop/recipes/recipe_geometry.h"
#include "tmop/target/composed_target.h"
#include "tmop/target/target.h"
#include "tools/print_error.h"

DEFINE_string(input, "",
              "Input mesh (.msh .vtk .vtu .mesh .ugrid .exo .e .cgns .obj .off .ply .stl).");
DEFINE_string(output, "", "Output mesh; format by extension. Written only on success.");
// --help lists the recipes of the registry (tmop/recipes/recipe.h) with their summaries.
static const std::string recipe_help = [] {
  std::string h;
  for (const tmop::RecipeInfo& r : tmop::recipes())
    h += std::string(h.empty() ? "" : "; ") + r.name + ": " + r.summary;
  return h + " (an option a recipe does not use is refused)";
}();
DEFINE_string(recipe, "auto", recipe_help.c_str());
DEFINE_string(fixed_nodes, "",
              "Nodes held fixed (bit for bit) in addition to the --boundary mode's: a text file "
              "of 0-based node indices separated by whitespace or newlines, # comments; or "
              "field:NAME, a point-data array of the input (nonzero = fixed). Recipe preserve: "
              "they take their --moved positions.");
DEFINE_string(from_report, "",
              "Rerun with the flags recorded in this --report file (flags given on the command "
              "line override; --output and --report are never taken from it).");
DEFINE_bool(write_on_failure, false,
            "When the recipe fails (e.g. cannot untangle or certify), still write --output: the "
            "result if it has fewer inverted cells than the input, else the input; exit 1.");
DEFINE_string(metric, "",
              "Metric name (default: the recipe's; see --list_metrics), or a weighted "
              "combination of two: W1*NAME1+W2*NAME2 (e.g. 0.7*shape_barrier+0.3*size_barrier).");
DEFINE_bool(list_metrics, false, "Print the metric names for 2D and 3D meshes and exit.");
DEFINE_string(target, "equal_size",
              "Target construction: ideal_unit, equal_size, local_size, reference, "
              "lambda_identity, size_field, composed (W = size x orientation x skew x aspect, "
              "each factor from --target_size, --target_orientation, --target_shape / "
              "--target_skew / --target_aspect; docs/theory.md).");
DEFINE_string(reference, "",
              "Mesh with the same vertices and cells whose Jacobians are the targets "
              "(implies --target=reference; with --target=composed it is the mesh the 'initial' "
              "factors come from).");
DEFINE_string(target_size, "equal",
              "--target=composed: size h (equivalent edge length): equal (mean of the input), "
              "initial (the input's at each point), ideal (as --target=ideal_unit), field:NAME "
              "(point data, the input's units), or a length in the input's units.");
DEFINE_string(target_orientation, "identity",
              "--target=composed: rotation: identity, initial, field:NAME (point-data vectors: "
              "2D the first axis, 3D two axes = 6 components), angle:DEG (2D), or axis "
              "components (2D: x,y; 3D: x1,y1,z1,x2,y2,z2).");
DEFINE_string(target_shape, "ideal",
              "--target=composed: skew and aspect together: ideal (the element type's ideal "
              "shape) or initial (the input's shape at each point).");
DEFINE_string(target_skew, "",
              "--target=composed: angles between the element's edge directions (default: "
              "--target_shape): ideal, initial, field:NAME, or degrees (2D: PHI; 3D: "
              "PHI12,PHI13,PHI23).");
DEFINE_string(target_aspect, "",
              "--target=composed: relative edge lengths (default: --target_shape): ideal, "
              "initial, smooth (the initial mesh's, averaged over neighbours), field:NAME, or "
              "lengths (2D: L1,L2; 3D: L1,L2,L3).");
DEFINE_string(size_field, "", "Point-data array of target edge lengths (--target=size_field).");
DEFINE_string(sample_points, "default", "Sample rule: default, corners, nodes, centroid, gauss.");
DEFINE_double(power, 0,
              "Power order p of the objective: 1 = plain mean; > 1 weights the worst elements "
              "up (one solve, a convex Ceres loss per point); 0 = the recipe's default (shape, "
              "auto, surface: 2; "
              "size_adapt: 1).");
DEFINE_string(solver, "lm",
              "Trust-region method: lm (Levenberg-Marquardt) or dogleg (always sparse Cholesky: "
              "slow on large 3D meshes).");
DEFINE_string(linear_solver, "auto", "auto, cholesky (sparse normal Cholesky) or cgnr.");
DEFINE_int32(max_iterations, 200,
             "Maximum Ceres iterations per solve of a stage (surface meshes: the budget of "
             "all frame rounds, 4x under a power; untangling: rounds of 5 iterations, up to "
             "60 eps rounds).");
DEFINE_double(max_seconds, 1e9, "Wall-clock limit per stage, seconds.");
DEFINE_double(function_tolerance, 1e-5,
              "A solve ends when an iteration lowers the objective by less than this fraction "
              "of itself (1e-5: within ~1e-4 of the converged objective; 1e-7 polishes the worst "
              "elements further at 2-3x the iterations).");
DEFINE_int32(threads, 0, "Threads for evaluation and linear algebra (0 = all cores).");
DEFINE_int32(part_size, -1,
             "Partitioned shape stages: elements per part (METIS), parts solved side by side "
             "on --threads; 0: one problem over the whole mesh; -1: the library's default "
             "(docs/partitioning.md).");
DEFINE_string(partitions, "auto",
              "Partitioned shape stages: auto (parts of --part_size elements from 2 parts' worth "
              "up), 1 (one problem) or K (K parts, at least 64 elements each).");
DEFINE_int32(part_sweeps, 4, "Partitioned stages: at most this many sweeps over the parts.");
DEFINE_double(
    part_first_tolerance, -1,
    "Partitioned stages: the first sweep's parts stop when a step lowers the objective by "
    "less than this fraction (0: as --function_tolerance; -1: the library's default, "
    "3e-4, docs/partitioning.md).");
DEFINE_int32(part_rings, 2,
             "Partitioned stages: sweeps after the first re-solve only the vertices within this "
             "many element rings of what moved since; 0: whole parts again.");
DEFINE_string(report, "", "Write a JSON report of the run to this file.");
DEFINE_bool(binary, false, "Write binary output where the format has a binary form.");
DEFINE_string(msh_version, "4.1",
              "Gmsh file-format version of a .msh output: 4.1 (what current Gmsh writes) or 2.2 "
              "(for old readers). Ignored for other formats.");
DEFINE_string(boundary, "fixed",
              "Boundary vertices: fixed, or slide (on their curves and surfaces; corners and "
              "feature edges are kept). Surface meshes always slide on their surface.");
DEFINE_string(geometry, "",
              "Geometry to slide on: sphere:cx,cy,cz,r / plane:px,py,pz,nx,ny,nz / "
              "cylinder:px,py,pz,dx,dy,dz,r / a surface file (.stl .obj .off .ply). Default: "
              "the input's own boundary.");
DEFINE_string(orientation, "auto",
              "Orientation convention of the input: auto (decided by the boundary: the signed "
              "volume (2D: area) its facets enclose as their cells orient them, which no tangle "
              "inside it can change; by a majority of the cells only when it encloses nothing), "
              "gmsh (det J > 0 is valid: Gmsh's and tmop's convention) or opposite (det J < 0 is "
              "valid: the cells are reoriented for the run and written back as they were).");
DEFINE_double(feature_angle, 30, "Boundary edges sharper than this (degrees) are features.");
DEFINE_string(moved, "",
              "Recipe preserve: the mesh with its boundary moved (same vertices and cells as "
              "--input); the interior follows, keeping the input's element shapes and sizes.");
DEFINE_double(shape_guard_weight, 1.0, "Recipe equal_edge: weight of the shape guard term.");
DEFINE_double(layer_edge_ratio, 3,
              "Recipe sliver: cells it keeps (max dihedral well below 135 deg) whose longest edge "
              "is at least this many times their shortest are boundary-layer cells; the vertices "
              "the layer shares with other cells are held. 0: nothing held.");
DEFINE_int32(max_sweeps, 100, "Recipe laplace: maximum Gauss-Seidel sweeps.");
DEFINE_bool(verbose, false, "Print a progress line per solver iteration.");
DEFINE_string(guarantee, "all",
              "What the result must keep against the input (docs/quality.md, Guarantees): all = "
              "no cell type's or region's worst element worse (each type by its own measures), "
              "no type's mean lower, no new slivers or inverted cells; worst = the same without "
              "the means (a trade of the average for other goals); off = nothing checked. A "
              "result that breaks one is not written (exit 1; --write_on_failure writes it). "
              "Recipes auto, shape, high_order, surface and untangle keep all; sliver and "
              "equal_edge the worst; size_adapt, preserve and laplace trade shape and are not "
              "checked.");

namespace tmop_tools {

using namespace tmop;

int fail(int code, const std::string& message) {
  tmop_tools::print_error("tmop_optimize", message,
                          {FLAGS_input, FLAGS_output, FLAGS_reference, FLAGS_moved, FLAGS_report,
                           FLAGS_geometry, FLAGS_fixed_nodes, FLAGS_from_report});
  return code;
}

namespace {

// True when both paths name one existing file (hard links and symlinks included).
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return !a.empty() && !b.empty() && ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 &&
         sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

}  // namespace

// Usage errors of the flags alone, said before any file is read: 0, or the exit code.
// --partitions as a count: 1 or K >= 2; 0 when it is not a whole number in [1, 2^31).
int partitions_from_flag() {
  const std::string& f = FLAGS_partitions;
  if (f.empty() || f.size() > 10 || f.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  const long long k = std::stoll(f);
  return k >= 1 && k <= 2147483647LL ? static_cast<int>(k) : 0;
}

int check_flags(int argc, char** argv) {
  if (argc > 1)
    return fail(2, std::string("unexpected argument '") + argv[1] +
                       "' (every option is a --flag=value; see --help)");
  if (FLAGS_input.empty() || FLAGS_output.empty())
    return fail(2, "--input and --output are required (see --help)");
  // Inputs are never modified: an output or report that is one of them is refused.
  for (const std::string* in : {&FLAGS_input, &FLAGS_reference, &FLAGS_moved, &FLAGS_fixed_nodes})
    for (const std::string* out : {&FLAGS_output, &FLAGS_report})
      if (same_file(*in, *out))
        return fail(2, *out + ": is the input " + *in +
                           " (tmop never modifies its inputs: write to another file)");
  if (!FLAGS_report.empty()) {
    const Status place = check_output_path(FLAGS_report);
    if (!place.ok()) return fail(2, place.message());
  }
  if (!find_recipe(FLAGS_recipe))
    return fail(2, "unknown --recipe '" + FLAGS_recipe + "' (known: " + recipe_names() + ")");
  if (FLAGS_max_iterations < 0) return fail(2, "--max_iterations must be >= 0");
  if (!(FLAGS_max_seconds > 0)) return fail(2, "--max_seconds must be > 0");
  if (!(FLAGS_function_tolerance >= 0)) return fail(2, "--function_tolerance must be >= 0");
  if (!(FLAGS_layer_edge_ratio >= 0)) return fail(2, "--layer_edge_ratio must be >= 0");
  if (FLAGS_threads < 0) return fail(2, "--threads must be >= 0 (0: all cores)");
  if (FLAGS_part_size < -1) return fail(2, "--part_size must be >= 0 (0: one problem)");
  if (!(FLAGS_part_first_tolerance == -1 ||
        (FLAGS_part_first_tolerance >= 0 && FLAGS_part_first_tolerance < 1)))
    return fail(2, "--part_first_tolerance must be in [0, 1) (0: as --function_tolerance)");
  if (FLAGS_part_sweeps < 1) return fail(2, "--part_sweeps must be >= 1");
  if (FLAGS_partitions != "auto") {
    if (partitions_from_flag() < 1)
      return fail(2, "--partitions must be auto, 1 or a number of parts K >= 2, not '" +
                         FLAGS_partitions + "'");
    if (FLAGS_part_size >= 0)
      return fail(2, "--partitions=" + FLAGS_partitions + " and --part_size: give one of them");
  }
  if (FLAGS_part_rings < 0) return fail(2, "--part_rings must be >= 0");
  if (!(FLAGS_power >= 1 || FLAGS_power == 0)) return fail(2, "--power must be >= 1 (or 0)");
  if (!(FLAGS_feature_angle > 0 && FLAGS_feature_angle < 180))
    return fail(2, "--feature_angle must be in (0, 180) degrees");
  GuaranteeMode g;
  if (!guarantee_mode_from_name(FLAGS_guarantee, &g))
    return fail(2, "--guarantee must be all, worst or off, not '" + FLAGS_guarantee + "'");
  if (FLAGS_orientation != "auto" && FLAGS_orientation != "gmsh" && FLAGS_orientation != "opposite")
    return fail(2, "--orientation must be auto, gmsh or opposite, not '" + FLAGS_orientation + "'");
  if (FLAGS_msh_version != "4.1" && FLAGS_msh_version != "2.2")
    return fail(2, "--msh_version must be 2.2 or 4.1, not '" + FLAGS_msh_version + "'");
  if (FLAGS_boundary != "fixed" && FLAGS_boundary != "slide")
    return fail(2, "--boundary must be fixed or slide, not '" + FLAGS_boundary + "'");
  if (FLAGS_recipe == "preserve" && FLAGS_moved.empty())
    return fail(2, "--recipe=preserve needs --moved=FILE (the mesh with its boundary moved)");
  return 0;
}

// The targets of --target, --reference, --size_field and the composed factors: 0 or the exit
// code.
int target_from_flags(TargetSpec* t, bool* composed) {
  *composed = FLAGS_target == "composed";
  const std::string target = FLAGS_reference.empty() || *composed ? FLAGS_target : "reference";
  if (!target_type_from_name(target, &t->type))
    return fail(2, "unknown --target '" + target +
                       "' (known: ideal_unit, equal_size, local_size, size_field, reference, "
                       "lambda_identity, composed)");
  if (target == "size_field") t->size_field = FLAGS_size_field;
  if (target == "reference" && FLAGS_reference.empty())
    return fail(2,
                "--target=reference needs --reference=FILE (the mesh whose Jacobians are the "
                "targets)");
  if (target == "size_field" && FLAGS_size_field.empty())
    return fail(2, "--target=size_field needs --size_field=NAME (a point-data array of the input)");
  const char* factor_flags[] = {"target_size", "target_orientation", "target_shape", "target_skew",
                                "target_aspect"};
  for (const char* f : factor_flags)
    if (!*composed && !gflags::GetCommandLineFlagInfoOrDie(f).is_default)
      return fail(2, std::string("--") + f + " needs --target=composed");
  if (FLAGS_target_shape != "ideal" && FLAGS_target_shape != "initial")
    return fail(2, "--target_shape must be ideal or initial, not '" + FLAGS_target_shape +
                       "' (--target_skew and --target_aspect take the other sources)");
  ComposedTarget& c = t->composed;
  const struct {
    FactorKind kind;
    const char* flag;
    const std::string& text;
    TargetFactor* factor;
  } factors[] = {
      {FactorKind::kSize, "target_size", FLAGS_target_size, &c.size},
      {FactorKind::kOrientation, "target_orientation", FLAGS_target_orientation, &c.orientation},
      {FactorKind::kSkew, "target_skew",
       FLAGS_target_skew.empty() ? FLAGS_target_shape : FLAGS_target_skew, &c.skew},
      {FactorKind::kAspect, "target_aspect",
       FLAGS_target_aspect.empty() ? FLAGS_target_shape : FLAGS_target_aspect, &c.aspect},
  };
  for (const auto& f : factors) {
    const Status ps = parse_target_factor(f.kind, f.text, f.factor);
    if (!ps.ok()) return fail(2, std::string("--") + f.flag + ": " + ps.message());
  }
  return 0;
}

// The registry's options from the flags (all but the files: fixed nodes, reference, moved).
int options_from_flags(RecipeOptions* o, bool* composed) {
  if (const int rc = target_from_flags(&o->target, composed)) return rc;
  o->metric = FLAGS_metric;
  o->power = FLAGS_power;
  if (!sample_rule_from_name(FLAGS_sample_points, &o->rule))
    return fail(2, "unknown --sample_points '" + FLAGS_sample_points + "'");
  // Recipes surface and sliver slide by default (their definitions); the others keep the
  // boundary fixed unless told.
  const bool given = !gflags::GetCommandLineFlagInfoOrDie("boundary").is_default;
  o->boundary = FLAGS_boundary == "slide" ? BoundaryMode::kSlide
                : given                   ? BoundaryMode::kFixed
                                          : BoundaryMode::kDefault;
  o->geometry.geometry = FLAGS_geometry;
  o->geometry.feature_angle_deg = FLAGS_feature_angle;
  guarantee_mode_from_name(FLAGS_guarantee, &o->guarantee);
  SolverOptions& s = o->solver;
  if (!solver_method_from_name(FLAGS_solver, &s.method))
    return fail(2, "unknown --solver '" + FLAGS_solver + "' (lm, dogleg)");
  if (!linear_solver_from_name(FLAGS_linear_solver, &s.linear_solver))
    return fail(2, "unknown --linear_solver '" + FLAGS_linear_solver + "'");
  if (s.method == SolverOptions::Method::kDogleg &&
      s.linear_solver == SolverOptions::LinearSolver::kCgnr)
    return fail(2,
                "--solver=dogleg needs sparse Cholesky (Ceres's dogleg cannot use CGNR): use "
                "--linear_solver=auto or cholesky, or --solver=lm");
  s.max_iterations = FLAGS_max_iterations;
  s.max_seconds = FLAGS_max_seconds;
  s.function_tolerance = FLAGS_function_tolerance;
  s.threads = FLAGS_threads;
  if (FLAGS_part_size >= 0) s.part_size = FLAGS_part_size;
  if (FLAGS_partitions != "auto") s.partitions = partitions_from_flag();
  s.max_sweeps = FLAGS_part_sweeps;
  if (FLAGS_part_first_tolerance >= 0) s.first_sweep_tolerance = FLAGS_part_first_tolerance;
  s.sweep_rings = FLAGS_part_rings;
  s.verbose = FLAGS_verbose;
  if (FLAGS_recipe == "size_adapt") o->size_field = FLAGS_size_field;
  o->shape_guard_weight = FLAGS_shape_guard_weight;
  o->layer_edge_ratio = FLAGS_layer_edge_ratio;
  o->max_sweeps = FLAGS_max_sweeps;
  // Given files count as set options even before they are read.
  if (!FLAGS_fixed_nodes.empty()) o->fixed.assign(1, 0);
  // An option the recipe does not use is refused (not ignored).
  const std::vector<RecipeOption> unused = unused_options(FLAGS_recipe, *o);
  if (!unused.empty())
    return fail(2, std::string("--") + recipe_option_flag(unused[0]) + " is not used by recipe " +
                       FLAGS_recipe);
  if (!FLAGS_size_field.empty() && o->size_field.empty() && o->target.size_field.empty())
    return fail(
        2, "--size_field is not used by recipe " + FLAGS_recipe + " without --target=size_field");
  if (!FLAGS_moved.empty() && FLAGS_recipe != "preserve")
    return fail(2, "--moved is not used by recipe " + FLAGS_recipe);
  o->fixed.clear();
  return 0;
}

}  // namespace tmop_tools
