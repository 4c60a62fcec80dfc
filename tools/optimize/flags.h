// tools/optimize/flags.h
// tmop_optimize's command-line flags (defined in flags.cc, documented by --help) and their
// translation into the recipe registry's options: usage errors are found here, before any file
// is read.
#ifndef TMOP_TOOLS_OPTIMIZE_FLAGS_H_
#define TMOP_TOOLS_OPTIMIZE_FLAGS_H_

#include <gflags/gflags.h>

#include <string>

#include "tmop/recipes/recipe.h"

DECLARE_string(input);
DECLARE_string(output);
DECLARE_string(recipe);
DECLARE_string(fixed_nodes);
DECLARE_string(from_report);
DECLARE_bool(write_on_failure);
DECLARE_string(metric);
DECLARE_bool(list_metrics);
DECLARE_string(target);
DECLARE_string(reference);
DECLARE_string(target_size);
DECLARE_string(target_orientation);
DECLARE_string(target_shape);
DECLARE_string(target_skew);
DECLARE_string(target_aspect);
DECLARE_string(size_field);
DECLARE_string(sample_points);
DECLARE_double(power);
DECLARE_string(solver);
DECLARE_string(linear_solver);
DECLARE_int32(max_iterations);
DECLARE_double(max_seconds);
DECLARE_double(function_tolerance);
DECLARE_int32(threads);
DECLARE_int32(part_size);
DECLARE_string(partitions);
DECLARE_int32(part_sweeps);
DECLARE_double(part_first_tolerance);
DECLARE_int32(part_rings);
DECLARE_string(report);
DECLARE_bool(binary);
DECLARE_string(msh_version);
DECLARE_string(boundary);
DECLARE_string(geometry);
DECLARE_string(orientation);
DECLARE_double(feature_angle);
DECLARE_string(moved);
DECLARE_double(shape_guard_weight);
DECLARE_double(layer_edge_ratio);
DECLARE_int32(max_sweeps);
DECLARE_bool(verbose);
DECLARE_string(guarantee);

namespace tmop_tools {

// Prints the one-line error "tmop_optimize: MESSAGE" (the run's paths quoted) on stderr and
// returns `code`.
int fail(int code, const std::string& message);

// Usage errors of the flags alone, said before any file is read: 0, or the exit code.
int check_flags(int argc, char** argv);

// The registry's options from the flags (all but the files: fixed nodes, reference, moved):
// 0 or the exit code. *composed: --target=composed (its fields are checked on the mesh later).
int options_from_flags(tmop::RecipeOptions* o, bool* composed);

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_OPTIMIZE_FLAGS_H_
