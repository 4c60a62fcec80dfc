// tmop/quality/histogram.h
// Histogram with fixed, documented bin edges (docs/quality.md lists the edges of every measure), so
// that histograms of different meshes and runs compare bin by bin.
#ifndef TMOP_QUALITY_HISTOGRAM_H_
#define TMOP_QUALITY_HISTOGRAM_H_

#include <cstdint>
#include <vector>

namespace tmop {

struct Histogram {
  // edges e_0 < e_1 < ... < e_n. Bin i counts values in [e_i, e_i+1); the last bin is closed,
  // [e_n-1, e_n], so that the ideal value 1 of a [0, 1] measure lands in the top bin.
  std::vector<double> edges;
  std::vector<std::int64_t> counts;  // edges.size() - 1 bins
  std::int64_t below = 0;            // values < e_0 (e.g. inverted cells of a [0, 1] measure)
  std::int64_t above = 0;            // values > e_n, +inf included. NaN is not counted anywhere.

  Histogram() = default;
  explicit Histogram(std::vector<double> bin_edges);
  void add(double value);
};

}  // namespace tmop

#endif  // TMOP_QUALITY_HISTOGRAM_H_
