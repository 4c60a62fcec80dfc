// tmop/quality/quality_measure.h
// One per-cell quality measure of a QualityReport: the values of every cell, their statistics and
// histogram. The statistics cover the finite values only; +-inf values (the condition number of an
// inverted cell) are counted in `infinite` and in the histogram's `above` / `below`.
#ifndef TMOP_QUALITY_QUALITY_MEASURE_H_
#define TMOP_QUALITY_QUALITY_MEASURE_H_

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tmop/quality/histogram.h"

namespace tmop {

struct QualityMeasure {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  std::string key;    // stable name: JSON key and .vtu field name ("mean_ratio")
  std::string label;  // for humans ("mean ratio")
  std::string ideal;  // the ideal value as text ("1"), empty when there is none (edge lengths)
  // One value per cell of the mesh (all cells, so indices match Mesh cells); NaN where the
  // measure does not apply (lower-dimensional cells, other cell types).
  std::vector<double> values;

  std::int64_t count = 0;     // finite values
  std::int64_t infinite = 0;  // infinite values
  double min = kNaN;          // over finite values; NaN when count == 0
  double mean = kNaN;         // summed in cell order: identical for every thread count
  double max = kNaN;
  Histogram histogram;  // empty (no edges) for measures without fixed bins

  // Recomputes count, infinite, min, mean, max and the histogram's counts from values.
  void summarize();
};

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_MEASURE_H_
