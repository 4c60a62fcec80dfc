// tmop/optimize/stage_spec.h
// What optimize_stage checks of a StageSpec before any work (stage.h's preconditions, each a
// one-line Status), the fixed vertices it resolves (the caller's, the geometry's fixed corners,
// else the boundary), and the command-line names of the solver settings.
#ifndef TMOP_OPTIMIZE_STAGE_SPEC_H_
#define TMOP_OPTIMIZE_STAGE_SPEC_H_

#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/stage.h"

namespace tmop {

// Ok when optimize_stage can run `spec` on `mesh`; else what is wrong.
Status check_stage_spec(const Mesh& mesh, const StageSpec& spec);

// One flag per vertex: spec.fixed, plus the fixed corners of spec.boundary, or the boundary
// when neither is given.
Status stage_fixed_vertices(const Mesh& mesh, const StageSpec& spec, std::vector<char>* fixed);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_STAGE_SPEC_H_
