// tmop/io/node_list.h
// Per-vertex flags from a user's list of nodes: what `tmop_optimize --fixed_nodes` reads.
//
//   read_node_list: a text file of 0-based node indices separated by whitespace or newlines;
//     "#" starts a comment to the end of the line. Out: flags, num_vertices entries, 1 for every
//     listed node (a node may be listed twice). Failure, one line naming the place:
//     "FILE:LINE: 'x' is not a node index", "FILE:LINE: node 12 out of range 0..9",
//     "FILE: cannot open (reason)", "FILE: not a regular file (a directory)".
//   node_flags_from_field: a point-data array of the mesh; nonzero = flagged (any component).
//     Failure: no such array ("no point-data array 'NAME' (arrays: a, b)").
#ifndef TMOP_IO_NODE_LIST_H_
#define TMOP_IO_NODE_LIST_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

Status read_node_list(const std::string& path, int num_vertices, std::vector<char>* flags);
Status node_flags_from_field(const Mesh& mesh, const std::string& name, std::vector<char>* flags);

}  // namespace tmop

#endif  // TMOP_IO_NODE_LIST_H_
