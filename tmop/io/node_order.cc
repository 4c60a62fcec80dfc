#include "tmop/io/node_order.h"

#include <algorithm>
#include <string>

#include "tmop/core/status.h"

namespace tmop {
namespace io {
namespace {

const int kIdentity[kMaxCellNodes] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13,
                                      14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
const int kWedge6[6] = {0, 2, 1, 3, 5, 4};
const int kTet10[10] = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
const int kHex27[27] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  11, 13, 9,  16, 18,
                        19, 17, 10, 12, 14, 15, 22, 23, 21, 24, 20, 25, 26};
// hex20 is hex27 without its face and centre nodes: the same first 20 entries.
const int* const kHex20 = kHex27;
// VTK's wedges: the base triangle reversed (as wedge6), then edges bottom, top, vertical, then
// (wedge18) the quad faces.
const int kWedge15[15] = {0, 2, 1, 3, 5, 4, 7, 9, 6, 13, 14, 12, 8, 11, 10};
// VTK's pyramid13: base edges in cycle order 0-1 1-2 2-3 3-0, then 0-4 1-4 2-4 3-4.
const int kPyramid13[13] = {0, 1, 2, 3, 4, 5, 8, 10, 6, 7, 9, 11, 12};
const int kWedge18[18] = {0, 2, 1, 3, 5, 4, 7, 9, 6, 13, 14, 12, 8, 11, 10, 16, 17, 15};

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
    23,  // quad8: VTK_QUADRATIC_QUAD
    25,  // hex20: VTK_QUADRATIC_HEXAHEDRON
    26,  // wedge15: VTK_QUADRATIC_WEDGE
    32,  // wedge18: VTK_BIQUADRATIC_QUADRATIC_WEDGE
    27,  // pyramid13: VTK_QUADRATIC_PYRAMID
    -1,  // pyramid14: none (VTK's quadratic pyramids have 13 or 19 nodes)
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
    case CellType::kHex20:
      return kHex20;
    case CellType::kWedge15:
      return kWedge15;
    case CellType::kWedge18:
      return kWedge18;
    case CellType::kPyramid13:
      return kPyramid13;
    default:
      return kIdentity;
  }
}

namespace {

// The PATRAN edge orders of the types whose order differs from Gmsh's (node_order.h).
struct PatranEdges {
  CellType type;
  int num_edges;
  int edges[12][2];
};
const int kHexPatranEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                    {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
const int kWedgePatranEdges[9][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4},
                                     {2, 5}, {3, 4}, {4, 5}, {5, 3}};
const int kPyramidPatranEdges[8][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0},
                                       {0, 4}, {1, 4}, {2, 4}, {3, 4}};
const int kTetPatranEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

// The face (and centre) nodes after the edges, in each format's order: the corners of the face
// whose centre each position holds, {-1} for the cell's centre.
struct PatranFaces {
  CellType type;
  int first;  // position of the first face / centre node
  int num;
  int corners[7][4];
};
// Exodus II (the Sandia IOSS hex27 / wedge18 face tables): hex27's centre first, then its faces
// z- z+ x- x+ y- y+.
const PatranFaces kExodusFaces[] = {
    {CellType::kHex27,
     20,
     7,
     {{-1}, {0, 1, 2, 3}, {4, 5, 6, 7}, {0, 3, 4, 7}, {1, 2, 5, 6}, {0, 1, 4, 5}, {2, 3, 6, 7}}},
    {CellType::kWedge18, 15, 3, {{0, 1, 3, 4}, {1, 2, 4, 5}, {0, 2, 3, 5}}},
};
// CGNS SIDS: hex27's faces z- y- x+ y+ x- z+, then its centre; wedge18 as Exodus.
const PatranFaces kCgnsFaces[] = {
    {CellType::kHex27,
     20,
     7,
     {{0, 1, 2, 3}, {0, 1, 4, 5}, {1, 2, 5, 6}, {2, 3, 6, 7}, {0, 3, 4, 7}, {4, 5, 6, 7}, {-1}}},
    {CellType::kWedge18, 15, 3, {{0, 1, 3, 4}, {1, 2, 4, 5}, {0, 2, 3, 5}}},
};

bool same_corners(const CellFacet& f, const int (&c)[4]) {
  if (f.num_corners != 4) return false;
  for (int i = 0; i < 4; ++i)
    if (std::find(f.corners, f.corners + 4, c[i]) == f.corners + 4) return false;
  return true;
}

// perm[type][gmsh node] = the format's position, derived from the cell table's edges and facets
// so the two cannot disagree.
struct PatranPermutations {
  int perm[kNumCellTypes][kMaxCellNodes];
  void edges(CellType type, const int (*pe)[2], int num) {
    const CellInfo& info = cell_info(type);
    for (int e = 0; e < info.num_edges; ++e) {
      const int a = info.edges[e][0], b = info.edges[e][1];
      for (int k = 0; k < num; ++k)
        if ((pe[k][0] == a && pe[k][1] == b) || (pe[k][0] == b && pe[k][1] == a))
          perm[static_cast<int>(type)][info.num_corners + e] = info.num_corners + k;
    }
  }
  void faces(const PatranFaces& pf) {
    const CellInfo& info = cell_info(pf.type);
    int* p = perm[static_cast<int>(pf.type)];
    for (int k = 0; k < pf.num; ++k) {
      if (pf.corners[k][0] < 0) {  // the centre: Gmsh's last node
        p[info.num_nodes - 1] = pf.first + k;
        continue;
      }
      for (int f = 0; f < info.num_facets; ++f)
        if (facet_node(info, f) >= 0 && same_corners(info.facets[f], pf.corners[k]))
          p[facet_node(info, f)] = pf.first + k;
    }
  }
  explicit PatranPermutations(const PatranFaces* pf, int num_faces) {
    for (int t = 0; t < kNumCellTypes; ++t)
      for (int i = 0; i < kMaxCellNodes; ++i) perm[t][i] = i;
    edges(CellType::kTet10, kTetPatranEdges, 6);
    for (CellType t : {CellType::kHex20, CellType::kHex27}) edges(t, kHexPatranEdges, 12);
    for (CellType t : {CellType::kWedge15, CellType::kWedge18}) edges(t, kWedgePatranEdges, 9);
    for (CellType t : {CellType::kPyramid13, CellType::kPyramid14})
      edges(t, kPyramidPatranEdges, 8);
    for (int k = 0; k < num_faces; ++k) faces(pf[k]);
  }
};

}  // namespace

int patran_index_of_gmsh_node(CellType type, int i, PatranFormat format) {
  static const PatranPermutations exodus(kExodusFaces, 2), cgns(kCgnsFaces, 2);
  return (format == PatranFormat::kExodus ? exodus : cgns).perm[static_cast<int>(type)][i];
}

void check_vtk_cell_types(const Mesh& mesh, const char* format) {
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (vtk_cell_type(mesh.cell_types[c]) < 0)
      throw Error(std::string("cannot write ") + cell_name(mesh.cell_types[c]) + " cells to " +
                  format + " (VTK has no such cell type; cell " + std::to_string(c) +
                  " is the first)");
}

std::string unsupported_vtk_type_note(std::int64_t vtk_type) {
  const char* name = nullptr;
  switch (vtk_type) {
    case 2:
      name = "VTK_POLY_VERTEX";
      break;
    case 4:
      name = "VTK_POLY_LINE";
      break;
    case 6:
      name = "VTK_TRIANGLE_STRIP";
      break;
    case 7:
      name = "VTK_POLYGON";
      break;
    case 8:
      name = "VTK_PIXEL";
      break;
    case 11:
      name = "VTK_VOXEL";
      break;
    case 42:
      name = "VTK_POLYHEDRON";
      break;
    default:
      if (vtk_type >= 68 && vtk_type <= 74) name = "an arbitrary-order VTK Lagrange cell";
      if (vtk_type >= 75 && vtk_type <= 81) name = "an arbitrary-order VTK Bezier cell";
  }
  return std::string(" (") + (name ? std::string(name) + "; " : std::string()) + "tmop reads " +
         supported_cell_types() + ")";
}

}  // namespace io
}  // namespace tmop
