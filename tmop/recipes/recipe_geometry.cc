#include "tmop/recipes/recipe_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "tmop/geometry/boundary_classification.h"
#include "tmop/geometry/geometry_source.h"

namespace tmop {

Status check_geometry_spec(const Mesh& mesh, const BoundaryOptions& options) {
  if (options.geometry.empty()) return Status::Ok();
  GeometrySource source;
  Status s = load_geometry_source(options.geometry, &source);
  if (!s.ok()) return s;
  const std::string name = "geometry '" + options.geometry + "'";
  if (mesh.space_dim != 3 || mesh.dim() < 2)
    return Status::Failure(name + ": a " + std::to_string(mesh.space_dim) +
                           "D mesh has no surfaces to slide on");
  const bool surface = is_surface_mesh(mesh);
  if (!surface && !options.slide)
    return Status::Failure(
        name +
        " would be unused: the boundary is fixed and only sliding boundary vertices use "
        "a geometry");
  // The boundary facets (a surface mesh's cells), split into triangles as BoundaryConstraints
  // sees them; the geometry's distance from the mesh is that of the facet nearest to lying on
  // it (the largest distance of its vertices), so a sphere that merely cuts the mesh through a
  // few vertices is still far from it.
  ClassifyOptions classify;
  classify.feature_angle_deg = options.feature_angle_deg;
  classify.boundary_tags = options.boundary_tags;
  BoundaryClassification c;
  s = classify_boundary(mesh, classify, &c);
  if (!s.ok()) return s;
  double lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  std::vector<double> distance(mesh.num_vertices(), -1);
  double edge_sum = 0, nearest = std::numeric_limits<double>::infinity();
  long edges = 0;
  for (const BoundaryPatch& patch : c.patches) {
    for (const auto& t : patch.triangles) {
      double facet = 0;
      for (int k = 0; k < 3; ++k) {
        const double* x = mesh.vertex(t[k]);
        double& d = distance[t[k]];
        if (d < 0) {
          d = source.surface->Distance(x);
          for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], x[a]);
            hi[a] = std::max(hi[a], x[a]);
          }
        }
        facet = std::max(facet, d);
        const double* y = mesh.vertex(t[(k + 1) % 3]);
        edge_sum += std::sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                              (x[2] - y[2]) * (x[2] - y[2]));
        ++edges;
      }
      nearest = std::min(nearest, facet);
    }
  }
  if (edges == 0) return Status::Failure(name + ": the mesh has no boundary facets");
  double diagonal = 0;
  for (int a = 0; a < 3; ++a) diagonal += (hi[a] - lo[a]) * (hi[a] - lo[a]);
  diagonal = std::sqrt(diagonal);
  // The smaller of the documented relative tolerance and the one by which BoundaryConstraints
  // lets vertices take the geometry: passing means some facet will use it.
  const double tolerance =
      std::min(kGeometryTolerance * diagonal, options.on_geometry_tolerance * edge_sum / edges);
  if (!(nearest <= tolerance)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  " is %.4g from the mesh (the boundary facet nearest to lying on it has a vertex "
                  "that far; tolerance %.3g)",
                  nearest, tolerance);
    return Status::Failure(name + text);
  }
  return Status::Ok();
}

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
