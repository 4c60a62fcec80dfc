#include "tmop/recipes/recipe_geometry.h"

namespace tmop {

Status build_recipe_geometry(const Mesh& mesh, const BoundaryOptions& options,
                             RecipeGeometry* out) {
  out->frame = normalizing_frame(mesh);
  if (!(out->frame.length > 0)) return Status::Failure("the mesh has no edge of positive length");
  Mesh mapped = mesh;
  to_frame(out->frame, &mapped);
  BoundaryOptions opt = options;
  for (int a = 0; a < 3; ++a) opt.geometry_frame.centre[a] = out->frame.centre[a];
  opt.geometry_frame.length = out->frame.length;
  for (int k = 0; k < 9; ++k) opt.geometry_frame.rotation[k] = out->frame.rotation[k];
  return BoundaryConstraints::Build(mapped, opt, &out->constraints);
}

Status resolve_recipe_geometry(const Mesh& mesh, bool slide, const BoundaryOptions& options,
                               const RecipeGeometry* given, RecipeGeometry* own,
                               const RecipeGeometry** out) {
  *out = given;
  if (given || !(slide || is_surface_mesh(mesh))) return Status::Ok();
  // The recipe's slide decides (BoundaryOptions::slide defaults to true, so or-ing it in made a
  // surface mesh's rim slide under a fixed boundary): a surface mesh's interior still slides on
  // its surface, its rim stays (boundary_constraints.h).
  BoundaryOptions b = options;
  b.slide = slide;
  Status s = build_recipe_geometry(mesh, b, own);
  if (s.ok()) *out = own;
  return s;
}

bool is_surface_mesh(const Mesh& mesh) { return mesh.dim() == 2 && mesh.space_dim == 3; }

}  // namespace tmop
