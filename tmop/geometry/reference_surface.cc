// GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's VectorT<double> copies when its
// templates are instantiated here; the warning is about OpenMesh's code, not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "tmop/geometry/reference_surface.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <algorithm>
#include <cctype>
#include <fstream>

namespace tmop {
namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> SurfaceMesh;

}  // namespace

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
  if (!std::ifstream(path).good()) return Status::Failure(path + ": cannot open the file");
  SurfaceMesh mesh;
  OpenMesh::IO::Options options;
  if (!OpenMesh::IO::read_mesh(mesh, path, options)) {
    return Status::Failure(path + ": OpenMesh could not read this surface");
  }
  vertices->reserve(3 * mesh.n_vertices());
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    vertices->insert(vertices->end(), {p[0], p[1], p[2]});
  }
  for (const auto fh : mesh.faces()) {
    std::int32_t first = -1, prev = -1;
    for (const auto vh : mesh.fv_range(fh)) {
      const std::int32_t v = vh.idx();
      if (first < 0) {
        first = v;
      } else if (prev != first) {
        triangles->insert(triangles->end(), {first, prev, v});
      }
      prev = v;
    }
  }
  if (triangles->empty()) return Status::Failure(path + ": the surface has no faces");
  return Status::Ok();
}

}  // namespace tmop
