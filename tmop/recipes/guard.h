// tmop/recipes/guard.h
// The guard that keeps the guarantees of quality/guarantees.h while a recipe improves the mesh:
// after a solve, the cells that break a guarantee (guard_violators: below their type's and
// region's input worst, a fallen type mean, a new sliver or inversion) are held at their input
// shape - their vertices join the fixed set - and the solve runs again from the input. Held
// cells satisfy every guarantee, the held set only grows, so the rounds end. Each round's result
// is also repaired without a solve (its violators put back). When the guard ends - with the
// input back, with a result that holds cells, or out of rounds - the first round's moves are
// kept vertex by vertex where they keep every guarantee (with held cells: the held vertices
// only) and the vertices whose move was not kept move uphill on the measures (vertex_moves.h);
// the higher-scoring result is kept. When `rounds` re-solves are spent with nothing repaired,
// the largest step back towards the input among 1/2, 1/4, ..., 1/64 of the last result's
// displacement that keeps every guarantee is taken, else the input itself.
#ifndef TMOP_RECIPES_GUARD_H_
#define TMOP_RECIPES_GUARD_H_

#include <functional>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/solver_options.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct GuardOptions {
  bool enabled = true;          // false: one solve, nothing checked
  GuaranteeOptions guarantees;  // tolerance; whether type means and slivers are guarded
  int rounds = 4;               // re-solves with more cells held
  int threads = 0;              // for the measures (0 = all cores)
  // Later rounds start from the result with the held vertices back at their input positions
  // (when that mesh is valid) instead of from the input: t3's 34k cells 5 -> 3 solves, the
  // second of 2 iterations. Recipes with a size goal (equal_edge) restart from the input: a
  // held vertex put back beside a neighbour that moved towards it makes a short edge.
  bool warm_start = true;
  // The first soft_rounds rounds hold nothing: the violators' weights (GuardSolve's cell_weight,
  // for the recipe's shape term) are multiplied by soft_factor and the solve restarts from the
  // input. For recipes whose goal pulls every cell (equal_edge's sizes), where holding cells
  // only moves the pull to their neighbours.
  int soft_rounds = 0;
  double soft_factor = 8;
  bool verbose = false;  // print the broken guarantees of each round (stdout)
  // The recipe's progress callback (shared cancel state): once it is cancelled no further round
  // starts and guarded_solve returns Status::Cancelled with the mesh as the stopped solve left
  // it (valid; the guarantees are not checked on a cancelled run).
  ProgressCallback progress;
};

// solve(fixed, cell_weight, round): optimizes *mesh in place from its current coordinates (the
// input's, every round) with `fixed` vertices held, appending its stages to result->stages. `fixed`
// starts as the caller's flags (one per vertex). `baseline` is the input's (guarantee_baseline of
// *mesh as given). cell_weight (one per cell, 1 unless soft rounds raised it; empty: 1 for every
// cell, the rounds before any soft round) multiplies the
// recipe's shape term at the cell's points. Fills result->guard_held_cells and the last stage's
// termination note. Returns the first failing solve's status (mesh restored to the input).
using GuardSolve = std::function<Status(const std::vector<char>& fixed,
                                        const std::vector<double>& cell_weight, int round)>;
Status guarded_solve(Mesh* mesh, const GuaranteeBaseline& baseline, const GuardOptions& options,
                     std::vector<char> fixed, const GuardSolve& solve, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_GUARD_H_
