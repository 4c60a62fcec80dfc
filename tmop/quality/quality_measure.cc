#include "tmop/quality/quality_measure.h"

#include <algorithm>
#include <cmath>

namespace tmop {

void QualityMeasure::summarize() {
  count = infinite = 0;
  histogram = Histogram(histogram.edges);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
  for (double v : values) {
    if (std::isnan(v)) continue;
    histogram.add(v);
    if (std::isinf(v)) {
      ++infinite;
      continue;
    }
    ++count;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  min = count ? lo : kNaN;
  max = count ? hi : kNaN;
  mean = count ? sum / static_cast<double>(count) : kNaN;
}

}  // namespace tmop
