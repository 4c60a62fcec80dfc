#include "tmop/geometry/reference_surface.h"

#include <algorithm>
#include <cctype>

#include "tmop/element/cell_type.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

Status read_reference_surface(const std::string& path, std::vector<double>* vertices,
                              std::vector<std::int32_t>* triangles) {
  vertices->clear();
  triangles->clear();
  const std::size_t dot = path.rfind('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != "stl" && ext != "obj" && ext != "off" && ext != "ply") {
    return Status::Failure(path + ": reference surfaces are .stl, .obj, .off or .ply files");
  }
  // tmop's own readers: strict, with FILE:LINE errors on malformed or truncated files.
  Mesh mesh;
  Status s = read_mesh(path, &mesh);
  if (!s.ok()) return s;
  const int sd = mesh.space_dim;  // 2 when every z is 0 (a planar surface): z = 0 then
  vertices->reserve(3 * static_cast<std::size_t>(mesh.num_vertices()));
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double* x = mesh.vertex(v);
    vertices->insert(vertices->end(), {x[0], sd > 1 ? x[1] : 0.0, sd > 2 ? x[2] : 0.0});
  }
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellInfo& info = cell_info(mesh.cell_type(c));
    if (info.dim != 2) continue;
    const std::int32_t* n = mesh.cell(c);
    for (int k = 1; k + 1 < info.num_corners; ++k)  // a fan over the corners
      triangles->insert(triangles->end(), {n[0], n[k], n[k + 1]});
  }
  if (triangles->empty()) return Status::Failure(path + ": the surface has no faces");
  return Status::Ok();
}

}  // namespace tmop
