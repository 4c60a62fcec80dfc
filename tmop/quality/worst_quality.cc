#include "tmop/quality/worst_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tmop/quality/element_scan.h"

namespace tmop {

namespace {
// Simplices have a mean ratio; the other types do not, so fall back to the scaled Jacobian.
double headline(const CellQuality& q) {
  return std::isnan(q.mean_ratio) ? q.scaled_jacobian : q.mean_ratio;
}
}  // namespace

std::vector<double> cell_headline_quality(const Mesh& mesh, int threads) {
  QualityOptions options;
  options.angles = false;
  options.threads = threads;
  std::vector<double> out(mesh.num_cells(), std::numeric_limits<double>::quiet_NaN());
  scan_elements(mesh, options, [&](std::int64_t, std::int64_t cell, const CellQuality& q) {
    out[cell] = headline(q);
  });
  return out;
}

double worst_quality(const Mesh& mesh, int threads) {
  QualityOptions options;
  options.angles = false;
  options.threads = threads;
  const double none = std::numeric_limits<double>::infinity();
  std::vector<double> per_chunk((mesh.num_cells() + kScanChunk - 1) / kScanChunk, none);
  scan_elements(mesh, options, [&](std::int64_t chunk, std::int64_t, const CellQuality& q) {
    per_chunk[chunk] = std::min(per_chunk[chunk], headline(q));
  });
  double worst = none;
  for (double v : per_chunk) worst = std::min(worst, v);
  return worst == none ? std::numeric_limits<double>::quiet_NaN() : worst;
}

}  // namespace tmop
