#include "tmop/mesh/mesh.h"

#include <algorithm>

namespace tmop {

int Mesh::add_vertex(const double* x) {
  coords.insert(coords.end(), x, x + space_dim);
  return num_vertices() - 1;
}

int Mesh::add_cell(CellType type, const std::int32_t* nodes, int region, int entity) {
  const int n = cell_num_nodes(type);
  cell_types.push_back(type);
  cell_nodes.insert(cell_nodes.end(), nodes, nodes + n);
  cell_offsets.push_back(static_cast<std::int64_t>(cell_nodes.size()));
  cell_region.push_back(region);
  cell_entity.push_back(entity);
  return num_cells() - 1;
}

int Mesh::dim() const {
  int d = 0;
  bool seen[kNumCellTypes] = {};
  for (CellType t : cell_types) seen[static_cast<int>(t)] = true;
  for (int i = 0; i < kNumCellTypes; ++i)
    if (seen[i]) d = std::max(d, cell_dim(static_cast<CellType>(i)));
  return d;
}

int Mesh::num_elements() const {
  const int d = dim();
  int n = 0;
  for (CellType t : cell_types) n += cell_dim(t) == d;
  return n;
}

std::vector<int> Mesh::count_by_type() const {
  std::vector<int> count(kNumCellTypes, 0);
  for (CellType t : cell_types) ++count[static_cast<int>(t)];
  return count;
}

const std::string* Mesh::physical_name(int dim, int tag) const {
  for (const PhysicalName& p : physical_names)
    if (p.dim == dim && p.tag == tag) return &p.name;
  return nullptr;
}

void Mesh::set_physical_name(int dim, int tag, const std::string& name) {
  for (PhysicalName& p : physical_names)
    if (p.dim == dim && p.tag == tag) {
      p.name = name;
      return;
    }
  physical_names.push_back({dim, tag, name});
}

void Mesh::clear() { *this = Mesh(); }

void Mesh::remove_lower_dimensional_cells() {
  const int d = dim();
  Mesh out;
  out.space_dim = space_dim;
  out.plane_z = plane_z;
  out.coords = std::move(coords);
  out.point_data = std::move(point_data);
  out.physical_names = std::move(physical_names);
  out.periodic = std::move(periodic);
  std::vector<bool> keep(num_cells());
  for (int c = 0; c < num_cells(); ++c) {
    keep[c] = cell_dim(cell_types[c]) == d;
    if (keep[c]) out.add_cell(cell_types[c], cell(c), cell_region[c], cell_entity[c]);
  }
  for (DataArray& a : cell_data) {
    DataArray b{a.name, a.components, {}};
    for (int c = 0; c < num_cells(); ++c)
      if (keep[c])
        b.values.insert(b.values.end(), a.values.begin() + std::size_t(c) * a.components,
                        a.values.begin() + std::size_t(c + 1) * a.components);
    out.cell_data.push_back(std::move(b));
  }
  *this = std::move(out);
}

void mark_periodic_vertices(const Mesh& mesh, std::vector<char>* flags) {
  const std::int32_t n = static_cast<std::int32_t>(flags->size());
  for (const PeriodicLink& link : mesh.periodic)
    for (const auto& pair : link.nodes)
      for (const std::int32_t v : {pair.first, pair.second})
        if (v >= 0 && v < n) (*flags)[v] = 1;
}

}  // namespace tmop
