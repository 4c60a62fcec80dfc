#include "tmop/quality/quality_summary.h"

#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace tmop {
namespace {

void append(std::string* out, const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  *out += buf;
}

std::string g6(double v) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::string quality_summary(const QualityReport& r) {
  std::string out;
  append(&out, "mesh: %dD elements in %dD space%s, %" PRId64 " vertices, %" PRId64 " elements",
         r.dim, r.space_dim, r.planar ? " (planar)" : "", r.num_vertices, r.num_elements);
  std::string types;
  for (int t = 0; t < kNumCellTypes && r.elements_by_type.size() == kNumCellTypes; ++t) {
    if (r.elements_by_type[t] == 0) continue;
    append(&types, "%s%s %" PRId64, types.empty() ? "" : ", ", cell_name(static_cast<CellType>(t)),
           r.elements_by_type[t]);
  }
  out += types.empty() ? "\n" : " (" + types + ")\n";
  if (r.opposite_convention)
    out += "orientation: opposite convention (most cells negative); measured in that convention\n";
  append(&out, "inverted: %" PRId64, r.inverted_cells);
  if (r.certifiable_cells > 0)
    append(&out, "   certified valid: %" PRId64 " of %" PRId64, r.certified_cells,
           r.certifiable_cells);
  if (r.tets > 0) append(&out, "   slivers: %" PRId64 " of %" PRId64 " tets", r.slivers, r.tets);
  out += "\n";
  if (r.capped_valence_vertices > 0 || r.cells_all_boundary > 0) {
    out += "quality capped by topology:";
    if (r.capped_valence_vertices > 0) {
      append(&out, " %" PRId64 " vertices of extreme valence (max %" PRId64 "; ids",
             r.capped_valence_vertices, r.max_valence);
      for (std::int64_t v : r.capped_valence_examples) append(&out, " %" PRId64, v);
      out += r.capped_valence_vertices > static_cast<std::int64_t>(r.capped_valence_examples.size())
                 ? " ...)"
                 : ")";
    }
    if (r.cells_all_boundary > 0) {
      append(&out, "%s %" PRId64 " elements with every corner on the boundary (ids",
             r.capped_valence_vertices > 0 ? ";" : "", r.cells_all_boundary);
      for (std::int64_t c : r.cells_all_boundary_examples) append(&out, " %" PRId64, c);
      out += r.cells_all_boundary > static_cast<std::int64_t>(r.cells_all_boundary_examples.size())
                 ? " ...)"
                 : ")";
    }
    out += "\n";
  }
  if (r.edge_length.count > 0) {
    append(&out, "edge length (%" PRId64 " unique edges): min %s  mean %s  max %s\n",
           r.edge_length.count, g6(r.edge_length.min).c_str(), g6(r.edge_length.mean).c_str(),
           g6(r.edge_length.max).c_str());
  }
  if (r.num_elements == 0) return out + "no 2D or 3D elements to measure\n";
  out += "\n";
  append(&out, "%-20s %12s %12s %12s %8s %10s\n", "measure", "min", "mean", "max", "ideal",
         "infinite");
  for (const QualityMeasure* m : r.measures()) {
    if (m->count + m->infinite == 0) continue;
    append(&out, "%-20s %12s %12s %12s %8s %10" PRId64 "\n", m->label.c_str(), g6(m->min).c_str(),
           g6(m->mean).c_str(), g6(m->max).c_str(), m->ideal.empty() ? "-" : m->ideal.c_str(),
           m->infinite);
  }
  return out;
}

}  // namespace tmop
