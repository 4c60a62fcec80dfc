#include "tmop/io/vtk_common.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tmop {
namespace io {

bool is_tag_array(const std::string& name) { return name == kRegionArray || name == kEntityArray; }

bool extract_tag_arrays(Mesh* mesh, std::string* bad_name) {
  const std::size_t n = mesh->cell_types.size();
  mesh->cell_region.assign(n, 0);
  mesh->cell_entity.assign(n, 0);
  auto take = [&](const char* name, std::vector<std::int32_t>* dst) -> int {
    for (std::size_t i = 0; i < mesh->cell_data.size(); ++i) {
      const DataArray& a = mesh->cell_data[i];
      if (a.name != name) continue;
      if (a.components != 1 || a.values.size() != n) return -1;
      for (std::size_t c = 0; c < n; ++c) {
        const double v = a.values[c];
        if (v != std::floor(v) || std::fabs(v) > std::numeric_limits<std::int32_t>::max())
          return -1;
        (*dst)[c] = static_cast<std::int32_t>(v);
      }
      mesh->cell_data.erase(mesh->cell_data.begin() + static_cast<std::ptrdiff_t>(i));
      return 1;
    }
    return 0;
  };
  const char* region_names[] = {kRegionArray, "CellEntityIds", "medit:ref"};
  for (const char* name : region_names) {
    const int r = take(name, &mesh->cell_region);
    if (r < 0) {
      *bad_name = name;
      return false;
    }
    if (r > 0) break;
  }
  if (take(kEntityArray, &mesh->cell_entity) < 0) {
    *bad_name = kEntityArray;
    return false;
  }
  return true;
}

std::vector<DataArray> field_data_of_names(const Mesh& mesh) {
  std::vector<PhysicalName> names = mesh.physical_names;
  std::stable_sort(names.begin(), names.end(), [](const PhysicalName& a, const PhysicalName& b) {
    return a.dim != b.dim ? a.dim < b.dim : a.tag < b.tag;
  });
  std::vector<DataArray> out;
  for (const PhysicalName& p : names)
    out.push_back(DataArray{p.name, 1, {static_cast<double>(p.tag), static_cast<double>(p.dim)}});
  return out;
}

void names_from_field_data(const std::vector<DataArray>& field, Mesh* mesh) {
  for (const DataArray& a : field) {
    if (a.values.size() != 2 || a.name.empty()) continue;
    const double tag = a.values[0], dim = a.values[1];
    if (tag != std::floor(tag) || std::fabs(tag) > std::numeric_limits<std::int32_t>::max() ||
        !(dim == 0 || dim == 1 || dim == 2 || dim == 3))
      continue;
    mesh->set_physical_name(static_cast<int>(dim), static_cast<int>(tag), a.name);
  }
}

}  // namespace io
}  // namespace tmop
