// tmop/quality/edge_length_stats.h
// Length statistics over the unique edges of a mesh's elements (cells with dim == mesh.dim()):
// each corner-to-corner edge counted once however many cells share it. Quadratic cells contribute
// their corner edges (chords), as in cell_quality.h.
#ifndef TMOP_QUALITY_EDGE_LENGTH_STATS_H_
#define TMOP_QUALITY_EDGE_LENGTH_STATS_H_

#include <cstdint>
#include <limits>

#include "tmop/mesh/mesh.h"

namespace tmop {

struct EdgeLengthStats {
  std::int64_t count = 0;                                 // unique edges
  double min = std::numeric_limits<double>::quiet_NaN();  // length units; NaN when count == 0
  double mean = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

// Linear time (a counting sort of the edges by their lower vertex, no hashing); threads as in
// QualityOptions::threads; the result does not depend on the thread count.
EdgeLengthStats edge_length_stats(const Mesh& mesh, int threads = 0);

}  // namespace tmop

#endif  // TMOP_QUALITY_EDGE_LENGTH_STATS_H_
