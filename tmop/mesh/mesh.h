// tmop/mesh/mesh.h
// Mesh: vertex coordinates and typed cells, plain data.
//
// - coords holds num_vertices() * space_dim doubles, vertex-major (x0 y0 [z0] x1 y1 ...). The
//   optimizer uses this storage directly as its Ceres parameter blocks, so do not reallocate it
//   while a Problem built on the mesh is alive.
// - Cells are stored in compressed rows: the nodes of cell c are
//   cell_nodes[cell_offsets[c] .. cell_offsets[c + 1]), in Gmsh node order, 0-based.
// - A mesh may hold cells of several dimensions: the cells of the highest dimension are the
//   elements tmop optimizes; lower-dimensional cells (boundary lines / faces, points) carry the
//   tags of boundary regions and are kept so that files round-trip.
// - cell_region is the physical tag (Gmsh physical group, Medit reference, meshio
//   "gmsh:physical"); cell_entity the elementary / geometric entity tag. 0 means none.
// - point_data / cell_data are optional named fields written by the formats that can carry them
//   (.vtu, .vtk); quality tools put per-cell measures there.
// - physical_names names physical tags per dimension (Gmsh $PhysicalNames: (1, 3) "inlet"); a
//   cell's name is the one of (cell_dim(type), cell_region). Formats with names of their own map
//   them (docs/formats.md: Exodus block names, CGNS families, SU2 markers, VTK field data).
// - periodic holds Gmsh's periodic links ($Periodic): pairs of vertices that are images of each
//   other. The optimizer keeps every such vertex fixed, so periodicity cannot break.
#ifndef TMOP_MESH_MESH_H_
#define TMOP_MESH_MESH_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tmop/element/cell_type.h"

namespace tmop {

struct DataArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // num_items * components
};

struct PhysicalName {
  int dim = 0;  // 0..3: the dimension of the cells the tag is on
  int tag = 0;  // the cell_region value
  std::string name;
};

// One $Periodic link: the vertices of entity (dim, tag) are images of those of (dim, master_tag).
struct PeriodicLink {
  int dim = 0;
  int tag = 0;
  int master_tag = 0;
  std::vector<double> affine;  // 16 values (row-major 4x4 transform, master -> slave) or empty
  std::vector<std::pair<std::int32_t, std::int32_t>> nodes;  // (vertex, master vertex), 0-based
};

class Mesh {
 public:
  int space_dim = 3;  // 2 or 3
  // space_dim 2: the plane z = plane_z the mesh lies in. Readers store a planar 2D mesh (every z
  // the same) with space_dim 2 and its z here, and writers put it back, so a flat mesh at z = 5
  // is optimized as a 2D mesh and written at z = 5.
  double plane_z = 0;
  std::vector<double> coords;

  std::vector<CellType> cell_types;
  std::vector<std::int64_t> cell_offsets{0};
  std::vector<std::int32_t> cell_nodes;
  std::vector<std::int32_t> cell_region;
  std::vector<std::int32_t> cell_entity;

  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;

  std::vector<PhysicalName> physical_names;  // at most one per (dim, tag)
  std::vector<PeriodicLink> periodic;

  // The name of physical tag `tag` in dimension `dim`; nullptr when it has none.
  const std::string* physical_name(int dim, int tag) const;
  // Sets (or replaces) the name of (dim, tag).
  void set_physical_name(int dim, int tag, const std::string& name);

  int num_vertices() const { return static_cast<int>(coords.size() / space_dim); }
  int num_cells() const { return static_cast<int>(cell_types.size()); }

  double* vertex(int v) { return coords.data() + static_cast<std::size_t>(v) * space_dim; }
  const double* vertex(int v) const {
    return coords.data() + static_cast<std::size_t>(v) * space_dim;
  }
  int add_vertex(const double* x);  // space_dim values; returns the new index

  CellType cell_type(int c) const { return cell_types[c]; }
  int cell_size(int c) const { return static_cast<int>(cell_offsets[c + 1] - cell_offsets[c]); }
  const std::int32_t* cell(int c) const { return cell_nodes.data() + cell_offsets[c]; }
  std::int32_t* cell(int c) { return cell_nodes.data() + cell_offsets[c]; }
  // Appends a cell; nodes has cell_num_nodes(type) entries. Returns the new index.
  int add_cell(CellType type, const std::int32_t* nodes, int region = 0, int entity = 0);

  // Highest reference dimension among the cells (0 for a mesh without cells).
  int dim() const;
  // True when the cell is one of the elements to optimize (its dimension equals dim()).
  // O(cells) because of dim(): in loops, compute dim() once and use the two-argument form.
  bool is_element(int c) const { return is_element(c, dim()); }
  bool is_element(int c, int mesh_dim) const { return cell_dim(cell_types[c]) == mesh_dim; }
  // Number of element cells (cells of dimension dim()).
  int num_elements() const;
  // Number of cells of each type, indexed by static_cast<int>(CellType).
  std::vector<int> count_by_type() const;

  void clear();
  // Removes every cell whose dimension is below dim() (boundary tags); keeps the vertices.
  void remove_lower_dimensional_cells();
};

// Sets flags[v] = 1 for both vertices of every periodic pair of mesh.periodic (flags has one
// entry per vertex; out-of-range pairs are ignored). The optimizer's fixed-vertex rule.
void mark_periodic_vertices(const Mesh& mesh, std::vector<char>* flags);

}  // namespace tmop

#endif  // TMOP_MESH_MESH_H_
