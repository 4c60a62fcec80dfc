// tmop/recipes/untangle.h
// Untangling: make every element valid (det A > 0 at every sample point) by node movement, then
// (optionally) improve the shapes with a barrier stage from the valid mesh.
//
// Energy: the regularised-determinant energy of metric/untangle.h on T = A W^-1, with W the
// ideal shape of equal size (default) or the Jacobians of a reference mesh of the same topology
// ("untangle toward its shapes"); eps is lowered between Ceres solves from the current minimum
// of det T until nothing is inverted (optimize/stage.h, StageSpec::untangle).
//
// Result: Ok when the mesh is untangled (and improved). Failure when an inverted element has
// every node fixed (nothing can repair it: the message names the cells; the mesh is unchanged)
// or when inverted elements remain after the rounds allowed (the message names them, counted as
// tmop_quality counts them, and says when they have nodes on the fixed boundary; the mesh then
// holds the best state reached - never more inverted cells than the input - so a caller may
// still write it on request), or when a quadratic cell is proven inverted by its certificate
// after the certification rounds.
#ifndef TMOP_RECIPES_UNTANGLE_H_
#define TMOP_RECIPES_UNTANGLE_H_

#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop {

struct UntangleOptions {
  TargetSpec target;  // ideal shape, equal size by default; kReference to untangle toward a mesh
  SampleRule rule = SampleRule::kDefault;
  double theta = 0.5;        // weight of the size term of the untangling energy, in [0, 1]
  double initial_eps = 1.0;  // first regularisation (dimensionless, det T units)
  int max_rounds = 60;       // Ceres solves with decreasing eps
  int round_iterations =
      5;  // few: eps is lowered again right after (LIM armadillo: 40 -> 5 took 38 s -> 6 s)
  double sigma_min = 0.5;  // eps schedule's least relative decrease (StageSpec::untangle_sigma_min)
  int patience = 8;        // stop after this many rounds without a better state (StageSpec)
  int spread_rounds = 2;   // ... or this many that spread the tangle (StageSpec; 0: never)
  // After untangling, run the shape recipe (a barrier stage) from the valid mesh.
  bool improve_shape_after = true;
  ShapeOptions shape;  // options of that stage (its fixed flags are replaced by ours)
  // Quadratic simplices (tri6, tet10): after the stages, prove det J > 0 over each whole cell
  // with the Bernstein coefficients of det J (quality/jacobian_certificate.h). A cell that is not
  // proven valid gets extra sample points where its coefficients are <= 0 and the stages run
  // again, at most certify_rounds times. RecipeResult reports certified / uncertified cells.
  bool certify = true;
  int certify_rounds = 4;
  std::vector<char> fixed;  // per-vertex flags; empty = boundary fixed (or sliding, below)
  // Boundary vertices slide on their geometry during untangling and shape improvement (one
  // geometry built from the input serves both); surface meshes always do. See ShapeOptions.
  bool slide = false;
  BoundaryOptions boundary;
  const RecipeGeometry* geometry = nullptr;
  SolverOptions solver;
};

Status untangle(Mesh* mesh, const UntangleOptions& options, RecipeResult* result);

}  // namespace tmop

#endif  // TMOP_RECIPES_UNTANGLE_H_
