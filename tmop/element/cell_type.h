// tmop/element/cell_type.h
// The table of cell types tmop knows. Node order is Gmsh's everywhere inside tmop (io/ converts
// other orders on read and write). For each type: reference dimension, node and corner counts,
// polynomial order, the corner-only (linear) type, the Gmsh element-type number, the edges (as
// pairs of local corner indices, in the order that quadratic types place their mid-edge nodes),
// and the facets (faces of 3D cells, edges of 2D cells) as local corner indices ordered so that
// the right-hand normal points out of the cell.
// Families: Lagrange (tri6, quad9, tet10, hex27, wedge18 = tri6 x line3), serendipity (quad8,
// hex20, wedge15: corners and mid-edge nodes only) and the pyramids (pyramid5 / 13 / 14, rational
// bases). Every quadratic type places its mid-edge nodes right after the corners, in the order of
// `edges`, then its face nodes (facet_nodes), then a centre node if it has one.
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
  kQuad8,      // serendipity quad (Gmsh 16, VTK_QUADRATIC_QUAD)
  kHex20,      // serendipity hex (Gmsh 17, VTK_QUADRATIC_HEXAHEDRON)
  kWedge15,    // serendipity wedge (Gmsh 18, VTK_QUADRATIC_WEDGE)
  kWedge18,    // Lagrange wedge tri6 x line3 (Gmsh 13, VTK_BIQUADRATIC_QUADRATIC_WEDGE)
  kPyramid13,  // serendipity pyramid: corners and mid-edge nodes (Gmsh 19, VTK_QUADRATIC_PYRAMID)
  kPyramid14,  // Lagrange pyramid: pyramid13 and the base centre (Gmsh 14; no VTK type)
};
constexpr int kNumCellTypes = 19;
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
  // Local node index of the node at the centre of each facet (num_facets entries, -1 where the
  // facet has none), or nullptr when the type has no face nodes (hex27, wedge18, pyramid14 have
  // them).
  const int* facet_nodes;
};

// The facet node of facet `f` of `info`, -1 when there is none.
inline int facet_node(const CellInfo& info, int f) {
  return info.facet_nodes ? info.facet_nodes[f] : -1;
}

const CellInfo& cell_info(CellType type);
inline int cell_dim(CellType t) { return cell_info(t).dim; }
inline int cell_num_nodes(CellType t) { return cell_info(t).num_nodes; }
inline const char* cell_name(CellType t) { return cell_info(t).name; }

// Looks a type up by its table name ("tet10"); false when unknown.
bool cell_type_from_name(const std::string& name, CellType* type);
// Looks a type up by its Gmsh element-type number; false when tmop does not support it.
bool cell_type_from_gmsh(int gmsh_type, CellType* type);

// "tri3, quad4, ..." : every supported cell type's table name, for messages that refuse a type.
const std::string& supported_cell_types();

}  // namespace tmop

#endif  // TMOP_ELEMENT_CELL_TYPE_H_
