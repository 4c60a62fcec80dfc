// tmop_optimize: improve a mesh by moving its nodes (Target-Matrix Optimization Paradigm).
//
//   tmop_optimize --input=IN --output=OUT [--recipe=NAME] [--boundary=fixed|slide]
//                 [--geometry=SPEC] [--metric=NAME]
//                 [--target=NAME] [--reference=FILE] [--sample_points=RULE] [--power=P]
//                 [--target=composed --target_size=SRC --target_orientation=SRC
//                  --target_shape=ideal|initial --target_skew=SRC --target_aspect=SRC]
//                 [--solver=lm|dogleg] [--linear_solver=auto|cholesky|cgnr]
//                 [--max_iterations=N] [--threads=N] [--report=FILE.json] [--verbose]
//                 [--orientation=auto|gmsh|opposite]
//
// Exit status: 0 success; 1 the optimization could not reach its goal; 2 bad input or usage.
// Errors are one line on stderr. OUT is written atomically and only on success; IN is never
// opened for writing.
#include <gflags/gflags.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <glog/logging.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/orientation.h"
#include "tmop/mesh/validate.h"
#include "tmop/metric/metric.h"
#include "tmop/quality/guarantees.h"
#include "tmop/quality/quality_fields.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/equal_edge.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/laplace.h"
#include "tmop/recipes/preserve.h"
#include "tmop/recipes/size_adapt.h"
#include "tmop/recipes/sliver.h"
#include "tmop/recipes/untangle.h"
#include "tmop/target/target.h"
#include "tools/parse_flags.h"
#include "tools/print_error.h"

DEFINE_string(input, "",
              "Input mesh (.msh .vtk .vtu .mesh .ugrid .exo .e .cgns .obj .off .ply .stl).");
DEFINE_string(output, "", "Output mesh; format by extension. Written only on success.");
DEFINE_string(recipe, "auto",
              "auto: untangle if anything is inverted, then improve shape; "
              "shape: shape improvement with a barrier metric (the input must be valid); "
              "untangle: untangle only; surface: shape improvement of a surface mesh on its "
              "geometry (--geometry); equal_edge: equal edge lengths keeping shapes; "
              "size_adapt: shapes with the local (or --size_field) size; preserve: follow a "
              "moved boundary (--moved); laplace: smart Laplacian baseline; sliver: remove "
              "slivers, keep the boundary layer (slides by default); high_order: quadratic "
              "meshes, untangle + shape + Bernstein certificate (the same as auto).");
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
DEFINE_int32(part_sweeps, 4, "Partitioned stages: at most this many sweeps over the parts.");
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

namespace {

int fail(int code, const std::string& message) {
  tmop_tools::print_error(
      "tmop_optimize", message,
      {FLAGS_input, FLAGS_output, FLAGS_reference, FLAGS_moved, FLAGS_report, FLAGS_geometry});
  return code;
}

// True when both paths name one existing file (hard links and symlinks included).
bool same_file(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return !a.empty() && !b.empty() && ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 &&
         sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

// The mesh in hand is in tmop's convention (--orientation decided): measure it as it is.
tmop::QualityOptions as_decided() {
  tmop::QualityOptions o;
  o.detect_convention = false;
  return o;
}

// One line of the quality report (tmop_quality gives the whole report); returns the report.
// keep_per_cell: keep the per-cell arrays (to refresh the mesh's quality fields with them).

tmop::QualityReport print_quality(const char* label, const tmop::Mesh& mesh,
                                  bool keep_per_cell = false) {
  tmop::QualityReport q = tmop::compute_quality(mesh, as_decided());
  std::printf("%-7s %lld elements, %lld inverted", label, static_cast<long long>(q.num_elements),
              static_cast<long long>(q.inverted_cells));
  if (q.mean_ratio.count > 0)
    std::printf(", mean ratio min %.4f mean %.4f", q.mean_ratio.min, q.mean_ratio.mean);
  if (q.scaled_jacobian.count > 0)
    std::printf(", scaled Jacobian min %.4f mean %.4f", q.scaled_jacobian.min,
                q.scaled_jacobian.mean);
  if (q.tets > 0)
    std::printf(", dihedral %.2f..%.2f deg, %lld slivers", q.min_dihedral.min, q.max_dihedral.max,
                static_cast<long long>(q.slivers));
  if (q.certifiable_cells > 0)
    std::printf(", %lld of %lld certified", static_cast<long long>(q.certified_cells),
                static_cast<long long>(q.certifiable_cells));
  std::printf("\n");
  if (!keep_per_cell) q.release_per_cell_values();  // the run report needs the summaries only
  return q;
}

// The run report: the recipe's record plus tmop_quality's report of the input and the result
// (the same keys as tmop_quality --json and tmop_compare --json, docs/quality.md).
// written: whether --output was written (null otherwise); status: "ok" or the recipe's failure;
// after: the result as written (or, when nothing was written, as the recipe left it).
std::string run_report(const tmop::RecipeResult& result, const tmop::QualityReport& before,
                       const tmop::QualityReport& after, bool written, const std::string& status) {
  auto indent = [](std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    std::string out;
    for (char c : text) out += c == '\n' ? std::string("\n  ") : std::string(1, c);
    return out;
  };
  return "{\n  \"input\": " + tmop::json_string(FLAGS_input) +
         ",\n  \"output\": " + (written ? tmop::json_string(FLAGS_output) : "null") +
         ",\n  \"status\": " + tmop::json_string(status) +
         ",\n  \"run\": " + tmop::recipe_json(result) +
         ",\n  \"quality_before\": " + indent(tmop::quality_json(before)) +
         ",\n  \"quality_after\": " + indent(tmop::quality_json(after)) + "\n}";
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "improve a mesh by node movement\n"
      "  tmop_optimize --input=IN --output=OUT [--recipe=auto|shape|untangle|surface|sliver|"
      "equal_edge|size_adapt|preserve|laplace|high_order] [flags]");
#ifdef __GLIBC__
  // A fixed mmap threshold: glibc's adaptive one rises to the size of freed buffers (reading,
  // the quality report), after which multi-MB vectors land in the heap and leave it fragmented;
  // 1M tets: peak 1,029 -> 988 MB, the same time (docs/benchmarks.md).
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
#endif
  tmop_tools::parse_flags(&argc, &argv);
  // Ctrl-C or a SIGTERM mid-run: temporary files removed, one line on stderr, exit 130.
  tmop::remove_temporaries_on_signal("tmop_optimize");
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
    std::printf("weighted combinations of two: W1*NAME1+W2*NAME2 (weights >= 0, default 1)\n");
    return 0;
  }
  if (argc > 1)
    return fail(2, std::string("unexpected argument '") + argv[1] +
                       "' (every option is a --flag=value; see --help)");
  if (FLAGS_input.empty() || FLAGS_output.empty())
    return fail(2, "--input and --output are required (see --help)");
  // Inputs are never modified: an output or report that is one of them is refused.
  for (const std::string* in : {&FLAGS_input, &FLAGS_reference, &FLAGS_moved})
    for (const std::string* out : {&FLAGS_output, &FLAGS_report})
      if (same_file(*in, *out))
        return fail(2, *out + ": is the input " + *in +
                           " (tmop never modifies its inputs: write to another file)");
  if (!FLAGS_report.empty()) {
    const Status place = check_output_path(FLAGS_report);
    if (!place.ok()) return fail(2, place.message());
  }
  const std::string recipes[] = {"auto",       "shape",    "untangle", "surface", "equal_edge",
                                 "size_adapt", "preserve", "laplace",  "sliver",  "high_order"};
  if (std::find(std::begin(recipes), std::end(recipes), FLAGS_recipe) == std::end(recipes))
    return fail(2, "unknown --recipe '" + FLAGS_recipe +
                       "' (known: auto, shape, untangle, surface, equal_edge, size_adapt, "
                       "preserve, laplace, sliver, high_order)");
  if (FLAGS_max_iterations < 0) return fail(2, "--max_iterations must be >= 0");
  if (!(FLAGS_max_seconds > 0)) return fail(2, "--max_seconds must be > 0");
  if (!(FLAGS_function_tolerance >= 0)) return fail(2, "--function_tolerance must be >= 0");
  if (!(FLAGS_layer_edge_ratio >= 0)) return fail(2, "--layer_edge_ratio must be >= 0");
  if (FLAGS_threads < 0) return fail(2, "--threads must be >= 0 (0: all cores)");
  if (FLAGS_part_size < -1) return fail(2, "--part_size must be >= 0 (0: one problem)");
  if (FLAGS_part_sweeps < 1) return fail(2, "--part_sweeps must be >= 1");
  if (!(FLAGS_power >= 1 || FLAGS_power == 0)) return fail(2, "--power must be >= 1 (or 0)");
  if (!(FLAGS_feature_angle > 0 && FLAGS_feature_angle < 180))
    return fail(2, "--feature_angle must be in (0, 180) degrees");
  if (FLAGS_guarantee != "all" && FLAGS_guarantee != "worst" && FLAGS_guarantee != "off")
    return fail(2, "--guarantee must be all, worst or off, not '" + FLAGS_guarantee + "'");
  if (FLAGS_orientation != "auto" && FLAGS_orientation != "gmsh" && FLAGS_orientation != "opposite")
    return fail(2, "--orientation must be auto, gmsh or opposite, not '" + FLAGS_orientation + "'");
  if (FLAGS_msh_version != "4.1" && FLAGS_msh_version != "2.2")
    return fail(2, "--msh_version must be 2.2 or 4.1, not '" + FLAGS_msh_version + "'");
  if (FLAGS_boundary != "fixed" && FLAGS_boundary != "slide")
    return fail(2, "--boundary must be fixed or slide, not '" + FLAGS_boundary + "'");
  // Recipes surface and sliver slide by default (their definitions); the others keep the
  // boundary fixed unless told.
  const bool boundary_given = !gflags::GetCommandLineFlagInfoOrDie("boundary").is_default;
  const bool slide = FLAGS_boundary == "slide" || FLAGS_recipe == "surface" ||
                     (FLAGS_recipe == "sliver" && !boundary_given);
  if (FLAGS_recipe == "preserve" && FLAGS_moved.empty())
    return fail(2, "--recipe=preserve needs --moved=FILE (the mesh with its boundary moved)");

  ShapeOptions opt;
  opt.metric = FLAGS_metric;
  if (FLAGS_power > 0) opt.power = FLAGS_power;
  if (!sample_rule_from_name(FLAGS_sample_points, &opt.rule))
    return fail(2, "unknown --sample_points '" + FLAGS_sample_points + "'");
  const bool composed = FLAGS_target == "composed";
  std::string target = FLAGS_reference.empty() || composed ? FLAGS_target : "reference";
  if (!target_type_from_name(target, &opt.target.type))
    return fail(2, "unknown --target '" + target +
                       "' (known: ideal_unit, equal_size, local_size, size_field, reference, "
                       "lambda_identity, composed)");
  opt.target.size_field = FLAGS_size_field;
  if (target == "reference" && FLAGS_reference.empty())
    return fail(2,
                "--target=reference needs --reference=FILE (the mesh whose Jacobians are the "
                "targets)");
  if (target == "size_field" && FLAGS_size_field.empty())
    return fail(2, "--target=size_field needs --size_field=NAME (a point-data array of the input)");
  {
    const char* factor_flags[] = {"target_size", "target_orientation", "target_shape",
                                  "target_skew", "target_aspect"};
    for (const char* f : factor_flags)
      if (!composed && !gflags::GetCommandLineFlagInfoOrDie(f).is_default)
        return fail(2, std::string("--") + f + " needs --target=composed");
    if (FLAGS_target_shape != "ideal" && FLAGS_target_shape != "initial")
      return fail(2, "--target_shape must be ideal or initial, not '" + FLAGS_target_shape +
                         "' (--target_skew and --target_aspect take the other sources)");
    ComposedTarget& c = opt.target.composed;
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
  }
  if (!solver_method_from_name(FLAGS_solver, &opt.solver.method))
    return fail(2, "unknown --solver '" + FLAGS_solver + "' (lm, dogleg)");
  if (!linear_solver_from_name(FLAGS_linear_solver, &opt.solver.linear_solver))
    return fail(2, "unknown --linear_solver '" + FLAGS_linear_solver + "'");
  if (opt.solver.method == SolverOptions::Method::kDogleg &&
      opt.solver.linear_solver == SolverOptions::LinearSolver::kCgnr)
    return fail(2,
                "--solver=dogleg needs sparse Cholesky (Ceres's dogleg cannot use CGNR): use "
                "--linear_solver=auto or cholesky, or --solver=lm");
  opt.solver.max_iterations = FLAGS_max_iterations;
  opt.solver.max_seconds = FLAGS_max_seconds;
  opt.solver.function_tolerance = FLAGS_function_tolerance;
  opt.solver.threads = FLAGS_threads;
  if (FLAGS_part_size >= 0) opt.solver.part_size = FLAGS_part_size;
  opt.solver.max_sweeps = FLAGS_part_sweeps;
  opt.solver.verbose = FLAGS_verbose;
  opt.slide = slide;
  opt.boundary.geometry = FLAGS_geometry;
  opt.boundary.feature_angle_deg = FLAGS_feature_angle;
  // The guarantees each recipe keeps (its guard) and the tool checks on its result.
  const bool trades_shape =
      FLAGS_recipe == "size_adapt" || FLAGS_recipe == "preserve" || FLAGS_recipe == "laplace";
  const bool keeps_means = FLAGS_guarantee == "all" && FLAGS_recipe != "sliver" &&
                           FLAGS_recipe != "equal_edge" && !trades_shape;
  const bool check_guarantee = FLAGS_guarantee != "off" && !trades_shape;
  opt.guard_worst = FLAGS_guarantee != "off";
  opt.guard_means = keeps_means;

  Mesh mesh;
  Status s = read_mesh(FLAGS_input, &mesh);
  if (!s.ok()) return fail(2, s.message());
  s = validate_mesh(mesh);
  if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  // The output's format must hold this mesh: refuse now rather than after the optimization.
  // Node movement changes neither cell types nor connectivity, which is all the check needs.
  WriteOptions wopt;
  wopt.binary = FLAGS_binary;
  wopt.msh_version = FLAGS_msh_version == "2.2" ? 22 : 41;
  s = check_writable(FLAGS_output, mesh, wopt);
  if (!s.ok()) return fail(2, s.message());
  // The recipe must fit the mesh and a --geometry must be well formed, near the mesh and used:
  // usage errors, said before any work (recipe_geometry.h: check_geometry_spec).
  if (FLAGS_recipe == "sliver" && !(mesh.dim() == 3 && mesh.space_dim == 3))
    return fail(2, FLAGS_input + ": recipe sliver needs a volume mesh (tets), not a " +
                       std::to_string(mesh.dim()) + "D mesh");
  if (FLAGS_recipe == "surface" && !is_surface_mesh(mesh))
    return fail(2, FLAGS_input + ": recipe surface needs a surface mesh (2D cells in 3D)");
  if (!FLAGS_geometry.empty()) {
    if (FLAGS_recipe == "preserve") return fail(2, "--geometry is not used by recipe preserve");
    BoundaryOptions b = opt.boundary;
    b.slide = slide;
    s = check_geometry_spec(mesh, b);
    if (!s.ok())
      return fail(
          2, s.message() + (!slide && !is_surface_mesh(mesh) ? " (add --boundary=slide)" : ""));
  }
  if (!FLAGS_metric.empty() && !make_metric(FLAGS_metric, mesh.dim())) {
    std::string known;
    for (const std::string& n : metric_names(mesh.dim())) known += (known.empty() ? "" : ", ") + n;
    return fail(2, "unknown --metric '" + FLAGS_metric + "' for " + std::to_string(mesh.dim()) +
                       "D meshes (known: " + known + "; or W1*NAME1+W2*NAME2 with weights >= 0)");
  }
  Mesh reference;
  if (!FLAGS_reference.empty()) {
    s = read_mesh(FLAGS_reference, &reference);
    if (!s.ok()) return fail(2, s.message());
    // Checked before any work: a reference of another mesh is a usage error (exit 2).
    if (!reference_matches(mesh, reference))
      return fail(2, FLAGS_reference + ": its vertices and cells do not match those of " +
                         FLAGS_input + " (a reference mesh must have the same topology)");
    opt.target.reference = &reference;
  }

  // A mesh written with the opposite orientation convention is not "all inverted": optimize it
  // in tmop's convention and write it back in its own. The boundary decides (orientation.h), so
  // a tangle of more than half the cells is still a tangle; --orientation states it instead.
  const OrientationReport orientation = check_orientation(mesh);
  const bool flipped = FLAGS_orientation == "auto" ? orientation.opposite_convention()
                                                   : FLAGS_orientation == "opposite";
  if (FLAGS_orientation == "auto" &&
      (flipped || 2 * orientation.negative > orientation.num_elements()))
    std::printf("note: %s: %s%s\n", FLAGS_input.c_str(), describe_orientation(orientation).c_str(),
                flipped ? ": handled" : ": the negative cells are inverted");
  else if (flipped)
    std::printf("note: %s: opposite convention (--orientation=opposite; %d of %d cells negative)\n",
                FLAGS_input.c_str(), orientation.negative, orientation.num_elements());
  if (flipped) {
    reorient(&mesh);
    if (opt.target.reference) reorient(&reference);
  }
  // Value counts, fields and the reference's topology are usage errors: say so before running.
  if (composed) {
    s = check_composed_target(mesh, opt.target);
    if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  }

  Mesh moved;
  if (!FLAGS_moved.empty()) {
    s = read_mesh(FLAGS_moved, &moved);
    if (!s.ok()) return fail(2, s.message());
    if (flipped) reorient(&moved);
  }
  if (slide && FLAGS_recipe != "auto" && FLAGS_recipe != "shape" && FLAGS_recipe != "untangle" &&
      FLAGS_recipe != "surface" && FLAGS_recipe != "sliver" && FLAGS_recipe != "equal_edge" &&
      FLAGS_recipe != "size_adapt" && FLAGS_recipe != "high_order" && FLAGS_recipe != "laplace")
    return fail(2, "--boundary=slide is not available for recipe " + FLAGS_recipe);

  RecipeResult result;
  const IterationRecord before = measure_mesh(mesh, opt.rule);
  GuaranteeBaseline baseline;
  if (check_guarantee) baseline = guarantee_baseline(mesh, FLAGS_threads);
  // --write_on_failure writes the better of the input and the recipe's result (fewer inverted
  // cells; the input on a tie).
  Mesh input_copy;
  if (FLAGS_write_on_failure) input_copy = mesh;
  const std::vector<double> input_coords = mesh.coords;
  QualityReport quality_before = print_quality("before:", mesh);
  quality_before.opposite_convention = flipped;  // as tmop_quality reports the input
  if ((FLAGS_recipe == "shape" || FLAGS_recipe == "equal_edge" || FLAGS_recipe == "size_adapt" ||
       FLAGS_recipe == "laplace") &&
      before.inverted > 0)
    return fail(1, FLAGS_input + ": " + std::to_string(before.inverted) +
                       " inverted elements: recipe " + FLAGS_recipe +
                       " needs a valid mesh (use --recipe=auto or untangle)");
  if (FLAGS_recipe == "shape") {
    s = improve_shape(&mesh, opt, &result);
  } else if (FLAGS_recipe == "equal_edge") {
    EqualEdgeOptions e;
    if (!FLAGS_metric.empty()) e.metric = FLAGS_metric;
    e.shape_guard_weight = FLAGS_shape_guard_weight;
    if (FLAGS_sample_points != "default") e.rule = opt.rule;
    e.solver = opt.solver;
    e.guard_worst = opt.guard_worst;
    e.slide = slide;
    e.boundary = opt.boundary;
    s = equal_edge(&mesh, e, &result);
  } else if (FLAGS_recipe == "size_adapt") {
    SizeAdaptOptions a;
    a.size_field = FLAGS_size_field;
    if (!FLAGS_metric.empty()) a.metric = FLAGS_metric;
    if (FLAGS_power > 0) a.power = FLAGS_power;
    a.rule = opt.rule;
    a.solver = opt.solver;
    a.slide = slide;
    a.boundary = opt.boundary;
    s = size_adapt(&mesh, a, &result);
  } else if (FLAGS_recipe == "preserve") {
    PreserveOptions p;
    p.moved = &moved;
    if (!FLAGS_metric.empty()) p.metric = FLAGS_metric;
    p.rule = opt.rule;
    p.solver = opt.solver;
    s = preserve(&mesh, p, &result);
  } else if (FLAGS_recipe == "sliver") {
    SliverOptions sl;
    sl.slide = slide;
    sl.boundary = opt.boundary;
    sl.rule = opt.rule;
    sl.solver = opt.solver;
    sl.guard_worst = opt.guard_worst;
    sl.layer_edge_ratio = FLAGS_layer_edge_ratio;
    s = remove_slivers(&mesh, sl, &result);
  } else if (FLAGS_recipe == "laplace") {
    LaplaceOptions l;
    l.max_sweeps = FLAGS_max_sweeps;
    l.slide = slide;
    l.boundary = opt.boundary;
    s = laplace(&mesh, l, &result);
  } else if (FLAGS_recipe == "surface") {
    UntangleOptions u;
    u.rule = opt.rule;
    u.solver = opt.solver;
    u.slide = true;
    u.boundary = opt.boundary;
    u.shape = opt;
    s = untangle(&mesh, u, &result);
    result.recipe = "surface";
  } else {
    UntangleOptions u;
    u.target = opt.target;  // untangle toward the reference when one is given
    if (opt.target.type != TargetType::kReference) u.target.type = TargetType::kIdealEqualSize;
    u.rule = opt.rule;
    u.solver = opt.solver;
    u.improve_shape_after = FLAGS_recipe == "auto" || FLAGS_recipe == "high_order";
    u.slide = opt.slide;
    u.boundary = opt.boundary;
    u.shape = opt;
    s = untangle(&mesh, u, &result);
  }
  for (const StageResult& st : result.stages) {
    // Under a power the solver minimises the power objective, which can fall while the mean
    // metric (the objective printed first) rises: print both.
    char power[96] = "";
    if (st.power_scale > 0 && st.history.size() > 1)
      std::snprintf(power, sizeof power, " (minimised power objective %.6g -> %.6g)",
                    st.history.front().solver_objective, st.history.back().solver_objective);
    std::printf("stage %s: objective %.6g -> %.6g%s in %d iterations (%d solves), %.2f s (%s)\n",
                st.name.c_str(), st.initial_objective, st.final_objective, power, st.iterations,
                st.solves, st.seconds, st.termination.c_str());
  }
  // The guarantees, checked on the result independently of the recipe's own guard.
  bool guarantee_broken = false;
  if (s.ok() && check_guarantee) {
    GuaranteeOptions g;
    g.means = keeps_means;
    // A tangled input is untangled: only new inversions count (docs/quality.md).
    g.tangled_inversions_only = true;
    const std::vector<GuaranteeViolation> broken =
        check_guarantees(baseline, guarantee_values(mesh, FLAGS_threads), g);
    if (!broken.empty()) {
      guarantee_broken = true;
      s = Status::Failure(
          "the result breaks a guarantee: " + broken[0].message() +
          (broken.size() > 1 ? " (and " + std::to_string(broken.size() - 1) + " more)" : "") +
          "; --guarantee=worst or off accepts such a trade");
    }
  }
  const Status recipe_status = s;
  std::string written_note;
  if (guarantee_broken) {
    written_note = FLAGS_write_on_failure ? "result written" : "nothing written";
  } else if (!recipe_status.ok()) {
    // Inverted counts as the quality report counts them (quadratic cells by their certificate).
    const std::int64_t now = compute_quality(mesh, as_decided()).inverted_cells;
    const std::int64_t was = quality_before.inverted_cells;
    if (!FLAGS_write_on_failure) {
      written_note = "nothing written: the result has " + std::to_string(now) +
                     " inverted cells, the input " + std::to_string(was);
    } else if (now >= was && mesh.coords != input_copy.coords) {
      mesh = input_copy;
      written_note = "input written unchanged: the result had " + std::to_string(now) +
                     " inverted cells, the input " + std::to_string(was);
    } else {
      written_note = mesh.coords == input_copy.coords
                         ? "input written unchanged"
                         : "best mesh written: " + std::to_string(now) +
                               " inverted cells, the input had " + std::to_string(was);
    }
    result.after = measure_mesh(mesh, opt.rule);  // the mesh written (or left), not the recipe's
  }
  const bool write = recipe_status.ok() || FLAGS_write_on_failure;
  const std::string status =
      recipe_status.ok() ? std::string("ok") : recipe_status.message() + " (" + written_note + ")";
  QualityReport quality_after = print_quality("after:", mesh, !mesh.cell_data.empty());
  quality_after.opposite_convention = flipped;  // written back in the input's convention
  if (recipe_status.ok() && result.guard_held_cells > 0)
    std::printf(mesh.coords == input_coords
                    ? "guard: no move kept every guarantee (%d cells would have got worse): the "
                      "mesh is unchanged; --guarantee=worst or off accepts a trade\n"
                    : "guard: %d cells held at their input shape to keep the guarantees\n",
                result.guard_held_cells);
  if (result.layer_cells >= 0)
    std::printf(result.recipe == "sliver"
                    ? "boundary layer: %d cells, %d vertices held on its outer surface\n"
                    : "boundary layer: %d cells kept, %d vertices held\n",
                result.layer_cells, result.held_vertices);
  if (result.certified >= 0)
    std::printf("certified valid everywhere (Bernstein bound): %d of %d quadratic cells\n",
                result.certified, result.certified + result.uncertified);

  // Per-cell quality arrays of the input (a tmop_quality --output file) describe the old nodes.
  if (refresh_quality_fields(quality_after, &mesh))
    std::printf("quality fields of the input replaced by the result's\n");
  if (flipped) reorient(&mesh);
  if (write) {
    s = write_mesh(FLAGS_output, mesh, wopt);
    if (!s.ok()) return fail(2, s.message());
    std::printf("wrote %s\n", FLAGS_output.c_str());
  }
  // The report is written on failure too: that is when it is needed.
  if (!FLAGS_report.empty()) {
    s = write_file_atomically(
        FLAGS_report, run_report(result, quality_before, quality_after, write, status) + "\n");
    if (!s.ok()) return fail(2, s.message());
  }
  if (!recipe_status.ok()) {
    // A convention stated against the boundary's evidence is the likelier culprit.
    std::string hint;
    if (orientation.evidence() == OrientationReport::Evidence::kBoundary &&
        flipped != orientation.opposite_convention())
      hint = "; the boundary says " +
             std::string(orientation.opposite_convention() ? "the opposite" : "Gmsh's") +
             " convention: try --orientation=auto";
    return fail(1, FLAGS_input + ": " + recipe_status.message() + " (" + written_note + ")" + hint);
  }
  return 0;
}
