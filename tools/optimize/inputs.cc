// tools/optimize/inputs.cc: tmop_optimize's inputs, read and checked before any work.
#include "tools/optimize/inputs.h"

#include <csignal>
#include <cstdio>
#include <string>

#include "tmop/io/atomic_file.h"
#include "tmop/io/node_list.h"
#include "tmop/mesh/validate.h"
#include "tmop/target/composed_target.h"
#include "tools/optimize/flags.h"

namespace tmop_tools {

using namespace tmop;

int load_inputs(bool composed, RecipeOptions* o, Inputs* in) {
  Mesh& mesh = in->mesh;
  Status s = read_mesh(FLAGS_input, &mesh);
  // A signal while a child process read the input (mesh_io.h, isolated reads) ends that read.
  if (!s.ok() && cancel_signal() != 0) {
    std::fprintf(stderr,
                 "tmop_optimize: interrupted by %s while reading the input; nothing written\n",
                 cancel_signal() == SIGTERM ? "SIGTERM" : "SIGINT");
    return 130;
  }
  if (!s.ok()) return fail(2, s.message());
  s = validate_mesh(mesh);
  if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  // The output's format must hold this mesh: refuse now rather than after the optimization.
  // Node movement changes neither cell types nor connectivity, which is all the check needs.
  in->write.binary = FLAGS_binary;
  in->write.msh_version = FLAGS_msh_version == "2.2" ? 22 : 41;
  s = check_writable(FLAGS_output, mesh, in->write);
  if (!s.ok()) return fail(2, s.message());
  if (!FLAGS_fixed_nodes.empty()) {
    const std::string& f = FLAGS_fixed_nodes;
    s = f.compare(0, 6, "field:") == 0 ? node_flags_from_field(mesh, f.substr(6), &o->fixed)
                                       : read_node_list(f, mesh.num_vertices(), &o->fixed);
    if (!s.ok())
      return fail(2, f.compare(0, 6, "field:") == 0
                         ? FLAGS_input + ": --fixed_nodes: " + s.message()
                         : s.message());
  }
  if (!FLAGS_moved.empty()) {
    s = read_mesh(FLAGS_moved, &in->moved);
    if (!s.ok()) return fail(2, s.message());
    o->moved = &in->moved;
  }
  // The recipe must fit the mesh and a --geometry must be well formed, near the mesh and used:
  // usage errors, said before any work (recipe.h: check_recipe).
  s = check_recipe(FLAGS_recipe, mesh, *o);
  if (!s.ok())
    return fail(
        2, (s.message().compare(0, 7, "recipe ") == 0 ? FLAGS_input + ": " : "") + s.message());
  if (!FLAGS_reference.empty()) {
    s = read_mesh(FLAGS_reference, &in->reference);
    if (!s.ok()) return fail(2, s.message());
    // Checked before any work: a reference of another mesh is a usage error (exit 2).
    if (!reference_matches(mesh, in->reference))
      return fail(2, FLAGS_reference + ": its vertices and cells do not match those of " +
                         FLAGS_input + " (a reference mesh must have the same topology)");
    o->target.reference = &in->reference;
  }
  // A mesh written with the opposite orientation convention is not "all inverted": optimize it
  // in tmop's convention and write it back in its own. The boundary decides (orientation.h), so
  // a tangle of more than half the cells is still a tangle; --orientation states it instead.
  const OrientationReport& orientation = in->orientation = check_orientation(mesh);
  const bool flipped = in->flipped = FLAGS_orientation == "auto" ? orientation.opposite_convention()
                                                                 : FLAGS_orientation == "opposite";
  if (FLAGS_orientation == "auto" &&
      (flipped || 2 * orientation.negative > orientation.num_elements()))
    std::printf("note: %s: %s%s\n", FLAGS_input.c_str(), describe_orientation(orientation).c_str(),
                flipped ? ": handled" : ": the negative cells are inverted");
  else if (flipped)
    std::printf("note: %s: opposite convention (--orientation=opposite; %d of %d cells negative)\n",
                FLAGS_input.c_str(), orientation.negative, orientation.num_elements());
  if (flipped) {
    reorient(&mesh);
    if (o->target.reference) reorient(&in->reference);
    if (o->moved) reorient(&in->moved);
  }
  // Value counts, fields and the reference's topology are usage errors: say so before running.
  if (composed) {
    s = check_composed_target(mesh, o->target);
    if (!s.ok()) return fail(2, FLAGS_input + ": " + s.message());
  }
  return 0;
}

}  // namespace tmop_tools
