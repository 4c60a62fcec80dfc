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

// The repair without a solve, a step back towards the start blended over rings of neighbours:
// the unknowns (`unknown[v]`: the stage's free vertices) among the nodes of the cells that break
// a guarantee are held (*held), vertices k rings of cells away from a held one get the fraction
// t = k / 8 of their move from the start to the stage's result, the others all of it (t = 1);
// apply(t) puts the mesh there (and places whatever depends on those vertices). The cells are
// then found again (a vertex stepped back changes its neighbours) and their unknowns join the
// held set, until no cell breaks a guarantee (true; the caller checks that the mesh is not the
// start itself) or no unknown is added or max_passes are spent (false). The held set only grows,
// so the repair ends. Putting the held vertices back whole (no blend) makes the neighbours that
// moved towards them pay: on t3 at order 2 that cascaded for 9 passes and lowered the tet10
// corner mean ratio mean from the solve's 0.800 to 0.739; blended over 8 rings: 1 pass, 0.768.
// *violates: the mesh's violators on entry; *passes: the passes made.
bool step_back_until_kept(Mesh* mesh, const QuadraticBaseline& input, const ShapeOptions& options,
                          const std::vector<char>& unknown,
                          const std::function<void(const std::vector<double>& t)>& apply,
                          int max_passes, std::vector<char>* violates, int* passes,
                          std::string* first, std::vector<char>* held);

}  // namespace tmop

#endif  // TMOP_RECIPES_QUADRATIC_GUARD_H_
