// tmop/quality/element_scan.h
// scan_elements: calls visit(cell, CellQuality) for every element of a mesh (cells with
// dim == mesh.dim()) on QualityOptions::threads threads, chunk by chunk; visit must be safe to
// call concurrently for different cells. The shared loop of compute_quality, count_inverted and
// worst_quality: it gathers node coordinates (z = 0 for space_dim 2) and orients 2D cells by +z
// on planar meshes (quality_report.h).
#ifndef TMOP_QUALITY_ELEMENT_SCAN_H_
#define TMOP_QUALITY_ELEMENT_SCAN_H_

#include <cstdint>
#include <functional>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/quality_options.h"

namespace tmop {

// Returns mesh.dim(). planar (optional) receives whether 2D cells were oriented by +z.
int scan_elements(
    const Mesh& mesh, const QualityOptions& options,
    const std::function<void(std::int64_t chunk, std::int64_t cell, const CellQuality& q)>& visit,
    bool* planar = nullptr);

// True when mesh.dim() == 2 and the mesh lies in a plane z = const (or space_dim == 2): then 2D
// cells are oriented by +z and clockwise cells are inverted.
bool is_planar_2d(const Mesh& mesh);

// Cells per chunk of scan_elements: per-chunk partial results combined in chunk order do not
// depend on the thread count.
constexpr std::int64_t kScanChunk = 4096;

}  // namespace tmop

#endif  // TMOP_QUALITY_ELEMENT_SCAN_H_
