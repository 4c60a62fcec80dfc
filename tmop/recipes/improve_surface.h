// tmop/recipes/improve_surface.h
// The surface recipe on an OpenMesh mesh, in place, for geometry pipelines that hold their
// surfaces as OpenMesh::TriMesh / PolyMesh: no file round trip.
//
//   OMMesh: any OpenMesh mesh type (TriMesh_ArrayKernelT<Traits>, PolyMesh_ArrayKernelT<Traits>)
//           whose faces are triangles or quads. Points are read and written through
//           OMMesh::Point, so a float kernel (OpenMesh's default Vec3f) keeps ~1e-7 relative
//           precision on the geometry; use a Traits with `typedef OpenMesh::Vec3d Point;` for
//           full double precision.
//   geometry: "" (slide on the mesh's own surface), "sphere:cx,cy,cz,r", "plane:...",
//           "cylinder:...", or a surface file (geometry/geometry_source.h).
//   options: the untangle recipe's options (slide and boundary.geometry are set here; open
//           surfaces keep their corners and slide their boundary curves).
// Fails (mesh unchanged) on faces that are not triangles or quads, an empty mesh, a bad geometry,
// or when the recipe fails.
#ifndef TMOP_RECIPES_IMPROVE_SURFACE_H_
#define TMOP_RECIPES_IMPROVE_SURFACE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/recipes/untangle.h"

namespace tmop {

template <class OMMesh>
Status improve_surface(OMMesh* om, const std::string& geometry, const UntangleOptions& options,
                       RecipeResult* result) {
  Mesh mesh;
  mesh.space_dim = 3;
  for (auto vh : om->vertices()) {
    const auto& p = om->point(vh);
    const double x[3] = {double(p[0]), double(p[1]), double(p[2])};
    mesh.add_vertex(x);
  }
  for (auto fh : om->faces()) {
    std::int32_t nodes[4];
    int n = 0;
    for (auto vh : om->fv_range(fh)) {
      if (n == 4) return Status::Failure("improve_surface: a face with more than 4 vertices");
      nodes[n++] = vh.idx();
    }
    if (n < 3) return Status::Failure("improve_surface: a face with fewer than 3 vertices");
    mesh.add_cell(n == 3 ? CellType::kTri3 : CellType::kQuad4, nodes);
  }
  if (mesh.num_cells() == 0) return Status::Failure("improve_surface: the mesh has no faces");
  UntangleOptions opt = options;
  opt.slide = true;
  opt.boundary.geometry = geometry;
  Status s = untangle(&mesh, opt, result);
  if (!s.ok()) return s;
  result->recipe = "surface";
  for (auto vh : om->vertices()) {
    const double* x = mesh.vertex(vh.idx());
    typename OMMesh::Point p;
    for (int a = 0; a < 3; ++a) p[a] = static_cast<typename OMMesh::Point::value_type>(x[a]);
    om->set_point(vh, p);
  }
  return Status::Ok();
}

}  // namespace tmop

#endif  // TMOP_RECIPES_IMPROVE_SURFACE_H_
