#include "tmop/element/cell_type.h"

namespace tmop {
namespace {

const int kLineEdges[][2] = {{0, 1}};
const int kTriEdges[][2] = {{0, 1}, {1, 2}, {2, 0}};
const int kQuadEdges[][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
// Gmsh's edge orders: mid-edge nodes of tet10 / hex27 follow them.
const int kTetEdges[][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
const int kHexEdges[][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                            {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
const int kWedgeEdges[][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4},
                              {2, 5}, {3, 4}, {3, 5}, {4, 5}};
const int kPyramidEdges[][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}};

const CellFacet kLineFacets[] = {{1, {0}}, {1, {1}}};
const CellFacet kTriFacets[] = {{2, {0, 1}}, {2, {1, 2}}, {2, {2, 0}}};
const CellFacet kQuadFacets[] = {{2, {0, 1}}, {2, {1, 2}}, {2, {2, 3}}, {2, {3, 0}}};
const CellFacet kTetFacets[] = {{3, {0, 2, 1}}, {3, {0, 1, 3}}, {3, {0, 3, 2}}, {3, {1, 2, 3}}};
// Gmsh's face order: hex27 places its mid-face nodes 20..25 in this order.
const CellFacet kHexFacets[] = {{4, {0, 3, 2, 1}}, {4, {0, 1, 5, 4}}, {4, {0, 4, 7, 3}},
                                {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {4, 5, 6, 7}}};
const CellFacet kWedgeFacets[] = {
    {3, {0, 2, 1}}, {3, {3, 4, 5}}, {4, {0, 1, 4, 3}}, {4, {1, 2, 5, 4}}, {4, {2, 0, 3, 5}}};
const CellFacet kPyramidFacets[] = {
    {4, {0, 3, 2, 1}}, {3, {0, 1, 4}}, {3, {1, 2, 4}}, {3, {2, 3, 4}}, {3, {3, 0, 4}}};

#define TMOP_N(a) static_cast<int>(sizeof(a) / sizeof(a[0])), a
const CellInfo kTable[kNumCellTypes] = {
    {"vertex", 0, 1, 1, 1, CellType::kVertex, 15, 0, nullptr, 0, nullptr},
    {"line2", 1, 2, 2, 1, CellType::kLine2, 1, TMOP_N(kLineEdges), TMOP_N(kLineFacets)},
    {"line3", 1, 3, 2, 2, CellType::kLine2, 8, TMOP_N(kLineEdges), TMOP_N(kLineFacets)},
    {"tri3", 2, 3, 3, 1, CellType::kTri3, 2, TMOP_N(kTriEdges), TMOP_N(kTriFacets)},
    {"quad4", 2, 4, 4, 1, CellType::kQuad4, 3, TMOP_N(kQuadEdges), TMOP_N(kQuadFacets)},
    {"tet4", 3, 4, 4, 1, CellType::kTet4, 4, TMOP_N(kTetEdges), TMOP_N(kTetFacets)},
    {"hex8", 3, 8, 8, 1, CellType::kHex8, 5, TMOP_N(kHexEdges), TMOP_N(kHexFacets)},
    {"wedge6", 3, 6, 6, 1, CellType::kWedge6, 6, TMOP_N(kWedgeEdges), TMOP_N(kWedgeFacets)},
    {"pyramid5", 3, 5, 5, 1, CellType::kPyramid5, 7, TMOP_N(kPyramidEdges), TMOP_N(kPyramidFacets)},
    {"tri6", 2, 6, 3, 2, CellType::kTri3, 9, TMOP_N(kTriEdges), TMOP_N(kTriFacets)},
    {"quad9", 2, 9, 4, 2, CellType::kQuad4, 10, TMOP_N(kQuadEdges), TMOP_N(kQuadFacets)},
    {"tet10", 3, 10, 4, 2, CellType::kTet4, 11, TMOP_N(kTetEdges), TMOP_N(kTetFacets)},
    {"hex27", 3, 27, 8, 2, CellType::kHex8, 12, TMOP_N(kHexEdges), TMOP_N(kHexFacets)},
};
#undef TMOP_N

}  // namespace

const CellInfo& cell_info(CellType type) { return kTable[static_cast<int>(type)]; }

bool cell_type_from_name(const std::string& name, CellType* type) {
  for (int i = 0; i < kNumCellTypes; ++i) {
    if (name == kTable[i].name) {
      *type = static_cast<CellType>(i);
      return true;
    }
  }
  return false;
}

bool cell_type_from_gmsh(int gmsh_type, CellType* type) {
  for (int i = 0; i < kNumCellTypes; ++i) {
    if (gmsh_type == kTable[i].gmsh_type) {
      *type = static_cast<CellType>(i);
      return true;
    }
  }
  return false;
}

}  // namespace tmop
