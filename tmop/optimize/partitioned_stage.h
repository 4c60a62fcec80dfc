// tmop/optimize/partitioned_stage.h (internal: optimize/ only; not part of tmop.h)
// The partitioned solve of a stage (DESIGN.md section 12; SolverOptions::part_size). A sweep:
// - phase A: the parts of a METIS partition P1 of the elements, side by side on the stage's
//   threads, each its own ceres::Problem (one thread) over the free vertices inside the part
//   (every element around them in the part); the vertices on P1's cuts are held;
// - phase B: the vertices on P1's cuts and their neighbours, in the parts of a second partition
//   P2 whose cuts avoid P1's cut vertices (METIS with heavy dual-graph edges there);
// - phase C: those of them still on a cut of P2, one problem (few).
// Sweeps repeat until one lowers the solver's objective by less than sweep_tolerance of itself.
// Every part reads the coordinates as they were at the start of its phase and the parts of a
// phase move disjoint vertex sets whose elements are disjoint: the result does not depend on
// the number of threads or the order parts finish in, every element is changed by one part at
// a time (a barrier part never inverts one), and the stage's objective is the sum of the parts'.
// Only the parts being solved hold Ceres problems.
#ifndef TMOP_OPTIMIZE_PARTITIONED_STAGE_H_
#define TMOP_OPTIMIZE_PARTITIONED_STAGE_H_

#include <chrono>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/sample_measures.h"
#include "tmop/optimize/stage.h"
#include "tmop/optimize/stage_problem.h"

namespace tmop {

// How many parts optimize_stage solves `spec` on `mesh` in (SolverOptions::partitions, else
// part_size); 1 means one problem (untangling, surface meshes, or too small a mesh).
int stage_num_parts(const Mesh& mesh, const StageSpec& spec);
// Whether optimize_stage solves `spec` on `mesh` in parts: stage_num_parts >= 2.
bool use_partitions(const Mesh& mesh, const StageSpec& spec);

// Solves the stage in parts, in place (mesh in the stage's frame). Marks in_problem, fills the
// result's counts, iterations, solves, times, parts and sweeps; *reason says why it stopped.
Status solve_partitioned(Mesh* mesh, const StageContext& ctx, const IdealTable& table,
                         std::chrono::steady_clock::time_point start, std::vector<char>* in_problem,
                         StageResult* result, std::string* reason);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_PARTITIONED_STAGE_H_
