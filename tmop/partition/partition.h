// tmop/partition/partition.h
// Partitions of a mesh's elements for partitioned stages (DESIGN.md section 12): METIS 5 k-way
// partitions of the element dual graph (elements adjacent when they share a facet: at least
// d corners), and the vertex sets a partition induces.
#ifndef TMOP_PARTITION_PARTITION_H_
#define TMOP_PARTITION_PARTITION_H_

#include <cstdint>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

// The elements (cells of the mesh's top dimension) touching each vertex, every node counted
// (mid-edge nodes of quadratic cells included), in increasing cell order.
struct VertexCells {
  std::vector<std::int64_t> offset;  // num_vertices + 1
  std::vector<std::int32_t> cell;
  int count(int v) const { return static_cast<int>(offset[v + 1] - offset[v]); }
  const std::int32_t* begin(int v) const { return cell.data() + offset[v]; }
  const std::int32_t* end(int v) const { return cell.data() + offset[v + 1]; }
};
VertexCells vertex_cells(const Mesh& mesh);

struct PartitionOptions {
  int num_parts = 1;
  // Per-element weight (the cost of its sample points), indexed by cell; empty: 1 each.
  const std::vector<int>* cell_weight = nullptr;
  // Vertices the cuts should avoid: dual-graph edges between two elements that share such a
  // corner weigh avoid_weight (the others 1), so METIS, which minimises the cut weight, puts
  // the flagged vertices inside parts. Empty: no preference.
  const std::vector<char>* avoid = nullptr;
  int avoid_weight = 50;
  int seed = 1;  // METIS's random seed: the same seed gives the same partition
};

// The element dual graph: elements (cells of the top dimension, in cell order) adjacent when
// they share d corners (a facet), in METIS's CSR form, each element's neighbours ascending.
// Built once, partitioned several times. `threads` workers take contiguous ranges of at least
// 4096 elements; the graph does not depend on their number.
struct ElementGraph {
  std::vector<int> element_cell;  // graph vertex -> cell
  std::vector<std::int32_t> xadj, adjncy;
};
Status element_graph(const Mesh& mesh, ElementGraph* graph, int threads = 1);

// part[c] in [0, num_parts) for every element c, -1 for the other cells (boundary facets).
// Fails (a one-line Status) when METIS does.
Status partition_elements(const Mesh& mesh, const ElementGraph& graph,
                          const PartitionOptions& options, std::vector<int>* part);

// Flags (1) the vertices whose elements lie in more than one part.
std::vector<char> cut_vertices(const Mesh& mesh, const VertexCells& vc,
                               const std::vector<int>& part);

}  // namespace tmop

#endif  // TMOP_PARTITION_PARTITION_H_
