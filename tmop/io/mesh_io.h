// tmop/io/mesh_io.h
// Reading and writing meshes in the common formats; the format is chosen by the file extension.
//
//   .msh                  Gmsh 2.2 and 4.1, ASCII and binary (read both; write per options)
//   .vtk                  VTK legacy UNSTRUCTURED_GRID (POLYDATA on read), ASCII and binary
//                         (big-endian)
//   .vtu                  VTK XML UnstructuredGrid (read: ascii, base64 inline, raw appended,
//                         zlib-compressed; write: ascii or base64 inline)
//   .mesh                 Medit / INRIA ASCII
//   .obj .off .ply .stl   surface formats through OpenMesh (tri3 / quad4 cells; coordinates
//                         pass through float32 in OpenMesh)
//
// read_mesh: fills *mesh (cleared first) with Gmsh node order inside (io/ converts). space_dim is
//   2 when every z coordinate is exactly 0 and no cell has dimension 3; otherwise 3 (surface
//   meshes in 3D stay 3D). Region tags go to Mesh::cell_region, elementary / geometric entity
//   tags to Mesh::cell_entity, named fields to point_data / cell_data. On failure *mesh is left
//   empty and the Status message is one line "FILE:LINE: what is wrong" ("FILE:byte N: ..." in
//   binary data; "FILE: ..." when there is no position, e.g. the file cannot be opened).
//   Declared counts are checked against the file size before anything is allocated.
// write_mesh: writes atomically (a temporary file in the same directory, then rename), so OUT
//   either holds the complete new file or is untouched. 2D meshes are written with z = 0.
//   Fails (Status) when the format cannot hold the mesh (e.g. a tet in .stl) or on I/O errors.
// docs/formats.md describes node-order conversions and the tag mapping of every format.
#ifndef TMOP_IO_MESH_IO_H_
#define TMOP_IO_MESH_IO_H_

#include <string>

#include "tmop/core/status.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

struct WriteOptions {
  // Binary output where the format has one (.msh, .vtk, .vtu base64, .ply, .stl). Default ASCII,
  // which is portable and diffable; binary is ~3x smaller and faster to read.
  bool binary = false;
  // Gmsh file-format version for .msh: 41 (default, what current Gmsh writes) or 22 (for old
  // readers).
  int msh_version = 41;
};

Status read_mesh(const std::string& path, Mesh* mesh);
Status write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options = {});

}  // namespace tmop

#endif  // TMOP_IO_MESH_IO_H_
