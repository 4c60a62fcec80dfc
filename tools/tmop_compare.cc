// tools/tmop_compare.cc
// tmop_compare --a=A --b=B [--reference=ORIG] [--json]   (or: tmop_compare A B [...])
//
// Compares two meshes of the same topology (same vertices and cells, e.g. tmop's output and
// another smoother's output for the same input): every quality measure of tmop/quality side by
// side with which mesh is better on it, and the vertex displacements between them (absolute and
// relative to the local edge length). With --reference (typically the common input), its
// quality is shown too and the displacements of A and B from it are added.
//
// "Better" on a measure compares the worst value (the minimum for measures where higher is
// better: mean ratio, scaled Jacobian, min angles; the maximum for condition number, max angles,
// edge ratio) and, separately, the mean. Size measures (min det, edge lengths) get no verdict.
//
// JSON (--json; stable keys, numbers %.17g, null for non-finite values):
//   {"format": "tmop.compare/1",
//    "a": {"file", "quality": <tmop_quality --json report, docs/quality.md>},
//    "b": {...}, ["reference": {...},]
//    "better": {"inverted_cells": "a"|"b"|"equal", "slivers": ... (null without tets),
//               "<measure key>": {"worst": "a"|"b"|"equal", "mean": ...} or null},
//    "displacement": {"b_minus_a": D, ["a_minus_reference": D, "b_minus_reference": D]}}
//   D = {"vertices", "moved", "max", "mean", "rms", "max_relative", "mean_relative",
//        "rms_relative"}: |x_2 - x_1| over all vertices, in length units and divided by the mean
//        length of the vertex's edges in the first mesh of the pair; "moved" counts vertices
//        that moved by more than 1e-12 of their local edge length.
// Exit codes: 0 success; 2 usage error, unreadable input or different topologies (one line on
// stderr).
#include <gflags/gflags.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/quality_report.h"
#include "tmop/quality/quality_svg.h"
#include "tools/parse_flags.h"
#include "tools/print_error.h"

DEFINE_string(a, "", "First mesh (or the first positional argument).");
DEFINE_string(b, "", "Second mesh, same vertices and cells as A (or the second positional one).");
DEFINE_string(reference, "",
              "Optional third mesh of the same topology, e.g. the common input: its quality is "
              "shown and displacements of A and B from it are added.");
DEFINE_bool(json, false,
            "Print JSON (stable keys, documented in the file header) instead of text.");
DEFINE_string(svg, "",
              "Also write an SVG overlaying A's and B's histograms and (tets) max-vs-min "
              "dihedral scatter plots, A as 'before' and B as 'after'.");
DEFINE_int32(threads, 0, "Threads for the quality measures; 0 = all cores.");

namespace {

constexpr int kUsageError = 2;

int fail(const std::string& message) {
  tmop_tools::print_error("tmop_compare", message, {FLAGS_a, FLAGS_b, FLAGS_reference, FLAGS_svg});
  return kUsageError;
}

bool same_topology(const tmop::Mesh& x, const tmop::Mesh& y) {
  return x.num_vertices() == y.num_vertices() && x.cell_types == y.cell_types &&
         x.cell_offsets == y.cell_offsets && x.cell_nodes == y.cell_nodes;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Which mesh wins on a value: lower_is_better flips the comparison; ties within 1e-12 relative.
const char* better(double a, double b, bool lower_is_better) {
  if (std::isnan(a) || std::isnan(b)) return nullptr;
  if (std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b))) return "equal";
  return (a < b) == lower_is_better ? "a" : "b";
}

enum class Direction { kHigher, kLower, kNone };
// Higher is better for quality ratios and minimum angles, lower for condition number, maximum
// angles and edge ratio; sizes (min det, edge lengths) have no "better".
Direction direction(const std::string& key) {
  if (key == "mean_ratio" || key == "scaled_jacobian" || key == "min_angle_deg" ||
      key == "min_dihedral_deg")
    return Direction::kHigher;
  if (key == "condition_number" || key == "max_angle_deg" || key == "max_dihedral_deg" ||
      key == "edge_ratio")
    return Direction::kLower;
  return Direction::kNone;
}

struct Displacement {
  int vertices = 0, moved = 0;
  double max = 0, mean = 0, rms = 0, max_rel = 0, mean_rel = 0, rms_rel = 0;
};

// |t|, also for meshes at 1e-310 or 1e300 (std::hypot scales, where squares would under- or
// overflow).
double norm3(const double* t) { return std::hypot(t[0], t[1], t[2]); }

// |to - from| per vertex; relative to the mean length of the vertex's edges in `from`.
Displacement displacement(const tmop::Mesh& from, const tmop::Mesh& to) {
  const int nv = from.num_vertices();
  std::vector<double> edge_sum(nv, 0);
  std::vector<int> edge_count(nv, 0);
  for (const auto& e : tmop::mesh_edges(from)) {
    double t[3] = {0, 0, 0};
    for (int k = 0; k < from.space_dim; ++k) t[k] = from.vertex(e[1])[k] - from.vertex(e[0])[k];
    const double l = norm3(t);
    for (int v : e) edge_sum[v] += l, ++edge_count[v];
  }
  Displacement d;
  d.vertices = nv;
  int rel_count = 0;
  for (int v = 0; v < nv; ++v) {
    double t[3];
    for (int k = 0; k < 3; ++k) {
      const double p = k < from.space_dim ? from.vertex(v)[k] : 0;
      const double q = k < to.space_dim ? to.vertex(v)[k] : 0;
      t[k] = q - p;
    }
    const double u = norm3(t);
    d.max = std::max(d.max, u);
    d.mean += u;
    d.rms += u * u;
    if (edge_count[v] > 0) {
      const double rel = u / (edge_sum[v] / edge_count[v]);
      d.max_rel = std::max(d.max_rel, rel);
      d.mean_rel += rel;
      d.rms_rel += rel * rel;
      ++rel_count;
      d.moved += rel > 1e-12;
    }
  }
  if (nv > 0) d.mean /= nv, d.rms = std::sqrt(d.rms / nv);
  if (rel_count > 0) d.mean_rel /= rel_count, d.rms_rel = std::sqrt(d.rms_rel / rel_count);
  return d;
}

std::string displacement_json(const Displacement& d, const std::string& indent) {
  return "{\n" + indent + "  \"vertices\": " + std::to_string(d.vertices) + ",\n" + indent +
         "  \"moved\": " + std::to_string(d.moved) + ",\n" + indent +
         "  \"max\": " + number(d.max) + ",\n" + indent + "  \"mean\": " + number(d.mean) + ",\n" +
         indent + "  \"rms\": " + number(d.rms) + ",\n" + indent +
         "  \"max_relative\": " + number(d.max_rel) + ",\n" + indent +
         "  \"mean_relative\": " + number(d.mean_rel) + ",\n" + indent +
         "  \"rms_relative\": " + number(d.rms_rel) + "\n" + indent + "}";
}

// quality_json's pretty text indented to sit as a nested value.
std::string nested(const std::string& json, const std::string& indent) {
  std::string out;
  for (std::size_t i = 0; i < json.size(); ++i) {
    if (json[i] == '\n') {
      if (i + 1 == json.size()) break;
      out += "\n" + indent;
    } else {
      out += json[i];
    }
  }
  return out;
}

std::string quote(const char* s) { return s ? std::string("\"") + s + "\"" : "null"; }

struct Input {
  std::string label, file;
  tmop::Mesh mesh;
  tmop::QualityReport report;
};

void print_text(const std::vector<Input>& in, const Input& a, const Input& b,
                const std::vector<std::pair<std::string, Displacement>>& moves) {
  std::printf("%-22s %-5s", "measure", "stat");
  for (const Input& i : in) std::printf(" %14s", i.label.c_str());
  std::printf("  better\n");
  auto count_row = [&](const char* name, auto get, bool applies) {
    std::printf("%-22s %-5s", name, "count");
    for (const Input& i : in) {
      if (applies) {
        std::printf(" %14lld", static_cast<long long>(get(i.report)));
      } else {
        std::printf(" %14s", "-");
      }
    }
    const char* w = applies ? better(get(a.report), get(b.report), true) : nullptr;
    std::printf("  %s\n", w ? w : "-");
  };
  count_row(
      "inverted cells", [](const tmop::QualityReport& r) { return r.inverted_cells; }, true);
  count_row(
      "slivers", [](const tmop::QualityReport& r) { return r.slivers; }, a.report.tets > 0);
  const std::vector<const tmop::QualityMeasure*> ma = a.report.measures(), mb = b.report.measures();
  for (std::size_t k = 0; k < ma.size(); ++k) {
    if (ma[k]->count + ma[k]->infinite == 0 && mb[k]->count + mb[k]->infinite == 0) continue;
    const Direction dir = direction(ma[k]->key);
    const char* stats[3] = {"min", "mean", "max"};
    for (int s = 0; s < 3; ++s) {
      std::printf("%-22s %-5s", s == 0 ? ma[k]->label.c_str() : "", stats[s]);
      for (const Input& i : in) {
        const tmop::QualityMeasure* m = i.report.measures()[k];
        const double v = s == 0 ? m->min : s == 1 ? m->mean : m->max;
        std::printf(" %14.6g", v);
      }
      const bool worst_row =
          (dir == Direction::kHigher && s == 0) || (dir == Direction::kLower && s == 2);
      const char* w = nullptr;
      if (worst_row)
        w = better(s == 0 ? ma[k]->min : ma[k]->max, s == 0 ? mb[k]->min : mb[k]->max,
                   dir == Direction::kLower);
      if (s == 1 && dir != Direction::kNone)
        w = better(ma[k]->mean, mb[k]->mean, dir == Direction::kLower);
      std::printf("  %s\n", w ? w : "");
    }
  }
  std::printf("%-22s %-5s", "unique edge length", "min");
  for (const Input& i : in) std::printf(" %14.6g", i.report.edge_length.min);
  std::printf("\n%-22s %-5s", "", "mean");
  for (const Input& i : in) std::printf(" %14.6g", i.report.edge_length.mean);
  std::printf("\n%-22s %-5s", "", "max");
  for (const Input& i : in) std::printf(" %14.6g", i.report.edge_length.max);
  std::printf("\n\ndisplacement          %12s %12s %12s %12s %12s %12s %8s\n", "max", "mean", "rms",
              "max/h", "mean/h", "rms/h", "moved");
  for (const auto& [name, d] : moves)
    std::printf("%-21s %12.6g %12.6g %12.6g %12.6g %12.6g %12.6g %8d\n", name.c_str(), d.max,
                d.mean, d.rms, d.max_rel, d.mean_rel, d.rms_rel, d.moved);
  std::printf("(h: mean length of the vertex's edges in the first mesh of the pair)\n");
}

std::string json_report(const std::vector<Input>& in, const Input& a, const Input& b,
                        const std::vector<std::pair<std::string, Displacement>>& moves) {
  std::string s = "{\n  \"format\": \"tmop.compare/1\"";
  for (const Input& i : in) {
    s += ",\n  \"" + i.label + "\": {\n    \"file\": \"";
    for (char c : i.file) s += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    s += "\",\n    \"quality\": " + nested(tmop::quality_json(i.report), "    ") + "\n  }";
  }
  s += ",\n  \"better\": {\n    \"inverted_cells\": " +
       quote(better(a.report.inverted_cells, b.report.inverted_cells, true)) +
       ",\n    \"slivers\": " +
       (a.report.tets > 0 ? quote(better(a.report.slivers, b.report.slivers, true)) : "null");
  const auto ma = a.report.measures(), mb = b.report.measures();
  for (std::size_t k = 0; k < ma.size(); ++k) {
    const Direction dir = direction(ma[k]->key);
    s += ",\n    \"" + ma[k]->key + "\": ";
    const bool applies = ma[k]->count > 0 && mb[k]->count > 0;
    if (dir == Direction::kNone || !applies) {
      s += "null";
      continue;
    }
    const bool lower = dir == Direction::kLower;
    s += "{\"worst\": " +
         quote(better(lower ? ma[k]->max : ma[k]->min, lower ? mb[k]->max : mb[k]->min, lower)) +
         ", \"mean\": " + quote(better(ma[k]->mean, mb[k]->mean, lower)) + "}";
  }
  s += "\n  },\n  \"displacement\": {";
  for (std::size_t k = 0; k < moves.size(); ++k)
    s += std::string(k ? "," : "") + "\n    \"" + moves[k].first +
         "\": " + displacement_json(moves[k].second, "    ");
  return s + "\n  }\n}\n";
}

}  // namespace

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "tmop_compare --a=A --b=B [--reference=ORIG] [--json]   (or: tmop_compare A B ...)\n"
      "Side-by-side quality of two meshes with the same topology, which is better on each "
      "measure, and their vertex displacements.\nExit codes: 0 success; 2 usage error, "
      "unreadable input or different topologies.");
  tmop_tools::parse_flags(&argc, &argv);
  tmop::remove_temporaries_on_signal("tmop_compare");
  std::vector<std::string> positional(argv + 1, argv + argc);
  if (!positional.empty() && FLAGS_a.empty())
    FLAGS_a = positional[0], positional.erase(positional.begin());
  if (!positional.empty() && FLAGS_b.empty())
    FLAGS_b = positional[0], positional.erase(positional.begin());
  if (!positional.empty()) return fail("unexpected argument '" + positional[0] + "'");
  if (FLAGS_a.empty() || FLAGS_b.empty()) return fail("two meshes are needed: --a=A --b=B or A B");

  std::vector<Input> in;
  if (!FLAGS_reference.empty()) in.push_back({"reference", FLAGS_reference, {}, {}});
  in.push_back({"a", FLAGS_a, {}, {}});
  in.push_back({"b", FLAGS_b, {}, {}});
  tmop::QualityOptions options;
  options.threads = FLAGS_threads;
  for (Input& i : in) {
    const tmop::Status s = tmop::read_mesh(i.file, &i.mesh);
    if (!s.ok()) return fail(s.message());
  }
  for (std::size_t k = 1; k < in.size(); ++k)
    if (!same_topology(in[0].mesh, in[k].mesh))
      return fail(in[0].file + " and " + in[k].file +
                  " have different topologies (vertices or cells differ)");
  for (Input& i : in) i.report = tmop::compute_quality(i.mesh, options);
  const Input& a = in[in.size() - 2];
  const Input& b = in[in.size() - 1];

  std::vector<std::pair<std::string, Displacement>> moves;
  moves.emplace_back("b_minus_a", displacement(a.mesh, b.mesh));
  if (in.size() == 3) {
    moves.emplace_back("a_minus_reference", displacement(in[0].mesh, a.mesh));
    moves.emplace_back("b_minus_reference", displacement(in[0].mesh, b.mesh));
  }
  if (!FLAGS_svg.empty()) {
    const std::string svg = tmop::quality_svg_compare(a.report, b.report, a.file, b.file);
    const tmop::Status written = tmop::write_file_atomically(FLAGS_svg, svg);
    if (!written.ok()) return fail(written.message());
  }
  if (FLAGS_json) {
    const std::string text = json_report(in, a, b, moves);
    std::fwrite(text.data(), 1, text.size(), stdout);
  } else {
    std::printf("a: %s\nb: %s\n", a.file.c_str(), b.file.c_str());
    if (in.size() == 3) std::printf("reference: %s\n", in[0].file.c_str());
    std::printf("\n");
    print_text(in, a, b, moves);
  }
  return 0;
}
