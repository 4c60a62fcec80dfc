#include "tmop/quality/count_inverted.h"

#include <vector>

#include "tmop/quality/element_scan.h"

namespace tmop {

std::int64_t count_inverted(const Mesh& mesh, int threads) {
  QualityOptions options;
  options.angles = false;
  options.threads = threads;
  std::vector<std::int64_t> per_chunk((mesh.num_cells() + kScanChunk - 1) / kScanChunk, 0);
  scan_elements(mesh, options, [&](std::int64_t chunk, std::int64_t, const CellQuality& q) {
    per_chunk[chunk] += q.inverted;
  });
  std::int64_t total = 0;
  for (std::int64_t n : per_chunk) total += n;
  return total;
}

}  // namespace tmop
