// tools/bench/floor.h
// tmop_bench's per-sample-point table and the "floor": one residual + gradient pass over it
// written by hand, without Ceres (tasks evaluate and floor: how far Ceres' evaluation is from
// the cost of the arithmetic itself, docs/benchmarks.md).
#ifndef TMOP_TOOLS_BENCH_FLOOR_H_
#define TMOP_TOOLS_BENCH_FLOOR_H_

#include <cstdint>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/metric/metric.h"
#include "tmop/target/target.h"

namespace tmop_bench {

// Sample points with a free node, their cells, and G_i = W^-T grad N_i (compact: n*d per point).
struct PointTable {
  std::vector<std::int32_t> cell;
  std::vector<std::int64_t> offset;  // into G, size + 1
  std::vector<double> G;
  std::vector<double> weight;  // sqrt of the rule weight, as optimize_stage applies it
};

// The table of `mesh`'s default sample points whose cell has a node not `fixed`, for `target`
// (fails on a singular target).
tmop::Status build_points(const tmop::Mesh& mesh, const tmop::TargetSpec& target,
                          const std::vector<char>& fixed, PointTable* pt);

// One residual + gradient pass (the floor). Returns 0.5 |r|^2 like Ceres's cost; false when the
// metric fails (a barrier metric at an inverted point).
bool floor_pass(const tmop::Mesh& mesh, const PointTable& pt, const tmop::Metric& metric,
                std::vector<double>* gradient, double* cost);

}  // namespace tmop_bench

#endif  // TMOP_TOOLS_BENCH_FLOOR_H_
