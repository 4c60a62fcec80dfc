// tmop/recipes/recipe_result.h
// What a recipe did: its stages in order, and the mesh's measures before and after (the same
// measure as the progress line: worst shape quality over sample points and inverted count).
#ifndef TMOP_RECIPES_RECIPE_RESULT_H_
#define TMOP_RECIPES_RECIPE_RESULT_H_

#include <string>
#include <vector>

#include "tmop/optimize/stage.h"

namespace tmop {

struct RecipeResult {
  std::string recipe;
  std::vector<StageResult> stages;
  IterationRecord before, after;
  double seconds = 0;
  // Quadratic simplices: cells proven valid everywhere by the Bernstein certificate, and those
  // not proven (-1 when no certificate was attempted).
  int certified = -1, uncertified = -1;
  std::vector<int> uncertified_cells;
  // Recipe sliver: boundary-layer cells found and the vertices held on the layer's outer
  // surface (-1 for other recipes).
  int layer_cells = -1, held_vertices = -1;
  // The guarantee guard (guard.h): cells held at their input shape in the last guard round
  // (0 when nothing had to be held; -1 when no guard ran).
  int guard_held_cells = -1;
};

// JSON object (no trailing newline) with stable keys, numbers printed with %.17g:
// {"recipe", "seconds", "before": {"min_quality", "min_quality_measure", "inverted"},
//  "after": {...},  (min_quality_measure is "sample_mean_ratio": min_quality is the worst mean
//  ratio d det(T)^(2/d) / |T|^2 of T = A W^-1, W the ideal element, over the sample points of
//  the rule, negative where det T < 0; tmop_quality's mean_ratio for linear simplices)
//  "certified", "uncertified" (null when not attempted),
//  "layer_cells", "held_vertices" (recipes sliver, shape: boundary layer; null otherwise),
//  "guard_held_cells" (the guarantee guard: cells held in its last round; null without guard),
//  "stages": [{"name", "linear_solver", "elements", "sample_points", "free_vertices",
//   "initial_objective", "final_objective", "iterations", "solves", "parts" (0: one problem),
//   "sweeps", "element_iterations" (elements x LM iterations, summed over the parts),
//   "termination", "seconds",
//   "inverted_before", "inverted_after", "min_quality_before", "min_quality_after",
//   "history": [{"iteration", "objective", "solver_objective", "min_quality", "inverted",
//                "seconds"}]}]}  (IterationRecord: objective, min_quality and inverted are null
//   unless the progress was reported, e.g. --verbose)
std::string recipe_json(const RecipeResult& result);

// Escapes a string for JSON (quotes included).
std::string json_string(const std::string& s);
// %.17g, or null for non-finite values (JSON has no inf/nan).
std::string json_number(double v);

}  // namespace tmop

#endif  // TMOP_RECIPES_RECIPE_RESULT_H_
