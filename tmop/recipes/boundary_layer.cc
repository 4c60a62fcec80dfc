#include "tmop/recipes/boundary_layer.h"

#include <cmath>

#include "tmop/mesh/topology.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/element_scan.h"

namespace tmop {

std::vector<char> find_boundary_layer(const Mesh& mesh, const BoundaryLayerOptions& options,
                                      const std::vector<char>* candidate) {
  const int num_cells = mesh.num_cells();
  std::vector<char> layer(num_cells, 0);
  if (!(options.edge_ratio > 0)) return layer;
  const int d = mesh.dim();
  const double z_up[3] = {0, 0, 1};
  const double* up = is_planar_2d(mesh) ? z_up : nullptr;
  QualityOptions qo;
  double nodes[kMaxCellNodes * 3];
  bool any = false;
  for (int cell = 0; cell < num_cells; ++cell) {
    if (!mesh.is_element(cell, d)) continue;
    if (candidate && !(*candidate)[cell]) continue;
    const CellType t = mesh.cell_type(cell);
    const CellType linear = cell_info(t).linear;
    const bool simplex = linear == CellType::kTet4 || linear == CellType::kTri3;
    if (options.simplices_only && !simplex) continue;
    for (int i = 0; i < mesh.cell_size(cell); ++i)
      for (int a = 0; a < 3; ++a)
        nodes[3 * i + a] = a < mesh.space_dim ? mesh.vertex(mesh.cell(cell)[i])[a] : 0.0;
    const CellQuality q = cell_quality(t, nodes, up, qo);
    double widest = linear == CellType::kTet4 ? q.max_dihedral_deg : q.max_angle_deg;
    if (std::isnan(widest)) widest = 0;  // types without the angle: no such limit
    layer[cell] = !q.inverted && widest < options.max_angle_deg &&
                  q.max_edge_length >= options.edge_ratio * q.min_edge_length;
    any = any || layer[cell];
  }
  if (!any) return layer;
  // Groups through shared facets (union-find), kept when large enough and on the boundary.
  std::vector<int> root(num_cells);
  for (int c = 0; c < num_cells; ++c) root[c] = c;
  auto find = [&root](int c) {
    while (root[c] != c) c = root[c] = root[root[c]];
    return c;
  };
  for (const InteriorFacet& f : interior_facets(mesh))
    if (layer[f.cell[0]] && layer[f.cell[1]]) root[find(f.cell[0])] = find(f.cell[1]);
  std::vector<int> size(num_cells, 0);
  std::vector<char> on_boundary(num_cells, !options.require_boundary);
  for (int c = 0; c < num_cells; ++c) size[find(c)] += layer[c];
  if (options.require_boundary)
    for (const BoundaryFacet& f : boundary_facets(mesh))
      if (layer[f.cell]) on_boundary[find(f.cell)] = 1;
  for (int c = 0; c < num_cells; ++c)
    layer[c] = layer[c] && size[find(c)] >= options.min_cells && on_boundary[find(c)];
  return layer;
}

}  // namespace tmop
