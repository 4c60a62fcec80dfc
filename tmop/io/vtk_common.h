// tmop/io/vtk_common.h
// What the two VTK formats (.vtk legacy, .vtu XML) share: turning the cell-data arrays that
// carry tags back into Mesh::cell_region / cell_entity, and the names used when writing them.
// Tag arrays (read and written as cell data, Int32):
//   "gmsh:physical"    <-> cell_region   (meshio's name, so meshio maps it back to Gmsh tags)
//   "gmsh:geometrical" <-> cell_entity
// Physical names (Mesh::physical_names) as meshio keeps Gmsh's: dataset-level field data, one
// integer array per name, named by it, holding [tag, dim] (2 tuples of 1 component).
// Also accepted on read as cell_region when "gmsh:physical" is absent: "CellEntityIds" (what Gmsh
// writes into .vtk files) and "medit:ref" (meshio's Medit reference).
#ifndef TMOP_IO_VTK_COMMON_H_
#define TMOP_IO_VTK_COMMON_H_

#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

constexpr const char* kRegionArray = "gmsh:physical";
constexpr const char* kEntityArray = "gmsh:geometrical";

// Moves the tag arrays out of mesh->cell_data. Returns false with *bad_name set when a tag array
// has more than one component or non-integer values.
bool extract_tag_arrays(Mesh* mesh, std::string* bad_name);

// True for names the writers produce themselves from cell_region / cell_entity (so a cell_data
// array with such a name is not written twice).
bool is_tag_array(const std::string& name);

// The field-data arrays of mesh's physical names ([tag, dim] each), in (dim, tag) order.
std::vector<DataArray> field_data_of_names(const Mesh& mesh);
// Physical names from field-data arrays: every array of exactly two integers [tag, dim] with dim
// in 0..3 names (dim, tag); other arrays are ignored.
void names_from_field_data(const std::vector<DataArray>& field, Mesh* mesh);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_VTK_COMMON_H_
