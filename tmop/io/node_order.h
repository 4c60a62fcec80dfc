// tmop/io/node_order.h
// Node-order tables between tmop (= Gmsh order, element/cell_type.h) and VTK (= meshio's
// internal order). Verified against ground truth: Gmsh 4.8 writing the same elements as .msh and
// .vtk, and meshio 5's gmsh<->vtk tables (docs/formats.md lists them):
//   wedge6: VTK's base triangle (0,1,2) has its normal pointing away from (3,4,5), Gmsh's towards
//           it, so VTK = Gmsh [0,2,1,3,5,4];
//   tet10:  mid-edge nodes 8 and 9 swapped (VTK 8 = edge 1-3, 9 = edge 2-3);
//   hex27:  VTK groups edges bottom / top / vertical and faces x- x+ y- y+ z- z+;
//   all other types (vertex, line2/3, tri3/6, quad4/9, tet4, hex8, pyramid5) are identical.
#ifndef TMOP_IO_NODE_ORDER_H_
#define TMOP_IO_NODE_ORDER_H_

#include "tmop/element/cell_type.h"

namespace tmop {
namespace io {

// VTK cell-type number of a tmop type.
int vtk_cell_type(CellType type);
// tmop type of a VTK cell-type number; false when tmop does not support it.
bool cell_type_from_vtk(int vtk_type, CellType* type);
// p[i] = the Gmsh-order index of VTK node i (cell_num_nodes(type) entries). Reading VTK:
// gmsh[p[i]] = vtk[i]; writing: vtk[i] = gmsh[p[i]].
const int* gmsh_index_of_vtk_node(CellType type);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_NODE_ORDER_H_
