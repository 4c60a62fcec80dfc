// tmop/element/cell_type.h
// The table of cell types tmop knows. Node order is Gmsh's everywhere inside tmop (io/ converts
// other orders on read and write). For each type: reference dimension, node and corner counts,
// polynomial order, the corner-only (linear) type, the Gmsh element-type number, the edges (as
// pairs of local corner indices, in the order that quadratic types place their mid-edge nodes),
// and the facets (faces of 3D cells, edges of 2D cells) as local corner indices ordered so that
// the right-hand normal points out of the cell.
#ifndef TMOP_ELEMENT_CELL_TYPE_H_
#define TMOP_ELEMENT_CELL_TYPE_H_

#include <cstdint>
#include <string>

namespace tmop {

enum class CellType : std::uint8_t {
  kVertex,
  kLine2,
  kLine3,
  kTri3,
  kQuad4,
  kTet4,
  kHex8,
  kWedge6,
  kPyramid5,
  kTri6,
  kQuad9,
  kTet10,
  kHex27,
};
constexpr int kNumCellTypes = 13;
constexpr int kMaxCellNodes = 27;

struct CellFacet {
  int num_corners;  // 2 (edge of a 2D cell), 3 or 4
  int corners[4];   // local corner indices, outward right-hand order
};

struct CellInfo {
  const char* name;  // "tri3", "hex27": stable, used in reports and JSON keys
  int dim;           // reference dimension: 0, 1, 2 or 3
  int num_nodes;     // nodes of the cell
  int num_corners;   // vertex nodes (the first num_corners nodes)
  int order;         // 1 linear, 2 quadratic
  CellType linear;   // the type made of the corners only
  int gmsh_type;     // Gmsh element-type number
  int num_edges;
  const int (*edges)[2];
  int num_facets;
  const CellFacet* facets;
};

const CellInfo& cell_info(CellType type);
inline int cell_dim(CellType t) { return cell_info(t).dim; }
inline int cell_num_nodes(CellType t) { return cell_info(t).num_nodes; }
inline const char* cell_name(CellType t) { return cell_info(t).name; }

// Looks a type up by its table name ("tet10"); false when unknown.
bool cell_type_from_name(const std::string& name, CellType* type);
// Looks a type up by its Gmsh element-type number; false when tmop does not support it.
bool cell_type_from_gmsh(int gmsh_type, CellType* type);

}  // namespace tmop

#endif  // TMOP_ELEMENT_CELL_TYPE_H_
