// tmop/recipes/vertex_moves.h
// Keeping the good part of a move, vertex by vertex (the guard's repair, recipes/guard.h).
//
// A solve that breaks a guarantee somewhere still moves most vertices for the better (Gmsh's
// pripyrtet: the solve lowers the wedges' and pyramids' scaled Jacobian while it raises the tets'
// mean ratio, and holding the 95 violating cells holds every free vertex). accept_vertex_moves
// starts from a mesh that keeps every guarantee and moves one vertex at a time towards the
// solve's result (the whole way, else 1/2, else 1/4 of it), keeping a move only when
//   - no cell of the vertex falls below its (type, region, measure) group's input worst, or
//     below its own value when it was there already; no new sliver, no new inversion;
//   - with means guarded, every (type, measure) sum over the cells stays at least the input's
//     (a cell type may lose where another move of the same type gained before);
//   - the sum of the guaranteed-mean measures of the vertex's cells rises.
// Every kept move keeps every guarantee, so the result keeps them all by construction, and the
// score (sum of guaranteed-mean measures) rises with every move, so the passes end.
#ifndef TMOP_RECIPES_VERTEX_MOVES_H_
#define TMOP_RECIPES_VERTEX_MOVES_H_

#include <cstdint>
#include <vector>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/guarantees.h"

namespace tmop {

struct VertexMoveOptions {
  int passes = 4;  // sweeps over the vertices (a moved vertex changes its neighbours' options)
  // Per vertex: 1 = only the whole move (a sliding boundary vertex: a part of its move leaves
  // its curve or surface). Empty: every vertex may take part of its move.
  std::vector<char> whole_only;
  // Per vertex: 1 = may move. Empty: every vertex.
  std::vector<char> only;
};

// *mesh keeps every guarantee of `baseline` (checked with `guarantees`: means, slivers,
// tolerance); *values are its guarantee values and are kept up to date. target: the coordinates
// to move towards (mesh->coords' size). Returns the number of moves kept.
int accept_vertex_moves(Mesh* mesh, const std::vector<double>& target,
                        const GuaranteeBaseline& baseline, const GuaranteeOptions& guarantees,
                        const VertexMoveOptions& options, GuaranteeValues* values);

// Where the solve's moves do not help (every vertex's move lowers the score), moves each
// `movable` vertex uphill on the guaranteed measures of its cells instead: a step along the
// central-difference gradient of their score (1/8, 1/32, 1/128 of its shortest edge), else along
// the axis and diagonal directions, kept under the same rules; then the edges both of whose
// vertices could not move alone, translated together (a prism between two moved layers keeps
// its right angles only when both copies of its vertex move). At most `passes` sweeps, and no
// new sweep or vertex once `budget` cells have been measured. Returns the number of moves kept.
int climb_vertex_measures(Mesh* mesh, const std::vector<char>& movable,
                          const GuaranteeBaseline& baseline, const GuaranteeOptions& guarantees,
                          int passes, std::int64_t budget, GuaranteeValues* values);

// The sum over the cells in a guarantee group of their guaranteed-mean measures (mean ratio,
// scaled Jacobian, corner mean ratio, det J ratio): which of two results that keep every
// guarantee is better by quality.
double guarantee_score(const GuaranteeBaseline& baseline, const GuaranteeValues& values);

}  // namespace tmop

#endif  // TMOP_RECIPES_VERTEX_MOVES_H_
