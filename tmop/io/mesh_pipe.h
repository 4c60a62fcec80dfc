// tmop/io/mesh_pipe.h
// A compact binary form of a whole tmop::Mesh over a file descriptor (a pipe), for the isolated
// read (isolated_read.h): the child process that parsed the file sends the mesh or the reader's
// error, the parent receives it. Internal to io/. Both ends are one build of tmop on one machine,
// so numbers travel in native byte order.
//
// Stream: the 8 bytes "TMOPPIP1", a kind byte, its payload, the 4 bytes "END1", then end of file.
//   'M' a mesh: space_dim, plane_z, coords, cell_types, cell_offsets, cell_nodes, cell_region,
//       cell_entity, point_data, cell_data (name, components, values each), physical_names (dim,
//       tag, name), periodic (dim, tag, master_tag, affine, node pairs): EVERY field of Mesh
//       (a static_assert on sizeof(Mesh) in mesh_pipe.cc fails when a field is added, so that it
//       is added here too). Arrays are a 64-bit count and the elements.
//   'E' a tmop::Error's message, 'A' std::bad_alloc, 'X' any other std::exception's what().
// send_*: the sender writes large arrays straight from the mesh's memory (no copy of the mesh);
//   returns false when the pipe fails (the parent is gone).
// receive_mesh: reads until end of file; arrays grow as their bytes arrive (at most 1 MiB ahead
//   of the data), so a damaged count cannot allocate more than what was sent. Returns the kind;
//   for 'M' fills *mesh, otherwise sets *message. A stream that is truncated, has a wrong marker,
//   impossible values or bytes after "END1" throws Error("damaged data: WHAT") (the caller adds
//   the file name).
#ifndef TMOP_IO_MESH_PIPE_H_
#define TMOP_IO_MESH_PIPE_H_

#include <string>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

bool send_mesh(int fd, const Mesh& mesh);
bool send_message(int fd, char kind, const std::string& message);  // kind 'E', 'A' or 'X'

// stop (may be null) is asked every 200 ms while no data comes; when it returns true,
// receive_mesh throws Error("interrupted").
char receive_mesh(int fd, Mesh* mesh, std::string* message, bool (*stop)() = nullptr);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_MESH_PIPE_H_
