// tools/optimize/inputs.h
// What a tmop_optimize run reads, read and checked before any work (inputs.cc).
#ifndef TMOP_TOOLS_OPTIMIZE_INPUTS_H_
#define TMOP_TOOLS_OPTIMIZE_INPUTS_H_

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"
#include "tmop/mesh/orientation.h"
#include "tmop/recipes/recipe.h"

namespace tmop_tools {

// What the run reads: the mesh (in tmop's convention), the reference and moved meshes.
struct Inputs {
  tmop::Mesh mesh, reference, moved;
  tmop::WriteOptions write;
  tmop::OrientationReport orientation;
  bool flipped = false;
  // This process writes the output and the report (under mpirun: rank 0 only).
  bool writes = true;
  // A .pvtu output of a distributed run: this process writes piece `piece` of `pieces` (one per
  // rank), the writing one also the index.
  int piece = 0, pieces = 1;
};

// Reads the mesh, the fixed nodes, the moved and reference meshes; checks that the output format
// holds the mesh, that the recipe fits it and that the reference matches it; decides the
// orientation convention (the mesh is then in tmop's). 0 or the exit code. composed:
// --target=composed (its fields are checked on the mesh here).
int load_inputs(bool composed, tmop::RecipeOptions* o, Inputs* in);

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_OPTIMIZE_INPUTS_H_
