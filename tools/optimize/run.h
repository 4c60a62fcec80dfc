// tools/optimize/run.h
// A tmop_optimize run on its inputs (run.cc): the recipe, the guarantees checked on the result,
// the output written, the report; progress lines and the one-line cancel message.
#ifndef TMOP_TOOLS_OPTIMIZE_RUN_H_
#define TMOP_TOOLS_OPTIMIZE_RUN_H_

#include "tmop/recipes/recipe.h"
#include "tools/optimize/inputs.h"

namespace tmop_tools {

// `user` wrapped so that the last stage and iteration reported are remembered (the cancel
// message names them). Safe to call from the workers of a partitioned stage.
tmop::ProgressCallback remembering_last_iteration(tmop::ProgressCallback user);

// The recipe on the inputs, the result checked, written and reported: the exit code (0, 1, 2,
// or 130 after SIGINT / SIGTERM).
int run(const tmop::RecipeOptions& o, Inputs* in);

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_OPTIMIZE_RUN_H_
