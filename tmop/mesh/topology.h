// tmop/mesh/topology.h
// Topology of a Mesh's elements (the cells with dimension == mesh.dim(); lower-dimensional
// boundary-tag cells are ignored): edges, boundary facets, boundary nodes, vertex -> cell lists.
//
// Inputs are assumed valid (validate_mesh); indices out of range are programmer errors here.
// Cost: O(N) or O(N log N) in the number of cells, no per-cell allocation; boundary_facets on
// 1M tets takes about 0.2 s, mesh_edges 0.15 s, vertex_to_cells 0.05 s (measured by
// tests/mesh/topology_test.cc, Release build).
#ifndef TMOP_MESH_TOPOLOGY_H_
#define TMOP_MESH_TOPOLOGY_H_

#include <array>
#include <cstdint>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

// Edges between corner vertices of the elements, each once as (a, b) with a < b, sorted
// lexicographically. Mid-edge nodes of quadratic cells are not endpoints of any edge.
std::vector<std::array<std::int32_t, 2>> mesh_edges(const Mesh& mesh);

// A facet (face of a 3D element, edge of a 2D element, end point of a 1D element) used by
// exactly one element. corners are global vertex indices in the cell table's outward order
// (cell_type.h), so the right-hand normal of a boundary facet points out of the mesh.
struct BoundaryFacet {
  std::int32_t cell;        // the element the facet belongs to
  std::int8_t local;        // facet index within cell_info(type).facets
  std::int8_t num_corners;  // 1, 2, 3 or 4
  std::int32_t corners[4];  // unused trailing entries are -1
};

// Ordered by (cell, local). Facets shared by two or more elements (including non-manifold ones)
// are interior.
std::vector<BoundaryFacet> boundary_facets(const Mesh& mesh);

// A facet shared by exactly two elements: the cells and their local facet indices.
struct InteriorFacet {
  std::int32_t cell[2];
  std::int8_t local[2];
};

// Ordered by the first side's (cell, local). Non-manifold facets (3+ elements) are in neither
// list.
std::vector<InteriorFacet> interior_facets(const Mesh& mesh);

// Whether two cells belong to the same region: equal cell_region (physical) and cell_entity
// (geometric entity) tags, 0 when a tag array is missing.
bool same_region(const Mesh& mesh, int a, int b);

// The interior facets between elements of different regions (material interfaces, CAD volumes
// meeting), in interior_facets order.
std::vector<InteriorFacet> region_interface_facets(const Mesh& mesh);

// num_vertices() entries: 1 for every node on a boundary facet or a region interface facet
// (both are boundaries of a region, and a fixed boundary keeps them), including the mid-edge
// nodes and (hex27) face nodes of quadratic cells that lie on that facet; 0 otherwise.
// The last mask is kept (thread-safe) with a 128-bit hash of the topology (cell types, offsets,
// nodes, regions, entities, vertex count) and returned again while that is unchanged; so is the
// last boundary_facets list.
std::vector<char> boundary_vertex_mask(const Mesh& mesh);

// Compressed rows: the cells of vertex v are items[offsets[v] .. offsets[v + 1]), ascending.
struct Adjacency {
  std::vector<std::int64_t> offsets;  // num_vertices() + 1
  std::vector<std::int32_t> items;
};

// For every vertex, the elements having it as one of their nodes (any node, quadratic ones too).
Adjacency vertex_to_cells(const Mesh& mesh);

}  // namespace tmop

#endif  // TMOP_MESH_TOPOLOGY_H_
