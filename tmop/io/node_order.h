// tmop/io/node_order.h
// Node-order tables between tmop (= Gmsh order, element/cell_type.h) and VTK (= meshio's
// internal order). Verified against ground truth: Gmsh 4.8 writing the same elements as .msh and
// .vtk, and meshio 5's gmsh<->vtk tables (docs/formats.md lists them):
//   wedge6: VTK's base triangle (0,1,2) has its normal pointing away from (3,4,5), Gmsh's towards
//           it, so VTK = Gmsh [0,2,1,3,5,4];
//   tet10:  mid-edge nodes 8 and 9 swapped (VTK 8 = edge 1-3, 9 = edge 2-3);
//   hex27:  VTK groups edges bottom / top / vertical and faces x- x+ y- y+ z- z+;
//   hex20:  hex27's first 20 entries;
//   wedge15 / wedge18: wedge6's corners, edges bottom / top / vertical (and wedge18's quad faces
//           0-1-4-3 0-2-5-3 1-2-5-4 as VTK's 17 15 16);
//   all other types (vertex, line2/3, tri3/6, quad4/8/9, tet4, hex8, pyramid5) are identical.
// The quadratic tables were derived from VTK 9's own parametric coordinates of each node
// (vtkCell::GetParametricCoords) and checked by tests/io/vtk_cells_test.py through vtk itself.
#ifndef TMOP_IO_NODE_ORDER_H_
#define TMOP_IO_NODE_ORDER_H_

#include <cstdint>
#include <string>

#include "tmop/element/cell_type.h"
#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

// VTK cell-type number of a tmop type; -1 for pyramid14, which VTK has no type for.
int vtk_cell_type(CellType type);
// tmop type of a VTK cell-type number; false when tmop does not support it.
bool cell_type_from_vtk(int vtk_type, CellType* type);
// p[i] = the Gmsh-order index of VTK node i (cell_num_nodes(type) entries). Reading VTK:
// gmsh[p[i]] = vtk[i]; writing: vtk[i] = gmsh[p[i]].
const int* gmsh_index_of_vtk_node(CellType type);

// Exodus II and CGNS share PATRAN's corner and edge order: Gmsh's corners, then one node per edge
// in their own edge order, then face / centre nodes.
//   tet10:   edges 0-1 1-2 2-0 0-3 1-3 2-3 (Gmsh's 3-2, 3-1 swapped);
//   hex20 / hex27: bottom 0-1 1-2 2-3 3-0, vertical 0-4 1-5 2-6 3-7, top 4-5 5-6 6-7 7-4;
//   wedge15 / wedge18: bottom 0-1 1-2 2-0, vertical 0-3 1-4 2-5, top 3-4 4-5 5-3;
//   pyramid13 / pyramid14: base 0-1 1-2 2-3 3-0, then 0-4 1-4 2-4 3-4 (pyramid14: then the base
//            centre, as Gmsh);
//   wedge18's face nodes (both): faces 0-1-4-3, 1-2-5-4, 2-0-3-5;
//   hex27's face and centre nodes differ: Exodus puts the centre first, then faces z- z+ x- x+
//            y- y+ (x- = corners 0-3-7-4, y- = 0-1-5-4); CGNS puts faces z- y- x+ y+ x- z+ first,
//            then the centre;
//   tri6, quad8, quad9 and the linear types: Gmsh's order.
enum class PatranFormat { kExodus, kCgns };
// The Exodus / CGNS position of Gmsh node i of a cell of `type`.
int patran_index_of_gmsh_node(CellType type, int i, PatranFormat format);

// Throws "cannot write TYPE cells to FORMAT (...)" when the mesh has a cell without a VTK type.
void check_vtk_cell_types(const Mesh& mesh, const char* format);

// The tail of the message refusing VTK cell type `vtk_type`: its VTK name where the refused
// type is a common one (polygon, polyhedron, pixel, voxel, quadratic pyramid, arbitrary-order
// Lagrange / Bezier cells) and the list of types tmop reads, e.g.
// " (VTK_POLYHEDRON; tmop reads vertex, line2, ...)".
std::string unsupported_vtk_type_note(std::int64_t vtk_type);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_NODE_ORDER_H_
