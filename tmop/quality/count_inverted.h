// tmop/quality/count_inverted.h
// count_inverted: the number of inverted elements (cell_quality.h's `inverted`, default options:
// corners and default sample points, Bernstein bound for tri6/tet10), for progress lines. Skips
// angles and statistics, so it costs a fraction of compute_quality. Thread-safe.
#ifndef TMOP_QUALITY_COUNT_INVERTED_H_
#define TMOP_QUALITY_COUNT_INVERTED_H_

#include <cstdint>

#include "tmop/mesh/mesh.h"

namespace tmop {

// threads: as QualityOptions::threads (0 = all cores). Equals compute_quality(mesh).inverted_cells.
std::int64_t count_inverted(const Mesh& mesh, int threads = 0);

}  // namespace tmop

#endif  // TMOP_QUALITY_COUNT_INVERTED_H_
