// tmop/quality/quality_report.h
// compute_quality: every quality measure of every element of a mesh (cell_quality.h), their
// statistics and fixed-bin histograms (docs/quality.md lists keys, ranges and bins), the number
// of inverted cells and slivers, and edge-length statistics over unique edges.
//
// Only elements (cells with dim == mesh.dim()) are measured; lower-dimensional cells (boundary
// tags) get NaN in every per-cell array. Planar meshes (space_dim 2, or space_dim 3 with every z
// equal) orient 2D cells by +z, so clockwise cells are inverted; 2D cells of a non-planar (surface)
// mesh are oriented by their own normal (cell_quality.h).
//
// Cost: one pass over the cells on QualityOptions::threads threads plus a linear-time edge pass;
// about 0.5 s for 1M tets on 2 cores (docs/quality.md has the measurements).
#ifndef TMOP_QUALITY_QUALITY_REPORT_H_
#define TMOP_QUALITY_QUALITY_REPORT_H_

#include <cstdint>
#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/edge_length_stats.h"
#include "tmop/quality/quality_measure.h"
#include "tmop/quality/quality_options.h"

namespace tmop {

// A tet is a sliver when its max dihedral angle exceeds kSliverMaxDihedralDeg and its min is below
// kSliverMinDihedralDeg (DESIGN.md section 10).
constexpr double kSliverMaxDihedralDeg = 150;
constexpr double kSliverMinDihedralDeg = 10;

struct QualityReport {
  int dim = 0;          // mesh.dim(): dimension of the measured elements
  int space_dim = 0;    // mesh.space_dim
  bool planar = false;  // 2D cells oriented by +z (see above)
  // The mesh uses the opposite orientation convention and was measured in it (every cell
  // reoriented first; QualityOptions::detect_convention).
  bool opposite_convention = false;
  std::int64_t num_vertices = 0;
  std::int64_t num_cells = 0;                  // all cells
  std::int64_t num_elements = 0;               // measured cells
  std::vector<std::int64_t> elements_by_type;  // kNumCellTypes entries, by CellType

  // Per cell (num_cells entries): 1 inverted, 0 not (0 for lower-dimensional cells).
  std::vector<std::uint8_t> inverted;
  std::int64_t inverted_cells = 0;
  // Per cell: cell_quality.h's `certified` (1, 0, NaN).
  std::vector<double> certified;
  std::int64_t certifiable_cells = 0;  // elements of a type that has a certificate
  std::int64_t certified_cells = 0;    // of those, proven valid
  std::int64_t tets = 0;               // tet4 + tet10 elements
  std::int64_t slivers = 0;            // tets that are slivers

  QualityMeasure min_det;  // cell_quality.h's definitions; histograms in docs/quality.md
  QualityMeasure mean_ratio;
  QualityMeasure scaled_jacobian;
  QualityMeasure condition_number;
  QualityMeasure min_angle;  // degrees
  QualityMeasure max_angle;
  QualityMeasure min_dihedral;  // degrees
  QualityMeasure max_dihedral;
  QualityMeasure min_edge_length;  // per cell, length units
  QualityMeasure max_edge_length;
  QualityMeasure edge_ratio;  // per cell max / min edge length, >= 1 (+inf for a 0 edge)

  EdgeLengthStats edge_length;  // over unique edges of the mesh

  // Where node movement alone cannot reach the ideal (topology_caps.h): corner vertices whose
  // valence is far from the ideal one (triangles 6, quads 4; interior vertices of all-triangle or
  // all-quad 2D / surface meshes: valence <= 3 or >= 9 for triangles, <= 2 or >= 6 for quads),
  // and elements whose corners all lie on the boundary (a fixed boundary freezes them).
  std::int64_t capped_valence_vertices = 0;
  std::vector<std::int64_t> capped_valence_examples;  // up to 20 vertex ids, ascending
  std::int64_t max_valence = 0;                       // over interior vertices (2D / surface)
  std::int64_t cells_all_boundary = 0;
  std::vector<std::int64_t> cells_all_boundary_examples;  // up to 20 cell ids, ascending
  // Per cell (num_cells entries): 1 for an element with every corner on the boundary, 0 for the
  // other elements, NaN for lower-dimensional cells (the .vtu field "all_boundary").
  std::vector<double> all_boundary;

  // The measures above in report order (for JSON, summaries, fields, plots).
  std::vector<const QualityMeasure*> measures() const;

  // Frees the per-cell arrays (each measure's values, inverted, certified, all_boundary) and
  // keeps everything the JSON and text summaries use (counts, min / mean / max, histograms,
  // examples): a report kept while the mesh is optimized costs ~100 MB at 1M tets otherwise.
  void release_per_cell_values();
};

QualityReport compute_quality(const Mesh& mesh, const QualityOptions& options = {});

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_REPORT_H_
