// tmop/recipes/laplace.h
// Smart Laplacian smoothing: the baseline that TMOP runs are compared against. Each free vertex
// moves to the centroid of its edge neighbours, but only when the move keeps every element
// around it valid and does not lower the worst shape quality among them; otherwise it stays.
// Vertices are visited in index order and each accepted move is used at once (Gauss-Seidel).
//
// Quality of an element here: the minimum over its sample points of q = d det(T)^(2/d) / |T|^2,
// T = A W^-1 with W the ideal element (the mean ratio for simplices; 1 = ideal, <= 0 inverted;
// the measure of the progress line, optimize/stage.h measure_mesh).
//
// Inputs: a mesh of linear elements (tri3, quad4, tet4, hex8, wedge6, pyramid5) in its own
// dimension; options. Output: the mesh moved in place; *result with one stage "laplace" whose
// `iterations` are the sweeps made.
// Guarantees: no element becomes inverted, and the worst quality around every vertex never
// decreases (so neither does the mesh's worst quality); an already inverted element is never made
// worse, though plain Laplacian smoothing cannot be relied on to repair it (use untangle).
// Failure: quadratic elements (their mid-edge nodes are not edge neighbours), surface meshes,
// wrong-sized `fixed`. The mesh is unchanged on failure.
#ifndef TMOP_RECIPES_LAPLACE_H_
#define TMOP_RECIPES_LAPLACE_H_

#include <vector>

#include "tmop/core/status.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/mesh.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct LaplaceOptions {
  // Sweeps over all free vertices at most. Default 100; smoothing converges slowly on large
  // meshes (information travels one ring per sweep), raise it for > 10^5 vertices.
  int max_sweeps = 100;

  // Stop when no vertex moved by more than this fraction of its mean incident edge length in a
  // sweep. Default 1e-6 (dimensionless, so results do not depend on the mesh's units).
  double tolerance = 1e-6;

  // Where element validity and quality are checked. Default kCorners: a linear element's
  // Jacobian is extreme at its corners (and constant on simplices).
  SampleRule rule = SampleRule::kCorners;

  // Per-vertex flags (1 = fixed), num_vertices() entries. Empty (default): the boundary is fixed.
  std::vector<char> fixed;
  // Boundary vertices move too, to their neighbours' centroid projected back onto their curve or
  // surface (geometry/boundary_constraints.h); corners stay. Volume and planar meshes.
  bool slide = false;
  BoundaryOptions boundary;
  // Called after every sweep with stage "laplace" (optimize/solver_options.h); returning false
  // stops after that sweep (the mesh is as the sweep left it: every move kept its cells valid)
  // and laplace returns Status::Cancelled.
  ProgressCallback progress;
};

Status laplace(Mesh* mesh, const LaplaceOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_LAPLACE_H_
