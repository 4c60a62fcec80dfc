#include "tmop/optimize/locality_order.h"

#include <algorithm>
#include <limits>

namespace tmop {
namespace {

// Spreads the low 21 bits of v to every third bit (Morton interleaving).
std::uint64_t spread3(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

std::vector<std::int32_t> locality_order(const Mesh& mesh, const std::vector<std::int32_t>& cell) {
  const int sd = mesh.space_dim;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < sd; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int a = 0; a < sd; ++a) {
      lo[a] = std::min(lo[a], mesh.vertex(v)[a]);
      hi[a] = std::max(hi[a], mesh.vertex(v)[a]);
    }
  std::vector<std::uint64_t> key(cell.size());
  int previous = -1;
  std::uint64_t previous_key = 0;
  for (std::size_t p = 0; p < cell.size(); ++p) {
    const int c = cell[p];
    if (c != previous) {
      const int k = cell_info(mesh.cell_type(c)).num_corners;
      std::uint64_t code = 0;
      for (int a = 0; a < sd; ++a) {
        double x = 0;
        for (int i = 0; i < k; ++i) x += mesh.vertex(mesh.cell(c)[i])[a] / k;
        const double span = hi[a] - lo[a];
        const double t = span > 0 ? (x - lo[a]) / span : 0.0;
        const auto q = static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 2097151.0);
        code |= spread3(q) << a;
      }
      previous = c;
      previous_key = code;
    }
    key[p] = previous_key;
  }
  std::vector<std::int32_t> order(cell.size());
  for (std::size_t p = 0; p < order.size(); ++p) order[p] = static_cast<std::int32_t>(p);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::int32_t a, std::int32_t b) { return key[a] < key[b]; });
  return order;
}

}  // namespace tmop
