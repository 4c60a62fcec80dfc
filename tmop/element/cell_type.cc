#include "tmop/element/cell_type.h"

#include <string>

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

// Face nodes: hex27's follow the facet order (20..25); wedge18's sit on the three quad faces in
// Gmsh's order (0-1-4-3, 0-2-5-3, 1-2-5-4); pyramid14's on its base.
const int kHex27FaceNodes[] = {20, 21, 22, 23, 24, 25};
const int kWedge18FaceNodes[] = {-1, -1, 15, 17, 16};
// pyramid14's base centre (facet 0, the quad).
const int kPyramid14FaceNodes[] = {13, -1, -1, -1, -1};

#define TMOP_N(a) static_cast<int>(sizeof(a) / sizeof(a[0])), a
const CellInfo kTable[kNumCellTypes] = {
    {"vertex", 0, 1, 1, 1, CellType::kVertex, 15, 0, nullptr, 0, nullptr, nullptr},
    {"line2", 1, 2, 2, 1, CellType::kLine2, 1, TMOP_N(kLineEdges), TMOP_N(kLineFacets), nullptr},
    {"line3", 1, 3, 2, 2, CellType::kLine2, 8, TMOP_N(kLineEdges), TMOP_N(kLineFacets), nullptr},
    {"tri3", 2, 3, 3, 1, CellType::kTri3, 2, TMOP_N(kTriEdges), TMOP_N(kTriFacets), nullptr},
    {"quad4", 2, 4, 4, 1, CellType::kQuad4, 3, TMOP_N(kQuadEdges), TMOP_N(kQuadFacets), nullptr},
    {"tet4", 3, 4, 4, 1, CellType::kTet4, 4, TMOP_N(kTetEdges), TMOP_N(kTetFacets), nullptr},
    {"hex8", 3, 8, 8, 1, CellType::kHex8, 5, TMOP_N(kHexEdges), TMOP_N(kHexFacets), nullptr},
    {"wedge6", 3, 6, 6, 1, CellType::kWedge6, 6, TMOP_N(kWedgeEdges), TMOP_N(kWedgeFacets),
     nullptr},
    {"pyramid5", 3, 5, 5, 1, CellType::kPyramid5, 7, TMOP_N(kPyramidEdges), TMOP_N(kPyramidFacets),
     nullptr},
    {"tri6", 2, 6, 3, 2, CellType::kTri3, 9, TMOP_N(kTriEdges), TMOP_N(kTriFacets), nullptr},
    {"quad9", 2, 9, 4, 2, CellType::kQuad4, 10, TMOP_N(kQuadEdges), TMOP_N(kQuadFacets), nullptr},
    {"tet10", 3, 10, 4, 2, CellType::kTet4, 11, TMOP_N(kTetEdges), TMOP_N(kTetFacets), nullptr},
    {"hex27", 3, 27, 8, 2, CellType::kHex8, 12, TMOP_N(kHexEdges), TMOP_N(kHexFacets),
     kHex27FaceNodes},
    {"quad8", 2, 8, 4, 2, CellType::kQuad4, 16, TMOP_N(kQuadEdges), TMOP_N(kQuadFacets), nullptr},
    {"hex20", 3, 20, 8, 2, CellType::kHex8, 17, TMOP_N(kHexEdges), TMOP_N(kHexFacets), nullptr},
    {"wedge15", 3, 15, 6, 2, CellType::kWedge6, 18, TMOP_N(kWedgeEdges), TMOP_N(kWedgeFacets),
     nullptr},
    {"wedge18", 3, 18, 6, 2, CellType::kWedge6, 13, TMOP_N(kWedgeEdges), TMOP_N(kWedgeFacets),
     kWedge18FaceNodes},
    {"pyramid13", 3, 13, 5, 2, CellType::kPyramid5, 19, TMOP_N(kPyramidEdges),
     TMOP_N(kPyramidFacets), nullptr},
    {"pyramid14", 3, 14, 5, 2, CellType::kPyramid5, 14, TMOP_N(kPyramidEdges),
     TMOP_N(kPyramidFacets), kPyramid14FaceNodes},
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

const std::string& supported_cell_types() {
  static const std::string list = [] {
    std::string out;
    for (int i = 0; i < kNumCellTypes; ++i) {
      if (i > 0) out += ", ";
      out += kTable[i].name;
    }
    return out;
  }();
  return list;
}

}  // namespace tmop
