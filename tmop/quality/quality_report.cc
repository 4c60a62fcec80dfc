#include "tmop/quality/quality_report.h"

#include <cmath>
#include <utility>

#include "tmop/mesh/orientation.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/element_scan.h"
#include "tmop/quality/topology_caps.h"

namespace tmop {
namespace {

std::vector<double> steps(double first, double last, double step) {
  std::vector<double> edges;
  const int n = static_cast<int>(std::lround((last - first) / step));
  for (int i = 0; i <= n; ++i) edges.push_back(first + i * step);
  return edges;
}

// Bins of [0, 1] measures: tenths (i / 10.0 is the double nearest to the decimal).
std::vector<double> tenths() {
  std::vector<double> edges;
  for (int i = 0; i <= 10; ++i) edges.push_back(i / 10.0);
  return edges;
}

void init(QualityMeasure* m, const char* key, const char* label, const char* ideal,
          std::vector<double> bins, std::int64_t num_cells) {
  m->key = key;
  m->label = label;
  m->ideal = ideal;
  m->values.assign(num_cells, QualityMeasure::kNaN);
  m->histogram = Histogram(std::move(bins));
}

}  // namespace

void QualityReport::release_per_cell_values() {
  // measures() is the one list of the measures; this report is not const, so neither are they.
  for (const QualityMeasure* m : measures())
    std::vector<double>().swap(const_cast<QualityMeasure*>(m)->values);
  std::vector<std::uint8_t>().swap(inverted);
  std::vector<double>().swap(certified);
  std::vector<double>().swap(all_boundary);
}

std::vector<const QualityMeasure*> QualityReport::measures() const {
  return {&mean_ratio,      &scaled_jacobian, &condition_number, &min_det,
          &min_angle,       &max_angle,       &min_dihedral,     &max_dihedral,
          &min_edge_length, &max_edge_length, &edge_ratio};
}

QualityReport compute_quality(const Mesh& mesh, const QualityOptions& options) {
  if (options.detect_convention && check_orientation(mesh).opposite_convention()) {
    Mesh own = mesh;
    reorient(&own);
    QualityOptions as_stored = options;
    as_stored.detect_convention = false;
    QualityReport r = compute_quality(own, as_stored);
    r.opposite_convention = true;
    return r;
  }
  QualityReport r;
  const int d = mesh.dim();
  const std::int64_t n = mesh.num_cells();
  r.dim = d;
  r.space_dim = mesh.space_dim;
  r.planar = is_planar_2d(mesh);
  r.num_vertices = mesh.num_vertices();
  r.num_cells = n;
  r.elements_by_type.assign(kNumCellTypes, 0);
  r.inverted.assign(n, 0);
  r.certified.assign(n, QualityMeasure::kNaN);
  const std::vector<double> angle_bins = steps(0, 180, 10);
  const std::vector<double> ratio_bins = {1, 1.25, 1.5, 2, 3, 5, 10, 100};
  init(&r.min_det, "min_det", "min det T", "", {}, n);
  init(&r.mean_ratio, "mean_ratio", "mean ratio", "1", tenths(), n);
  init(&r.scaled_jacobian, "scaled_jacobian", "scaled Jacobian", "1", tenths(), n);
  init(&r.condition_number, "condition_number", "condition number", "1", ratio_bins, n);
  init(&r.min_angle, "min_angle_deg", "min angle (deg)", "60/90", angle_bins, n);
  init(&r.max_angle, "max_angle_deg", "max angle (deg)", "60/90", angle_bins, n);
  init(&r.min_dihedral, "min_dihedral_deg", "min dihedral (deg)", "70.53", angle_bins, n);
  init(&r.max_dihedral, "max_dihedral_deg", "max dihedral (deg)", "70.53", angle_bins, n);
  init(&r.min_edge_length, "min_edge_length", "min edge length", "", {}, n);
  init(&r.max_edge_length, "max_edge_length", "max edge length", "", {}, n);
  init(&r.edge_ratio, "edge_ratio", "edge ratio", "1", ratio_bins, n);
  if (d < 2) return r;

  scan_elements(mesh, options, [&](std::int64_t, std::int64_t c, const CellQuality& q) {
    r.inverted[c] = q.inverted;
    r.certified[c] = q.certified;
    r.min_det.values[c] = q.min_det;
    r.mean_ratio.values[c] = q.mean_ratio;
    r.scaled_jacobian.values[c] = q.scaled_jacobian;
    r.condition_number.values[c] = q.condition_number;
    r.min_angle.values[c] = q.min_angle_deg;
    r.max_angle.values[c] = q.max_angle_deg;
    r.min_dihedral.values[c] = q.min_dihedral_deg;
    r.max_dihedral.values[c] = q.max_dihedral_deg;
    r.min_edge_length.values[c] = q.min_edge_length;
    r.max_edge_length.values[c] = q.max_edge_length;
    r.edge_ratio.values[c] = q.max_edge_length / q.min_edge_length;  // +inf for a 0 edge
  });

  for (std::int64_t c = 0; c < n; ++c) {
    const CellType type = mesh.cell_types[c];
    if (cell_dim(type) != d) continue;
    ++r.num_elements;
    ++r.elements_by_type[static_cast<int>(type)];
    r.inverted_cells += r.inverted[c];
    if (!std::isnan(r.certified[c])) {
      ++r.certifiable_cells;
      r.certified_cells += r.certified[c] == 1;
    }
    if (cell_info(type).linear == CellType::kTet4) {
      ++r.tets;
      r.slivers += r.max_dihedral.values[c] > kSliverMaxDihedralDeg &&
                   r.min_dihedral.values[c] < kSliverMinDihedralDeg;
    }
  }
  for (QualityMeasure* m : {&r.min_det, &r.mean_ratio, &r.scaled_jacobian, &r.condition_number,
                            &r.min_angle, &r.max_angle, &r.min_dihedral, &r.max_dihedral,
                            &r.min_edge_length, &r.max_edge_length, &r.edge_ratio}) {
    m->summarize();
  }
  r.edge_length = edge_length_stats(mesh, options.threads);
  topology_caps(mesh, &r);
  return r;
}

}  // namespace tmop
