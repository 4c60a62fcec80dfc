// tools/tmop_quality.cc
// tmop_quality --input=IN [--json] [--output=OUT.vtu] [--svg=FILE]: the quality report of a mesh
// (docs/quality.md). Prints the human summary on stdout, or the JSON report with --json; writes
// the per-cell measures as cell fields with --output and a picture with --svg.
// Exit codes: 0 success; 2 usage error or unreadable input (one line on stderr); 1 an output file
// could not be written.
#include <gflags/gflags.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/quality/quality_fields.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/quality_report.h"
#include "tmop/quality/quality_summary.h"
#include "tmop/quality/quality_svg.h"
#include "tools/parse_flags.h"
#include "tools/print_error.h"

DEFINE_string(input, "",
              "Mesh to measure (required). Format by extension: .msh (Gmsh 2.2/4.1), .vtk, .vtu, "
              ".mesh (Medit), .obj/.off/.ply/.stl (surfaces).");
DEFINE_bool(json, false,
            "Print the JSON report (stable keys, numbers with 17 significant digits, "
            "docs/quality.md) on stdout instead of the readable summary.");
DEFINE_string(output, "",
              "Also write the mesh with the per-cell measures as cell fields (inverted, certified, "
              "mean_ratio, scaled_jacobian, condition_number, ...). Use .vtu (or .vtk) to keep "
              "the fields. Written atomically.");
DEFINE_bool(binary, false, "Write --output in binary where the format has a binary form.");
DEFINE_string(msh_version, "4.1", "Gmsh version of a .msh --output: 4.1 or 2.2.");
DEFINE_string(svg, "",
              "Also write an SVG picture: 2D meshes coloured by quality with a colour bar; 3D "
              "meshes as histograms and a max-vs-min dihedral angle scatter plot.");
DEFINE_string(sample_rule, "default",
              "Where the Jacobian of quadratic cells is evaluated (corners always added): "
              "default, corners, nodes, centroid, gauss.");
DEFINE_bool(bezier, true,
            "Certify tri6/tet10 cells with the Bernstein bound of det J; an unproven cell counts "
            "as inverted. --nobezier reports sample-point inversion only.");
DEFINE_int32(bezier_subdivision, 3,
             "Subdivision levels of the tri6/tet10 certificate where the plain Bernstein bound is "
             "inconclusive (0 = plain bound only; at most 8).");
DEFINE_bool(certify_all_types, false,
            "Also compute the Bernstein certificate of quad9/hex8/wedge6 cells (the 'certified' "
            "field; it does not change 'inverted'). About 5x slower on hex meshes.");
DEFINE_int32(threads, 0, "Worker threads; 0 = all cores. Results do not depend on it.");

namespace {

constexpr int kUsageError = 2;
constexpr int kOutputError = 1;

int fail(int code, const std::string& message) {
  tmop_tools::print_error("tmop_quality", message, {FLAGS_input, FLAGS_output, FLAGS_svg});
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "tmop_quality --input=IN [--json] [--output=OUT.vtu] [--svg=FILE]\n"
      "Measures every element of a mesh (inversion, mean ratio, scaled Jacobian, condition "
      "number, angles, dihedral angles, edge lengths; docs/quality.md) and prints a summary or "
      "the JSON report.\nExit codes: 0 success; 2 usage error or unreadable input; 1 an output "
      "file could not be written.");
  tmop_tools::parse_flags(&argc, &argv);
  tmop::remove_temporaries_on_signal("tmop_quality");
  if (argc > 1)
    return fail(kUsageError,
                std::string("unexpected argument '") + argv[1] + "' (flags only; see --help)");
  if (FLAGS_input.empty()) return fail(kUsageError, "--input is required (see --help)");
  if (FLAGS_msh_version != "4.1" && FLAGS_msh_version != "2.2")
    return fail(kUsageError, "--msh_version must be 2.2 or 4.1, not '" + FLAGS_msh_version + "'");
  tmop::QualityOptions options;
  if (!tmop::sample_rule_from_name(FLAGS_sample_rule, &options.sample_rule))
    return fail(kUsageError, "unknown --sample_rule '" + FLAGS_sample_rule + "'");
  options.bezier_certificate = FLAGS_bezier;
  options.bezier_subdivision = FLAGS_bezier_subdivision;
  options.certify_all_types = FLAGS_certify_all_types;
  options.threads = FLAGS_threads;

  tmop::Mesh mesh;
  const tmop::Status status = tmop::read_mesh(FLAGS_input, &mesh);
  if (!status.ok()) return fail(kUsageError, status.message());
  const tmop::QualityReport report = tmop::compute_quality(mesh, options);
  const std::string text = FLAGS_json ? tmop::quality_json(report) : tmop::quality_summary(report);
  std::fwrite(text.data(), 1, text.size(), stdout);

  if (!FLAGS_svg.empty()) {
    const tmop::Status written =
        tmop::write_file_atomically(FLAGS_svg, tmop::quality_svg(mesh, report));
    if (!written.ok()) return fail(kOutputError, written.message());
  }
  if (!FLAGS_output.empty()) {
    tmop::add_quality_fields(report, &mesh);
    tmop::WriteOptions wopt;
    wopt.binary = FLAGS_binary;
    wopt.msh_version = FLAGS_msh_version == "2.2" ? 22 : 41;
    const tmop::Status written = tmop::write_mesh(FLAGS_output, mesh, wopt);
    if (!written.ok()) return fail(kOutputError, written.message());
  }
  return 0;
}
