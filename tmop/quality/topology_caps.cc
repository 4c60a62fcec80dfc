#include "tmop/quality/topology_caps.h"

#include <algorithm>
#include <limits>

#include "tmop/mesh/topology.h"

namespace tmop {

void topology_caps(const Mesh& mesh, QualityReport* r) {
  const int d = mesh.dim();
  r->all_boundary.assign(mesh.num_cells(), std::numeric_limits<double>::quiet_NaN());
  if (d < 2) return;
  const std::vector<char> boundary = boundary_vertex_mask(mesh);
  // Valence is a property of corner vertices: a mid-edge node of a quadratic cell has 1 or 2
  // incident elements by construction and says nothing about the topology.
  std::vector<char> corner(mesh.num_vertices(), 0);
  bool all_tri = true, all_quad = true;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    const CellType linear = cell_info(mesh.cell_type(c)).linear;
    all_tri &= linear == CellType::kTri3;
    all_quad &= linear == CellType::kQuad4;
    const CellInfo& info = cell_info(mesh.cell_type(c));
    bool on_boundary = true;
    for (int i = 0; i < info.num_corners; ++i) {
      on_boundary &= boundary[mesh.cell(c)[i]] != 0;
      corner[mesh.cell(c)[i]] = 1;
    }
    r->all_boundary[c] = on_boundary ? 1.0 : 0.0;
    if (!on_boundary) continue;
    ++r->cells_all_boundary;
    if (r->cells_all_boundary_examples.size() < 20) r->cells_all_boundary_examples.push_back(c);
  }
  if (d != 2 || !(all_tri || all_quad)) return;
  const Adjacency adj = vertex_to_cells(mesh);
  const int low = all_tri ? 3 : 2, high = all_tri ? 9 : 6;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const std::int64_t valence = adj.offsets[v + 1] - adj.offsets[v];
    if (boundary[v] || !corner[v]) continue;
    r->max_valence = std::max(r->max_valence, valence);
    if (valence > low && valence < high) continue;
    ++r->capped_valence_vertices;
    if (r->capped_valence_examples.size() < 20) r->capped_valence_examples.push_back(v);
  }
}

}  // namespace tmop
