// tmop/quality/parallel_for.h
// parallel_chunks: runs body(chunk, begin, end) for the fixed chunks [chunk * size, ...) of
// [0, n) on up to `threads` std::threads (0 = hardware_concurrency). The chunking depends on n and
// size only, so per-chunk results combined in chunk order are the same for every thread count.
#ifndef TMOP_QUALITY_PARALLEL_FOR_H_
#define TMOP_QUALITY_PARALLEL_FOR_H_

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace tmop {

inline int resolve_threads(int threads) {
  if (threads > 0) return threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

template <class Body>
void parallel_chunks(std::int64_t n, std::int64_t size, int threads, const Body& body) {
  const std::int64_t chunks = (n + size - 1) / size;
  const int workers = static_cast<int>(std::min<std::int64_t>(resolve_threads(threads), chunks));
  std::atomic<std::int64_t> next{0};
  auto work = [&] {
    for (std::int64_t c; (c = next.fetch_add(1)) < chunks;)
      body(c, c * size, std::min(n, (c + 1) * size));
  };
  if (workers <= 1) {
    work();
    return;
  }
  std::vector<std::thread> pool;
  for (int i = 1; i < workers; ++i) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace tmop

#endif  // TMOP_QUALITY_PARALLEL_FOR_H_
