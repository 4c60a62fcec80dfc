// tmop/io/mesh_io.cc
// Dispatch by extension, the common post-read step and atomic writes.
#include "tmop/io/mesh_io.h"

#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tmop/io/atomic_file.h"
#include "tmop/io/formats.h"
#include "tmop/io/isolated_read.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"

namespace tmop {
namespace {

std::string extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_openmesh_ext(const std::string& ext) {
  return ext == "obj" || ext == "off" || ext == "ply";
}

const char* kKnown =
    "known: .msh .vtk .vtu .mesh .ugrid .su2 .exo .e .cgns .obj .off .ply .stl (.pvtu: write only)";

bool is_exodus_ext(const std::string& ext) { return ext == "exo" || ext == "e"; }

bool is_known_ext(const std::string& ext) {
  return ext == "msh" || ext == "vtk" || ext == "vtu" || ext == "pvtu" || ext == "mesh" ||
         ext == "stl" || ext == "ugrid" || ext == "su2" || ext == "cgns" || is_exodus_ext(ext) ||
         is_openmesh_ext(ext);
}

// True when dropping z would put two vertices that differ only in z on one point (a fuzzed STL:
// (x, y, 0) and (x, y, 1e-38)). Formats that name corners by their coordinates (STL) would
// then merge them on the next read, so such a mesh stays 3D.
bool flattening_merges_vertices(const std::vector<double>& coords) {
  struct XyHash {
    std::size_t operator()(const std::pair<double, double>& p) const {
      return std::hash<double>()(p.first) * 1099511628211ull ^ std::hash<double>()(p.second);
    }
  };
  std::unordered_map<std::pair<double, double>, double, XyHash> z_at;
  const std::size_t n = coords.size() / 3;
  z_at.reserve(n);
  for (std::size_t v = 0; v < n; ++v) {
    const auto it =
        z_at.emplace(std::make_pair(coords[3 * v], coords[3 * v + 1]), coords[3 * v + 2]);
    if (!it.second && it.first->second != coords[3 * v + 2]) return true;
  }
  return false;
}

}  // namespace

namespace io {

void finish_read(Mesh* mesh) {
  mesh->cell_region.resize(mesh->cell_types.size(), 0);
  mesh->cell_entity.resize(mesh->cell_types.size(), 0);
  if (mesh->space_dim != 3) return;
  bool flat = true;
  for (CellType t : mesh->cell_types)
    if (cell_dim(t) > 2) flat = false;
  // Planar when every z is the same up to round-off: generators (gmsh's spline curves, say)
  // leave z values of 1e-17 on meshes that are meant to lie in the plane z = 0. The test is
  // relative to the mesh's extent, so the z differences dropped are below 1e-12 of its size. A
  // plane z = c other than 0 is kept in plane_z (writers put it back).
  const std::size_t n = mesh->coords.size() / 3;
  const double z0 = n > 0 ? mesh->coords[2] : 0.0;
  double extent = 0, zdev = 0;
  for (std::size_t v = 0; v < n; ++v) {
    extent = std::max({extent, std::abs(mesh->coords[3 * v]), std::abs(mesh->coords[3 * v + 1])});
    zdev = std::max(zdev, std::abs(mesh->coords[3 * v + 2] - z0));
  }
  if (!(zdev <= 1e-12 * extent) && zdev != 0.0) flat = false;
  if (flat && zdev != 0.0 && flattening_merges_vertices(mesh->coords)) flat = false;
  if (!flat) return;
  mesh->plane_z = std::abs(z0) <= 1e-12 * extent ? 0.0 : z0;
  for (std::size_t v = 0; v < n; ++v) {
    mesh->coords[2 * v] = mesh->coords[3 * v];
    mesh->coords[2 * v + 1] = mesh->coords[3 * v + 1];
  }
  mesh->coords.resize(2 * n);
  mesh->space_dim = 2;
}

}  // namespace io

Status read_mesh(const std::string& path, Mesh* mesh) { return read_mesh(path, mesh, nullptr); }

Status read_mesh(const std::string& path, Mesh* mesh, SurfaceRepair* repair) {
  mesh->clear();
  if (repair) *repair = SurfaceRepair();
  const std::string ext = extension(path);
  try {
    // A directory (or a device, a FIFO) is refused as such, whatever its name ends with.
    io::check_regular_file(path);
    if (!is_known_ext(ext))
      return Status::Failure(path + ": unknown mesh file extension '." + ext + "' (" + kKnown +
                             ")");
    if (ext == "pvtu")
      return Status::Failure(path +
                             ": tmop writes .pvtu but does not read it (read its .vtu pieces)");
    if (is_exodus_ext(ext) || ext == "cgns") {
      // libexodusii and libcgns read the file by its name; what goes to libhdf5 may be parsed
      // in a child process (isolated_read.h).
      const bool isolate = isolated_hdf5_reads() && (ext == "cgns" || io::has_hdf5_signature(path));
      if (isolate && ext == "cgns")
        io::read_isolated(path, io::read_cgns, "CGNS", mesh);
      else if (isolate)
        io::read_isolated(path, io::read_exodus, "netCDF-4 (HDF5) Exodus II", mesh);
      else if (ext == "cgns")
        io::read_cgns(path, mesh);
      else
        io::read_exodus(path, mesh);
      io::finish_read(mesh);
      return Status::Ok();
    }
    const std::string data = io::read_file(path, ext);
    if (ext == "msh") io::read_msh(path, data, mesh);
    if (ext == "vtk") io::read_vtk(path, data, mesh);
    if (ext == "vtu") io::read_vtu(path, data, mesh);
    if (ext == "mesh") io::read_medit(path, data, mesh);
    if (ext == "ugrid") io::read_ugrid(path, data, mesh);
    if (ext == "su2") io::read_su2(path, data, mesh);
    if (ext == "stl") io::read_stl(path, data, mesh, repair);
    if (is_openmesh_ext(ext)) io::read_surface(path, ext, data, mesh, repair);
    io::finish_read(mesh);
  } catch (const Error& e) {
    mesh->clear();
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    mesh->clear();
    return Status::Failure(path + ": out of memory while reading");
  }
  return Status::Ok();
}

namespace {

// Throws Error("PATH: ...") for anything write_mesh would refuse before writing.
void check_writable_or_throw(const std::string& path, const Mesh& mesh,
                             const WriteOptions& options) {
  const std::string ext = extension(path);
  if (!is_known_ext(ext))
    throw Error(path + ": unknown mesh file extension '." + ext + "' (" + kKnown + ")");
  if (mesh.space_dim != 2 && mesh.space_dim != 3)
    throw Error(path + ": cannot write a mesh with space_dim " + std::to_string(mesh.space_dim));
  // Writers index these arrays per cell: refuse an inconsistent Mesh instead of reading past
  // the end of one of them.
  const std::size_t n = mesh.cell_types.size();
  if (mesh.cell_region.size() != n || mesh.cell_entity.size() != n ||
      mesh.cell_offsets.size() != n + 1 || mesh.coords.size() % mesh.space_dim != 0 ||
      (n > 0 && static_cast<std::size_t>(mesh.cell_offsets[n]) != mesh.cell_nodes.size()))
    throw Error(path +
                ": cannot write an inconsistent Mesh (cell_region, cell_entity, "
                "cell_offsets, cell_nodes and coords sizes disagree)");
  for (std::size_t c = 0; c < n; ++c)
    if (mesh.cell_offsets[c + 1] - mesh.cell_offsets[c] != cell_num_nodes(mesh.cell_types[c]))
      throw Error(path + ": cannot write: cell " + std::to_string(c) + " has " +
                  std::to_string(mesh.cell_offsets[c + 1] - mesh.cell_offsets[c]) +
                  " nodes, its type " + cell_name(mesh.cell_types[c]) + " has " +
                  std::to_string(cell_num_nodes(mesh.cell_types[c])));
  for (std::int32_t v : mesh.cell_nodes)
    if (v < 0 || v >= mesh.num_vertices())
      throw Error(path + ": cannot write: a cell refers to vertex " + std::to_string(v) +
                  ", the mesh has " + std::to_string(mesh.num_vertices()));
  if (ext == "msh" && options.msh_version != 22 && options.msh_version != 41)
    throw Error(path + ": cannot write MSH version " + std::to_string(options.msh_version) +
                " (22 and 41 are supported)");
  try {
    if (ext == "msh") io::check_msh_writable(mesh);
    if (ext == "mesh") io::check_medit_writable(mesh);
    if (ext == "ugrid") io::check_ugrid_writable(path, mesh);
    if (ext == "su2") io::check_su2_writable(mesh);
    if (is_exodus_ext(ext)) io::check_exodus_writable(mesh);
    if (ext == "cgns") io::check_cgns_writable(mesh);
    if (ext == "vtk") io::check_vtk_writable(mesh);
    if (ext == "vtu") io::check_vtk_cell_types(mesh, ".vtu");
    if (ext == "pvtu") io::check_vtk_cell_types(mesh, ".pvtu");
    if (ext == "pvtu" && options.pieces < 1)
      throw Error("cannot write " + std::to_string(options.pieces) + " pieces (1 or more)");
    if (ext == "stl") io::check_stl_writable(mesh, options);
    if (is_openmesh_ext(ext)) io::check_openmesh_writable(ext, mesh);
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  const Status place = check_output_path(path);
  if (!place.ok()) throw Error(place.message());
}

}  // namespace

Status check_output_path(const std::string& path) {
  // The temporary file goes next to the output, so its directory must exist and be writable.
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return Status::Failure(path + ": cannot write: directory " + dir + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    return Status::Failure(path + ": cannot write: directory " + dir + " is not writable");
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    return Status::Failure(path + ": cannot write: it is a directory");
  return Status::Ok();
}

Status check_writable(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  try {
    check_writable_or_throw(path, mesh, options);
  } catch (const Error& e) {
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    return Status::Failure(path + ": out of memory while checking the output");
  }
  return Status::Ok();
}

Status write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  const std::string ext = extension(path);
  try {
    check_writable_or_throw(path, mesh, options);
    if (is_openmesh_ext(ext)) {
      // OpenMesh picks its writer by the extension, which the temporary file keeps.
      TempFile tmp(path, ext);
      tmp.close_fd();
      try {
        io::write_openmesh(tmp.name(), ext, mesh, options);
      } catch (const Error& e) {
        throw Error(path + ": " + e.what());
      }
      tmp.commit();
      return Status::Ok();
    }
    if (ext == "pvtu") {
      for (int k = 0; k < options.pieces; ++k) {
        const Status s = write_pvtu_piece(path, mesh, options, k, options.pieces);
        if (!s.ok()) return s;
      }
      return write_pvtu_index(path, mesh, options, options.pieces);
    }
    if (is_exodus_ext(ext) || ext == "cgns") {
      // Atomically, through their own temporary files.
      if (ext == "cgns")
        io::write_cgns(path, mesh);
      else
        io::write_exodus(path, mesh);
      return Status::Ok();
    }
    std::string bytes;
    try {
      if (ext == "msh")
        io::write_msh(mesh, options, &bytes);
      else if (ext == "vtk")
        io::write_vtk(mesh, options, &bytes);
      else if (ext == "vtu")
        io::write_vtu(mesh, options, &bytes);
      else if (ext == "mesh")
        io::write_medit(mesh, options, &bytes);
      else if (ext == "ugrid")
        io::write_ugrid(path, mesh, &bytes);
      else if (ext == "su2")
        io::write_su2(mesh, &bytes);
      else
        io::write_stl(mesh, options, &bytes);
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
    const Status written = write_file_atomically(path, bytes);
    if (!written.ok()) return written;
  } catch (const Error& e) {
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    return Status::Failure(path + ": out of memory while writing");
  }
  return Status::Ok();
}

Status write_pvtu_piece(const std::string& path, const Mesh& mesh, const WriteOptions& options,
                        int piece, int pieces) {
  try {
    check_writable_or_throw(path, mesh, options);
    if (pieces < 1 || piece < 0 || piece >= pieces)
      throw Error(path + ": piece " + std::to_string(piece) + " of " + std::to_string(pieces));
    std::string bytes;
    io::write_vtu(io::pvtu_piece(mesh, piece, pieces), options, &bytes);
    return write_file_atomically(io::pvtu_piece_path(path, piece), bytes);
  } catch (const Error& e) {
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    return Status::Failure(path + ": out of memory while writing");
  }
}

Status write_pvtu_index(const std::string& path, const Mesh& mesh, const WriteOptions& options,
                        int pieces) {
  try {
    check_writable_or_throw(path, mesh, options);
    if (pieces < 1) throw Error(path + ": " + std::to_string(pieces) + " pieces");
    return write_file_atomically(path, io::pvtu_index(path, mesh, options, pieces));
  } catch (const Error& e) {
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    return Status::Failure(path + ": out of memory while writing");
  }
}

}  // namespace tmop
