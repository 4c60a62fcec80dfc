// tmop/optimize/part_solve.h (internal: optimize/ only)
// One part of a partitioned stage (partitioned_stage.h): its free vertices move, every other
// node of the elements around them is held where the phase started. The part's problem lives in
// its own copy of those nodes' coordinates and is solved on one thread with the stage's
// stopping rules (the relative gradient, vertex movement relative to the local edge length,
// mean metric decrease per element of the part); the free vertices' results are written to
// `out` (the mesh's coordinates).
#ifndef TMOP_OPTIMIZE_PART_SOLVE_H_
#define TMOP_OPTIMIZE_PART_SOLVE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/stage_problem.h"
#include "tmop/partition/partition.h"

namespace tmop {

// Sample points per cell: points of cell c are at(offset[c]) .. at(offset[c+1] - 1). When the
// stage's points are already grouped by cell in cell order (the canonical sample set: 1M tets,
// 5M points) the list is the identity and is not stored.
struct CellPoints {
  std::vector<std::int32_t> offset;  // points are numbered in int32 (point_cell), so are these
  std::vector<std::int32_t> point;   // empty when identity
  bool identity = false;
  std::int32_t at(std::int64_t k) const {
    return identity ? static_cast<std::int32_t>(k) : point[static_cast<std::size_t>(k)];
  }
};
CellPoints cell_points(const Mesh& mesh, const std::vector<std::int32_t>& point_cell);

struct PartOutcome {
  bool ok = true;
  std::string error;                        // when !ok
  double initial_cost = 0, final_cost = 0;  // Ceres's costs (half the sum of squares)
  int iterations = 0, elements = 0;
  std::string linear_solver;
  StageResult::Times times;
};

// Reusable per-worker buffers (one int per vertex and per cell).
struct PartScratch {
  std::vector<int> local;  // vertex -> local index, -1 outside the part
  std::vector<int> mark;   // cell -> the last part that took it
  int stamp = 0;
};

// `start`: the coordinates at the start of the phase (read only); `free`: the part's free
// vertices, sorted; seconds: what is left of the stage's time; function_tolerance: Ceres's, for
// this part (the stage's, or the first sweep's, SolverOptions::first_sweep_tolerance).
PartOutcome solve_part(const Mesh& mesh, const std::vector<double>& start, const StageContext& ctx,
                       const IdealTable& table, const VertexCells& vc, const CellPoints& cp,
                       const std::vector<int>& free, double seconds, double function_tolerance,
                       PartScratch* scratch, std::vector<double>* out);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_PART_SOLVE_H_
