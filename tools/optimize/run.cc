// tools/optimize/run.cc: a tmop_optimize run on its inputs (run.h).
#include "tools/optimize/run.h"

#include <csignal>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "tmop/io/atomic_file.h"
#include "tmop/quality/guarantees.h"
#include "tmop/quality/quality_fields.h"
#include "tmop/quality/quality_report.h"
#include "tools/optimize/flags.h"
#include "tools/optimize/run_report.h"

namespace tmop_tools {

using namespace tmop;

namespace {

// The mesh in hand is in tmop's convention (--orientation decided): measure it as it is.
QualityOptions as_decided() {
  QualityOptions o;
  o.detect_convention = false;
  return o;
}

// One line of the quality report (tmop_quality gives the whole report); returns the report.
// keep_per_cell: keep the per-cell arrays (to refresh the mesh's quality fields with them).
QualityReport print_quality(const char* label, const Mesh& mesh, bool keep_per_cell = false) {
  QualityReport q = compute_quality(mesh, as_decided());
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

void print_stages(const RecipeResult& result) {
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
}

void print_notes(const RecipeResult& result, bool ok, bool unchanged) {
  if (ok && result.guard_held_cells > 0)
    std::printf(unchanged ? "guard: no move kept every guarantee (%d cells would have got worse): "
                            "the mesh is unchanged; --guarantee=worst or off accepts a trade\n"
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
}

// The last iteration reported (the cancel message names it). Progress may come from the
// workers of a partitioned stage: a mutex, never taken by the signal handler.
std::mutex g_last_mutex;
std::string g_last_stage;
int g_last_iteration = -1;

int interrupted() {
  const int sig = tmop::cancel_signal();
  std::string where = "before the first iteration";
  {
    std::lock_guard<std::mutex> lock(g_last_mutex);
    if (g_last_iteration >= 0)
      where = "after " + g_last_stage + " iteration " + std::to_string(g_last_iteration);
  }
  std::fprintf(stderr, "tmop_optimize: interrupted by %s %s; nothing written\n",
               sig == SIGTERM ? "SIGTERM" : "SIGINT", where.c_str());
  return 130;
}

}  // namespace

ProgressCallback remembering_last_iteration(ProgressCallback user) {
  return [user](const ProgressRecord& r) {
    {
      std::lock_guard<std::mutex> lock(g_last_mutex);
      g_last_stage = r.stage;
      g_last_iteration = r.iteration;
    }
    return !user || user(r);
  };
}

int run(const RecipeOptions& o, Inputs* in) {
  Mesh& mesh = in->mesh;
  GuaranteeOptions guarantees;
  const bool check_guarantee = recipe_guarantees(FLAGS_recipe, o, &guarantees);
  const int threads = FLAGS_threads;
  GuaranteeBaseline baseline;
  // A signal during reading or the measures before the recipe: nothing more starts.
  const auto signalled = [&o] { return o.cancel && o.cancel->load(); };
  if (signalled()) return interrupted();
  if (check_guarantee) baseline = guarantee_baseline(mesh, threads);
  if (signalled()) return interrupted();
  // --write_on_failure writes the better of the input and the recipe's result (fewer inverted
  // cells; the input on a tie).
  Mesh input_copy;
  if (FLAGS_write_on_failure) input_copy = mesh;
  const std::vector<double> input_coords = mesh.coords;
  QualityReport quality_before = print_quality("before:", mesh);
  if (signalled()) return interrupted();
  quality_before.opposite_convention = in->flipped;  // as tmop_quality reports the input
  int inverted = 0;
  Status s = check_valid_input(FLAGS_recipe, mesh, o.rule, &inverted);
  if (!s.ok()) return fail(1, FLAGS_input + ": " + s.message());
  if (signalled()) return interrupted();
  RecipeResult result;
  RecipeOptions with_baseline = o;  // the guard reuses the tool's baseline of the input
  if (check_guarantee) with_baseline.input_baseline = &baseline;
  s = run_recipe(FLAGS_recipe, &mesh, with_baseline, &result);
  // A cancelled run (SIGINT / SIGTERM raised the cancel flag) writes nothing: one line, exit 130.
  // From here on a signal takes the immediate path: a temporary file being written is removed.
  if (tmop::stop_cancelling_on_signal() || s.cancelled()) return interrupted();
  print_stages(result);
  // The guarantees, checked on the result independently of the recipe's own guard.
  bool guarantee_broken = false;
  if (s.ok() && check_guarantee) {
    const std::vector<GuaranteeViolation> broken =
        check_guarantees(baseline, guarantee_values(mesh, threads), guarantees);
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
    result.after = measure_mesh(mesh, o.rule);  // the mesh written (or left), not the recipe's
  }
  const bool write = recipe_status.ok() || FLAGS_write_on_failure;
  QualityReport quality_after = print_quality("after:", mesh, !mesh.cell_data.empty());
  quality_after.opposite_convention = in->flipped;  // written back in the input's convention
  print_notes(result, recipe_status.ok(), mesh.coords == input_coords);
  // Per-cell quality arrays of the input (a tmop_quality --output file) describe the old nodes.
  if (refresh_quality_fields(quality_after, &mesh))
    std::printf("quality fields of the input replaced by the result's\n");
  if (in->flipped) reorient(&mesh);
  const bool pvtu =
      FLAGS_output.size() > 5 && FLAGS_output.compare(FLAGS_output.size() - 5, 5, ".pvtu") == 0;
  if (write && pvtu && in->pieces > 1) {
    // A distributed run: each process writes its piece, the writing one also the index.
    s = write_pvtu_piece(FLAGS_output, mesh, in->write, in->piece, in->pieces);
    if (s.ok() && in->writes) s = write_pvtu_index(FLAGS_output, mesh, in->write, in->pieces);
    if (!s.ok()) return fail(2, s.message());
    if (in->writes) std::printf("wrote %s (%d pieces)\n", FLAGS_output.c_str(), in->pieces);
  } else if (write && in->writes) {
    s = write_mesh(FLAGS_output, mesh, in->write);
    if (!s.ok()) return fail(2, s.message());
    std::printf("wrote %s\n", FLAGS_output.c_str());
  }
  // The report is written on failure too: that is when it is needed.
  if (!FLAGS_report.empty() && in->writes) {
    tmop_tools::ReportInputs r;
    r.input = FLAGS_input;
    r.output = FLAGS_output;
    r.written = write;
    r.status = recipe_status.ok() ? std::string("ok")
                                  : recipe_status.message() + " (" + written_note + ")";
    r.settings_json = recipe_settings_json(FLAGS_recipe, mesh, o);
    s = write_file_atomically(
        FLAGS_report, tmop_tools::run_report(r, result, quality_before, quality_after) + "\n");
    if (!s.ok()) return fail(2, s.message());
  }
  if (!recipe_status.ok()) {
    // A convention stated against the boundary's evidence is the likelier culprit.
    std::string hint;
    const OrientationReport& orientation = in->orientation;
    if (orientation.evidence() == OrientationReport::Evidence::kBoundary &&
        in->flipped != orientation.opposite_convention())
      hint = "; the boundary says " +
             std::string(orientation.opposite_convention() ? "the opposite" : "Gmsh's") +
             " convention: try --orientation=auto";
    return fail(1, FLAGS_input + ": " + recipe_status.message() + " (" + written_note + ")" + hint);
  }
  return 0;
}

}  // namespace tmop_tools
