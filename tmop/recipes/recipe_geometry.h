// tmop/recipes/recipe_geometry.h
// The boundary geometry of one recipe run, built once from the input mesh so that every stage
// (untangle, then shape, ...) slides on the same curves and surfaces: rebuilding it from the
// moved boundary between stages would let the boundary drift.
//
// The constraints are built on the mesh mapped into its normalising frame (optimize/stage.h),
// the coordinates every stage solves in; user geometry strings ("sphere:0,0,0,1", a surface
// file) are given in the mesh's own units and mapped the same way.
#ifndef TMOP_RECIPES_RECIPE_GEOMETRY_H_
#define TMOP_RECIPES_RECIPE_GEOMETRY_H_

#include <memory>
#include <string>

#include "tmop/core/status.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"

namespace tmop {

struct RecipeGeometry {
  CoordinateFrame frame;
  std::unique_ptr<BoundaryConstraints> constraints;
  // Sets a stage's boundary and frame.
  void apply(StageSpec* stage) const {
    stage->boundary = constraints.get();
    stage->frame = frame;
  }
};

// Fails (one line) on a bad geometry string or file, or a mesh whose boundary cannot be
// classified.
Status build_recipe_geometry(const Mesh& mesh, const BoundaryOptions& options, RecipeGeometry* out);

// The geometry a recipe runs with: `given` when set; else one built into *own when the recipe
// slides or the mesh is a surface mesh (which always needs its geometry); else none (*out =
// nullptr: the boundary is fixed).
Status resolve_recipe_geometry(const Mesh& mesh, bool slide, const BoundaryOptions& options,
                               const RecipeGeometry* given, RecipeGeometry* own,
                               const RecipeGeometry** out);

// Checks a user geometry (options.geometry; "" is always fine) against the mesh before any work,
// in the mesh's own units. Failure, one line: a malformed spec or unreadable / unusable surface
// file (load_geometry_source's message); a geometry on a 2D mesh (no surfaces to slide on); a
// geometry far from the mesh, with the distance in the message: no boundary facet (a surface
// mesh's cell, a volume mesh's boundary face; split into triangles) has all its vertices within
// the tolerance, the smaller of kGeometryTolerance x the boundary's bounding-box diagonal and
// options.on_geometry_tolerance x the mean boundary edge (the tolerance by which
// BoundaryConstraints lets vertices take the geometry), and the distance is the largest vertex
// distance of the facet nearest to lying on it; a geometry that would be unused because
// options.slide is false on a volume mesh (a fixed boundary; surface meshes always slide on
// their surface).
Status check_geometry_spec(const Mesh& mesh, const BoundaryOptions& options);
constexpr double kGeometryTolerance = 1e-3;

// True for a surface mesh (2D elements in 3D space): such meshes always need a geometry.
bool is_surface_mesh(const Mesh& mesh);

}  // namespace tmop

#endif  // TMOP_RECIPES_RECIPE_GEOMETRY_H_
