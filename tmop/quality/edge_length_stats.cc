#include "tmop/quality/edge_length_stats.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tmop/quality/parallel_for.h"

namespace tmop {
namespace {

// |y - x|, also where the squared length under- or overflows (edges 1e-310 or 1e300 long):
// then the difference is scaled by its largest component first.
double edge_length(const double* x, const double* y, int sd) {
  double l2 = 0;
  for (int i = 0; i < sd; ++i) l2 += (y[i] - x[i]) * (y[i] - x[i]);
  if (l2 >= 0x1p-900 && l2 <= 0x1p900) return std::sqrt(l2);
  double m = 0;
  for (int i = 0; i < sd; ++i) m = std::max(m, std::abs(y[i] - x[i]));
  if (!(m > 0) || !std::isfinite(m)) return m;
  double s = 0;
  for (int i = 0; i < sd; ++i) s += ((y[i] - x[i]) / m) * ((y[i] - x[i]) / m);
  return m * std::sqrt(s);
}

}  // namespace

EdgeLengthStats edge_length_stats(const Mesh& mesh, int threads) {
  const int d = mesh.dim();
  const int nv = mesh.num_vertices();
  EdgeLengthStats out;
  if (d < 1 || nv == 0) return out;

  // Every element edge as (lower vertex a, higher vertex b), bucketed by a.
  std::vector<std::int64_t> start(static_cast<std::size_t>(nv) + 1, 0);
  auto for_each_edge = [&](auto&& f) {
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const CellInfo& info = cell_info(mesh.cell_types[c]);
      if (info.dim != d) continue;
      const std::int32_t* n = mesh.cell(c);
      for (int e = 0; e < info.num_edges; ++e) {
        const std::int32_t u = n[info.edges[e][0]], v = n[info.edges[e][1]];
        f(std::min(u, v), std::max(u, v));
      }
    }
  };
  for_each_edge([&](std::int32_t a, std::int32_t) { ++start[a + 1]; });
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::int32_t> other(start[nv]);
  {
    std::vector<std::int64_t> cursor(start.begin(), start.end() - 1);
    for_each_edge([&](std::int32_t a, std::int32_t b) { other[cursor[a]++] = b; });
  }

  // Per chunk of vertices: sort and deduplicate each bucket, accumulate. Chunks are combined in
  // order, so the sum is the same for every thread count.
  constexpr std::int64_t kChunk = 1 << 14;
  const std::int64_t chunks = (nv + kChunk - 1) / kChunk;
  std::vector<EdgeLengthStats> partial(chunks);
  std::vector<double> sums(chunks, 0.0);
  const int sd = mesh.space_dim;
  parallel_chunks(nv, kChunk, threads,
                  [&](std::int64_t chunk, std::int64_t begin, std::int64_t end) {
                    EdgeLengthStats s;
                    double lo = std::numeric_limits<double>::infinity(), hi = 0, sum = 0;
                    for (std::int64_t a = begin; a < end; ++a) {
                      std::int32_t* first = other.data() + start[a];
                      std::int32_t* last = other.data() + start[a + 1];
                      std::sort(first, last);
                      last = std::unique(first, last);
                      const double* x = mesh.vertex(static_cast<int>(a));
                      for (const std::int32_t* b = first; b != last; ++b) {
                        const double* y = mesh.vertex(*b);
                        const double l = edge_length(x, y, sd);
                        lo = std::min(lo, l);
                        hi = std::max(hi, l);
                        sum += l;
                        ++s.count;
                      }
                    }
                    s.min = lo;
                    s.max = hi;
                    partial[chunk] = s;
                    sums[chunk] = sum;
                  });
  double lo = std::numeric_limits<double>::infinity(), hi = 0, sum = 0;
  for (std::int64_t c = 0; c < chunks; ++c) {
    if (partial[c].count == 0) continue;
    out.count += partial[c].count;
    lo = std::min(lo, partial[c].min);
    hi = std::max(hi, partial[c].max);
    sum += sums[c];
  }
  if (out.count > 0) {
    out.min = lo;
    out.max = hi;
    out.mean = sum / static_cast<double>(out.count);
  }
  return out;
}

}  // namespace tmop
