// tmop/recipes/quadratic_guard.h (internal to recipes/)
// The guard of the quadratic shape recipe (quadratic_shape.h): the cells of a result that break
// one of its guarantees against the input, and the repair without a solve that puts cells back
// at their input shape until none breaks one.
#ifndef TMOP_RECIPES_QUADRATIC_GUARD_H_
#define TMOP_RECIPES_QUADRATIC_GUARD_H_

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/guarantees.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/quadratic_shape.h"

namespace tmop {

// Per quadratic type: the worst and the sum of the guarded measures (corner quality, pointwise
// mean ratio, det J ratio) and the dihedral range of the corner tets.
constexpr int kQuadraticGuarded = 3;
struct QuadraticTypeBounds {
  int count = 0;
  double worst[kQuadraticGuarded] = {std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::infinity()};
  double sum[kQuadraticGuarded] = {0, 0, 0};
  double min_dihedral = std::numeric_limits<double>::infinity();
  double max_dihedral = -std::numeric_limits<double>::infinity();
};

// The input as the guard compares against it.
struct QuadraticBaseline {
  std::vector<QuadraticCellMeasures> cells;  // per cell (quadratic elements only)
  std::vector<QuadraticTypeBounds> types;    // per CellType
  GuaranteeBaseline guarantees;              // quality/guarantees.h, per type and region
};
// threads: as SolverOptions::threads (0 = all cores); the result does not depend on it.
QuadraticBaseline quadratic_baseline(const Mesh& input, int threads);

// The cells of `mesh` that break a guarantee of quadratic_shape.h against the input: flags them
// in *violates (one per cell) and returns their count; *first describes one.
int quadratic_violators(const Mesh& mesh, const QuadraticBaseline& input,
                        const ShapeOptions& options, std::vector<char>* violates,
                        std::string* first);

// The repair without a solve, a per-vertex step back towards the start: every vertex v with
// `unknown[v]` has a fraction t[v] (1 at first) of its move from the start to the stage's result;
// apply(t) puts the mesh there (and places whatever depends on those vertices). While cells break
// a guarantee, the unknowns among their nodes halve their fraction (below 1/16: 0, the start
// itself), and the cells are found again (a node stepped back changes its neighbours too). A
// whole cell put back at once makes the neighbours that moved towards it pay: on t3 at order 2
// the cascade went on for 9 passes and kept 12,153 of 19,312 improved tets; halving keeps
// them. The fractions only fall and reach 0 in 5 halvings, so the repair ends: true when no cell
// breaks a guarantee (the caller checks that the mesh is not the start itself), false when
// max_passes are spent or every violator is at its start. *violates: the mesh's violators on entry;
// *passes: passes made.
bool step_back_until_kept(Mesh* mesh, const QuadraticBaseline& input, const ShapeOptions& options,
                          const std::vector<char>& unknown,
                          const std::function<void(const std::vector<double>& t)>& apply,
                          int max_passes, std::vector<char>* violates, int* passes,
                          std::string* first, std::vector<char>* held);

}  // namespace tmop

#endif  // TMOP_RECIPES_QUADRATIC_GUARD_H_
