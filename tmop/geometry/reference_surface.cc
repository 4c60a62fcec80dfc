#include "tmop/geometry/reference_surface.h"

#include <algorithm>
#include <cctype>

#include "tmop/element/cell_type.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

Status read_reference_surface(const std::string& path, std::vector<double>* vertices,
                              std::vector<std::int32_t>* triangles, SurfaceRepair* report) {
  vertices->clear();
  triangles->clear();
  const std::size_t dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != "stl" && ext != "obj" && ext != "off" && ext != "ply") {
    return Status::Failure(path + ": reference surfaces are .stl, .obj, .off or .ply files");
  }
  // tmop's own readers, with FILE:LINE errors on malformed or truncated files; as reference
  // geometry the surface may have degenerate facets (dropped) and polygons (split into fans).
  Mesh mesh;
  SurfaceRepair repair;
  Status s = read_mesh(path, &mesh, &repair);
  if (!s.ok()) return s;
  if (report) *report = repair;
  // Triangles over the vertices they use (a dropped facet may leave a vertex unused).
  std::vector<std::int32_t> index(mesh.num_vertices(), -1);
  const int sd = mesh.space_dim;  // 2 when the surface lies in z = 0: z = 0 then
  auto use = [&](std::int32_t v) {
    if (index[v] < 0) {
      index[v] = static_cast<std::int32_t>(vertices->size() / 3);
      const double* x = mesh.vertex(v);
      vertices->insert(vertices->end(), {x[0], sd > 1 ? x[1] : 0.0, sd > 2 ? x[2] : 0.0});
    }
    return index[v];
  };
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellInfo& info = cell_info(mesh.cell_type(c));
    if (info.dim != 2) continue;
    const std::int32_t* n = mesh.cell(c);
    for (int k = 1; k + 1 < info.num_corners; ++k) {  // a fan over the corners
      const std::int32_t a = use(n[0]), b = use(n[k]), d = use(n[k + 1]);
      triangles->insert(triangles->end(), {a, b, d});
    }
  }
  if (triangles->empty()) return Status::Failure(path + ": the surface has no faces");
  return Status::Ok();
}

}  // namespace tmop
