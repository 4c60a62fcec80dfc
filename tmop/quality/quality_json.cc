#include "tmop/quality/quality_json.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <vector>

namespace tmop {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string integer(std::int64_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%" PRId64, v);
  return buf;
}

// Writes `"key": value` lines with commas between them, nested by indentation.
class JsonWriter {
 public:
  void open(const std::string& key) {
    field(key, "{");
    ++depth_;
    first_ = true;
  }
  void close() {
    --depth_;
    out_ += "\n" + std::string(2 * depth_, ' ') + "}";
    first_ = false;
  }
  void field(const std::string& key, const std::string& raw) {
    out_ += first_ ? "\n" : ",\n";
    out_ += std::string(2 * depth_, ' ');
    if (!key.empty()) out_ += "\"" + key + "\": ";
    out_ += raw;
    first_ = false;
  }
  std::string finish() { return out_ + "\n}\n"; }

 private:
  std::string out_ = "{";
  int depth_ = 1;
  bool first_ = true;
};

std::string number_array(const std::vector<double>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + number(values[i]);
  return s + "]";
}

std::string integer_array(const std::vector<std::int64_t>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + integer(values[i]);
  return s + "]";
}

bool applies(const QualityMeasure& m) { return m.count + m.infinite > 0; }

void write_measure(const QualityMeasure& m, JsonWriter* w) {
  if (!applies(m)) {
    w->field(m.key, "null");
    return;
  }
  w->open(m.key);
  w->field("count", integer(m.count));
  w->field("infinite", integer(m.infinite));
  w->field("min", number(m.min));
  w->field("mean", number(m.mean));
  w->field("max", number(m.max));
  w->close();
}

// {min, max} of a min-measure and a max-measure pair (angles, dihedral angles).
void write_range(const std::string& key, const QualityMeasure& lo, const QualityMeasure& hi,
                 JsonWriter* w) {
  if (!applies(lo)) {
    w->field(key, "null");
    return;
  }
  w->open(key);
  w->field("min", number(lo.min));
  w->field("max", number(hi.max));
  w->close();
}

}  // namespace

std::string quality_json(const QualityReport& r) {
  JsonWriter w;
  w.field("format", "\"tmop.quality/1\"");
  w.field("dim", integer(r.dim));
  w.field("space_dim", integer(r.space_dim));
  w.field("planar", r.planar ? "true" : "false");
  w.field("opposite_convention", r.opposite_convention ? "true" : "false");
  w.field("vertices", integer(r.num_vertices));
  w.field("elements", integer(r.num_elements));
  w.open("cells");
  for (int t = 0; t < kNumCellTypes; ++t)
    if (r.elements_by_type.size() == kNumCellTypes && r.elements_by_type[t] > 0)
      w.field(cell_name(static_cast<CellType>(t)), integer(r.elements_by_type[t]));
  w.close();
  w.field("inverted_cells", integer(r.inverted_cells));
  w.field("certifiable_cells", integer(r.certifiable_cells));
  w.field("certified_cells", integer(r.certified_cells));
  w.field("tets", integer(r.tets));
  w.field("slivers", r.tets > 0 ? integer(r.slivers) : "null");
  w.open("topology_capped");
  w.field("capped_valence_vertices", integer(r.capped_valence_vertices));
  w.field("capped_valence_examples", integer_array(r.capped_valence_examples));
  w.field("max_valence", integer(r.max_valence));
  w.field("cells_all_boundary", integer(r.cells_all_boundary));
  w.field("cells_all_boundary_examples", integer_array(r.cells_all_boundary_examples));
  w.close();
  write_range("angle_deg", r.min_angle, r.max_angle, &w);
  write_range("dihedral_deg", r.min_dihedral, r.max_dihedral, &w);
  if (r.edge_length.count > 0) {
    w.open("edge_length");
    w.field("count", integer(r.edge_length.count));
    w.field("min", number(r.edge_length.min));
    w.field("mean", number(r.edge_length.mean));
    w.field("max", number(r.edge_length.max));
    w.close();
  } else {
    w.field("edge_length", "null");
  }
  for (const QualityMeasure* m : r.measures()) write_measure(*m, &w);
  w.open("histograms");
  for (const QualityMeasure* m : r.measures()) {
    if (m->histogram.edges.empty() || !applies(*m)) continue;
    w.open(m->key);
    w.field("edges", number_array(m->histogram.edges));
    w.field("counts", integer_array(m->histogram.counts));
    w.field("below", integer(m->histogram.below));
    w.field("above", integer(m->histogram.above));
    w.close();
  }
  w.close();
  return w.finish();
}

}  // namespace tmop
