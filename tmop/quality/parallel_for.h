// tmop/quality/parallel_for.h
// parallel_chunks: runs body(chunk, begin, end) for the fixed chunks [chunk * size, ...) of
// [0, n) on up to `threads` std::threads (0 = hardware_concurrency). The chunking depends on n and
// size only, so per-chunk results combined in chunk order are the same for every thread count.
// side_by_side (below): two different tasks at once.
#ifndef TMOP_QUALITY_PARALLEL_FOR_H_
#define TMOP_QUALITY_PARALLEL_FOR_H_

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <system_error>
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

// side_by_side: runs a() on a second thread and b() on this one when concurrent (a() then b()
// when not, or when no thread can be started). An exception from a() is rethrown here after
// both finished; one from b() propagates after a() finished. For read-only passes over shared
// data that each write their own results.
template <class A, class B>
void side_by_side(bool concurrent, const A& a, const B& b) {
  std::exception_ptr error;
  std::thread other;
  if (concurrent) {
    try {
      other = std::thread([&] {
        try {
          a();
        } catch (...) {
          error = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      // no thread to be had: run in turn below
    }
  }
  if (!other.joinable()) {
    a();
    b();
    return;
  }
  {
    struct Join {
      std::thread& t;
      ~Join() { t.join(); }
    } join{other};
    b();
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace tmop

#endif  // TMOP_QUALITY_PARALLEL_FOR_H_
