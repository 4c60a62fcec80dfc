// tools/bench/perturb.h
// tmop_bench --task=perturb: interior vertices moved in a random direction by `amount` x their
// shortest incident edge. The directions come from splitmix64 seeded per vertex, so the result
// depends on (mesh, amount, seed) only, not on the standard library. keep_valid retries a move
// (20 tries) that would invert an incident element; without it every move is kept. *moved
// counts the vertices that moved.
#ifndef TMOP_TOOLS_BENCH_PERTURB_H_
#define TMOP_TOOLS_BENCH_PERTURB_H_

#include <cstdint>

#include "tmop/mesh/mesh.h"

namespace tmop_bench {

void perturb(tmop::Mesh* mesh, double amount, std::uint64_t seed, bool keep_valid, int* moved);

}  // namespace tmop_bench

#endif  // TMOP_TOOLS_BENCH_PERTURB_H_
