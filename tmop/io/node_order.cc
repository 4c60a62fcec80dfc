#include "tmop/io/node_order.h"

namespace tmop {
namespace io {
namespace {

const int kIdentity[kMaxCellNodes] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13,
                                      14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
const int kWedge6[6] = {0, 2, 1, 3, 5, 4};
const int kTet10[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
const int kHex27[27] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                        19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};

// Indexed by CellType.
const int kVtkTypes[kNumCellTypes] = {
    1,   // vertex: VTK_VERTEX
    3,   // line2: VTK_LINE
    21,  // line3: VTK_QUADRATIC_EDGE
    5,   // tri3: VTK_TRIANGLE
    9,   // quad4: VTK_QUAD
    10,  // tet4: VTK_TETRA
    12,  // hex8: VTK_HEXAHEDRON
    13,  // wedge6: VTK_WEDGE
    14,  // pyramid5: VTK_PYRAMID
    22,  // tri6: VTK_QUADRATIC_TRIANGLE
    28,  // quad9: VTK_BIQUADRATIC_QUAD
    24,  // tet10: VTK_QUADRATIC_TETRA
    29,  // hex27: VTK_TRIQUADRATIC_HEXAHEDRON
};

}  // namespace

int vtk_cell_type(CellType type) { return kVtkTypes[static_cast<int>(type)]; }

bool cell_type_from_vtk(int vtk_type, CellType* type) {
  for (int i = 0; i < kNumCellTypes; ++i) {
    if (kVtkTypes[i] == vtk_type) {
      *type = static_cast<CellType>(i);
      return true;
    }
  }
  return false;
}

const int* gmsh_index_of_vtk_node(CellType type) {
  switch (type) {
    case CellType::kWedge6:
      return kWedge6;
    case CellType::kTet10:
      return kTet10;
    case CellType::kHex27:
      return kHex27;
    default:
      return kIdentity;
  }
}

}  // namespace io
}  // namespace tmop
