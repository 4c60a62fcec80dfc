#include "tmop/quality/histogram.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tmop {

Histogram::Histogram(std::vector<double> bin_edges)
    : edges(std::move(bin_edges)), counts(edges.empty() ? 0 : edges.size() - 1, 0) {}

void Histogram::add(double value) {
  if (std::isnan(value) || counts.empty()) return;
  if (value < edges.front()) {
    ++below;
  } else if (value > edges.back()) {
    ++above;
  } else {
    // upper_bound finds the first edge > value; the closed last bin takes value == e_n.
    const std::size_t i = std::upper_bound(edges.begin(), edges.end(), value) - edges.begin();
    ++counts[std::min(i, counts.size()) - 1];
  }
}

}  // namespace tmop
