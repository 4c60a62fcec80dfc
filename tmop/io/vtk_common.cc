#include "tmop/io/vtk_common.h"

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

}  // namespace io
}  // namespace tmop
