// tmop/mesh/validate.h
// validate_mesh: checks what the rest of tmop assumes about a Mesh before anything indexes into
// it. Readers call it after parsing; tools report its message and exit.
//
// Checks, in this order (the first failure is returned):
//   - space_dim is 2 or 3 and the cell arrays have matching lengths;
//   - every coordinate is finite                            "vertex 12: coordinate 1 is nan"
//   - every cell: dimension <= space_dim, node count of its type, node indices in range,
//     no node repeated                                     "cell 17: node 12 out of range 0..9"
//   - no two elements (cells of dimension mesh.dim()) with the same node set
//                                                           "cell 17: same nodes as cell 3"
// Lower-dimensional cells may repeat (Gmsh writes a boundary line once per physical group).
// Cost: O(N log N), a few seconds at most for 10M cells.
#ifndef TMOP_MESH_VALIDATE_H_
#define TMOP_MESH_VALIDATE_H_

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

Status validate_mesh(const Mesh& mesh);

}  // namespace tmop

#endif  // TMOP_MESH_VALIDATE_H_
