// tmop/io/formats.h
// The per-format readers and writers behind read_mesh / write_mesh (internal to io/).
// Readers get the whole file in memory, throw tmop::Error with a located one-line message, and
// fill a Mesh with space_dim = 3 (finish_read() then decides 2 or 3). Writers append the complete
// file to *out (mesh_io.cc writes it atomically) or throw Error("cannot write ..."). The
// check_*_writable functions throw the same errors as their writer for a mesh the format cannot
// hold, without writing (check_writable in mesh_io.h).
#ifndef TMOP_IO_FORMATS_H_
#define TMOP_IO_FORMATS_H_

#include <string>

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

void read_msh(const std::string& path, const std::string& data, Mesh* mesh);
void write_msh(const Mesh& mesh, const WriteOptions& options, std::string* out);
void check_msh_writable(const Mesh& mesh);  // physical names Gmsh can read back

void read_vtk(const std::string& path, const std::string& data, Mesh* mesh);
void write_vtk(const Mesh& mesh, const WriteOptions& options, std::string* out);
void check_vtk_writable(const Mesh& mesh);

void read_vtu(const std::string& path, const std::string& data, Mesh* mesh);
void write_vtu(const Mesh& mesh, const WriteOptions& options, std::string* out);
// .pvtu (pvtu.cc): the path of piece K, the mesh of piece K of P, the index's text.
std::string pvtu_piece_path(const std::string& pvtu, int piece);
Mesh pvtu_piece(const Mesh& mesh, int piece, int pieces);
std::string pvtu_index(const std::string& pvtu, const Mesh& mesh, const WriteOptions& options,
                       int pieces);

void read_medit(const std::string& path, const std::string& data, Mesh* mesh);
void write_medit(const Mesh& mesh, const WriteOptions& options, std::string* out);
void check_medit_writable(const Mesh& mesh);

// SU2 .su2 (ASCII): boundary markers <-> regions and physical names of the boundary cells.
void read_su2(const std::string& path, const std::string& data, Mesh* mesh);
void write_su2(const Mesh& mesh, std::string* out);
void check_su2_writable(const Mesh& mesh);

// AFLR3 .ugrid; the encoding comes from the name (NAME.ugrid ASCII, NAME.b8.ugrid, .lb8, .r8,
// .lr8 binary: ugrid.cc), not from WriteOptions.
void read_ugrid(const std::string& path, const std::string& data, Mesh* mesh);
void write_ugrid(const std::string& path, const Mesh& mesh, std::string* out);
void check_ugrid_writable(const std::string& path, const Mesh& mesh);

// Exodus II .exo / .e through libexodusii (exodus.cc), which reads and writes by path: the
// reader opens path itself, the writer writes path (mesh_io.cc passes a temporary name).
// Without the library (TMOP_WITH_EXODUS unset) all three throw "... built without Exodus II".
void read_exodus(const std::string& path, Mesh* mesh);
void write_exodus(const std::string& path, const Mesh& mesh);
void check_exodus_writable(const Mesh& mesh);

// CGNS .cgns through libcgns (cgns.cc), by path like Exodus; TMOP_WITH_CGNS.
void read_cgns(const std::string& path, Mesh* mesh);
void write_cgns(const std::string& path, const Mesh& mesh);
void check_cgns_writable(const Mesh& mesh);

// repair (null: strict) makes the surface readers drop faces with a repeated corner and split
// faces of more than 4 corners into triangle fans, counting both (mesh_io.h, SurfaceRepair).
void read_stl(const std::string& path, const std::string& data, Mesh* mesh,
              SurfaceRepair* repair = nullptr);
void write_stl(const Mesh& mesh, const WriteOptions& options, std::string* out);
void check_stl_writable(const Mesh& mesh, const WriteOptions& options);

// .obj .off .ply (ext without the dot, lower case): tmop reads them (surface_read.cc); OpenMesh
// writes them to a path, a temporary one whose extension selects the format (openmesh_io.cc).
void read_surface(const std::string& path, const std::string& ext, const std::string& data,
                  Mesh* mesh, SurfaceRepair* repair = nullptr);
void write_openmesh(const std::string& path, const std::string& ext, const Mesh& mesh,
                    const WriteOptions& options);
void check_openmesh_writable(const std::string& ext, const Mesh& mesh);

// After a reader: sets space_dim to 2 when every z is exactly 0 and no cell is 3D (dropping the
// z column), makes cell_region / cell_entity as long as the cell list.
void finish_read(Mesh* mesh);

// Coordinate k (0..2) of vertex v, 0 beyond space_dim: writers pad 2D meshes with z = 0.
inline double coord(const Mesh& mesh, int v, int k) {
  return k < mesh.space_dim ? mesh.coords[static_cast<std::size_t>(v) * mesh.space_dim + k]
                            : mesh.plane_z;
}

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_FORMATS_H_
