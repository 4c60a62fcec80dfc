// tmop/io/mesh_io.h
// Reading and writing meshes in the common formats; the format is chosen by the file extension.
//
//   .msh                  Gmsh 2.2 and 4.1, ASCII and binary (read both; write per options)
//   .vtk                  VTK legacy UNSTRUCTURED_GRID (POLYDATA on read), ASCII and binary
//                         (big-endian)
//   .pvtu                 VTK's parallel XML UnstructuredGrid: an index and .vtu pieces (write
//                         only: write_pvtu_piece below)
//   .vtu                  VTK XML UnstructuredGrid (read: ascii, base64 inline, raw appended,
//                         zlib-compressed; write: ascii or base64 inline)
//   .mesh                 Medit / INRIA ASCII
//   .ugrid                AFLR3 UGRID: NAME.ugrid ASCII, NAME.b8.ugrid / NAME.lb8.ugrid C binary
//                         big / little-endian, NAME.r8.ugrid / NAME.lr8.ugrid Fortran records
//                         (the name picks the encoding; WriteOptions::binary is not used)
//   .su2                  SU2 native mesh, ASCII: boundary markers as regions + physical names
//   .exo .e               Exodus II through libexodusii, element blocks as regions (only when
//                         tmop was built with the library; otherwise a "built without" error)
//   .cgns                 CGNS through libcgns (the same proviso): unstructured zones, element
//                         sections as regions
//   .obj .off .ply        surface formats (tri3 / quad4 cells): read by tmop, written through
//                         OpenMesh, which writes coordinates as float32
//   .stl                  ASCII and binary STL (tri3 cells; binary holds float32)
//
// read_mesh: fills *mesh (cleared first) with Gmsh node order inside (io/ converts). space_dim is
//   2 when every z coordinate is exactly 0 and no cell has dimension 3; otherwise 3 (surface
//   meshes in 3D stay 3D). Region tags go to Mesh::cell_region, elementary / geometric entity
//   tags to Mesh::cell_entity, named fields to point_data / cell_data. On failure *mesh is left
//   empty and the Status message is one line "FILE:LINE: what is wrong" ("FILE:byte N: ..." in
//   binary data; "FILE: ..." when there is no position, e.g. the file cannot be opened).
//   Declared counts are checked against the file size before anything is allocated. Only
//   regular files are read ("FILE: not a regular file (a directory)"; FIFOs and devices are
//   refused before they are opened), and the first 64 KiB must be a possible start of the
//   format (io/scanner.h, check_magic) before the rest is read.
// write_mesh: writes atomically (io/atomic_file.h: a uniquely named temporary file in the same
//   directory, then rename; removed on failure and on SIGINT/SIGTERM once a tool installed
//   remove_temporaries_on_signal), so OUT either holds the complete new file or is untouched. 2D
//   meshes are written with z = 0. Fails (Status "OUT: cannot write ...", no file written) when the
//   format cannot hold the mesh (a tet or a quad in .stl, quadratic or 3D cells in .obj/.off/.ply,
//   no faces at all in a surface format, quad9 / hex27 / points in .mesh) or on I/O errors.
// check_writable: the checks write_mesh makes before writing, without writing: known extension,
//   a consistent Mesh, cells the format can hold (for .obj/.off/.ply also a surface OpenMesh can
//   build) and an existing, writable output directory. Linear in the mesh size, no file is
//   created. Tools call it before a long computation whose result would be refused; it depends
//   on the cell types, connectivity and data-array names (.vtk refuses an unnamed array), which
//   node movement does not change, and for .stl on coordinates: binary ones must fit in float32,
//   and no triangle may have two corners at one point (in float32 for binary), since STL keeps
//   corners by coordinates and such a file would not read back. write_mesh checks again.
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
  // .pvtu: the number of pieces write_mesh writes (1 or more).
  int pieces = 1;
};

Status read_mesh(const std::string& path, Mesh* mesh);

// Process isolation of the reads that hand file bytes to libhdf5: .cgns files, and .exo/.e files
// that start with the HDF5 signature (netCDF-4). libhdf5 does not validate a damaged file before
// it uses it (fuzzing made libhdf5 1.10.8 free an invalid pointer: docs/fuzzing.md), so with
// isolation on such a file is parsed in a forked child process that sends the mesh back through a
// pipe (io/isolated_read.h), and a crash there is the one-line Status "FILE: the HDF5 library
// crashed reading this file (SIGABRT, signal 6); the file is damaged or not a valid CGNS file"
// instead of the end of the program. The mesh read is the same, field by field.
// Off by default in the library (fork in a library can surprise a program: its other threads do
// not exist in the child, so a lock one of them holds inside libhdf5 would hang the child); the
// tmop tools turn it on. Process-wide (an atomic flag). isolated_hdf5_reads() is the effective
// setting: false whatever was set when MPI is in use (started by mpirun: OMPI_COMM_WORLD_SIZE,
// PMIX_RANK, PMI_SIZE or PMI_RANK set; or MPI_Initialized true in a program linked with MPI), since
// OpenMPI does not support fork. Cost: docs/formats.md, "Process isolation".
void set_isolated_hdf5_reads(bool on);
bool isolated_hdf5_reads();

// For reference geometry (a surface to slide on, not a mesh to optimise): the .stl, .obj, .off
// and .ply readers drop faces with a repeated corner (degenerate facets) and split faces of
// more than 4 corners into triangle fans instead of refusing the file, and count both here.
// Every other error is reported as by read_mesh; other formats ignore the repair.
struct SurfaceRepair {
  int dropped_degenerate = 0;
  int split_polygons = 0;
};
Status read_mesh(const std::string& path, Mesh* mesh, SurfaceRepair* repair);
Status write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options = {});
Status check_writable(const std::string& path, const Mesh& mesh, const WriteOptions& options = {});
// .pvtu (VTK's parallel XML UnstructuredGrid; written, not read): an index naming pieces
// STEM_K.vtu next to it (K = 0 .. pieces-1), each the .vtu of a contiguous block of the cells, in
// cell order, with the vertices they use and their point and cell data; ParaView and VTK's
// vtkXMLPUnstructuredGridReader open the index. write_mesh("X.pvtu") writes every piece and
// then the index (each file atomically, not the set); the processes of a distributed run write
// their own piece each and one of them the index:
Status write_pvtu_piece(const std::string& path, const Mesh& mesh, const WriteOptions& options,
                        int piece, int pieces);
Status write_pvtu_index(const std::string& path, const Mesh& mesh, const WriteOptions& options,
                        int pieces);

// The part of check_writable that is about the place, for any output file (a report, say): the
// directory exists and is writable (the temporary file goes there) and path is not a directory.
Status check_output_path(const std::string& path);

}  // namespace tmop

#endif  // TMOP_IO_MESH_IO_H_
