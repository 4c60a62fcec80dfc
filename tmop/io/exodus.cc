// tmop/io/exodus.cc
// Exodus II (.exo .e) through libexodusii (Debian's 6.02, a netCDF file). Only built with the
// library (CMake finds exodusII.h and libexoIIv2c: TMOP_WITH_EXODUS); without it reading and
// writing fail with "FILE: tmop was built without Exodus II support".
//
// Element blocks <-> cells: one block per (region, type) on write, block id = the region when
// that id is still free (otherwise the next free id), so Mesh::cell_region = block id on read.
// Block names <-> Mesh::physical_names: a block is named by the physical name of its (dimension,
// region); on read a named block names (dimension of its type, block id). Names are stored up
// to 255 characters (ex_set_max_name_length). Side sets <-> boundary regions (exodus_sides.h:
// written in addition to the blocks for regions whose cells are all sides of elements; read as
// boundary cells unless a block holds the same cell). Node sets and variables are not read or
// written.
//
// Types and node order (Exodus II manual, "element types"; Sandia's IOSS face tables for HEX27
// and WEDGE18): BAR2/BEAM2/TRUSS2 line2, BEAM3 (read also BAR3, TRUSS3: meshio 5 knows only
// BEAM3) line3, TRI/TRI3/TRISHELL/SHELL3 tri3, TRI6, QUAD/QUAD4/SHELL/SHELL4 quad4, QUAD8/SHELL8,
// QUAD9/SHELL9, TETRA/TETRA4, TETRA10, PYRAMID/PYRAMID5/13/14, WEDGE/WEDGE6/15/18,
// HEX/HEX8/20/27 (the first name is written: meshio 5 reads TETRA4 as an unknown "tetra4" and not
// WEDGE6 at all; a base name takes its type from the node count). Mid-edge, face and centre nodes
// in PATRAN's order (node_order.h).
#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "tmop/io/atomic_file.h"
#include "tmop/io/exodus_sides.h"
#include "tmop/io/formats.h"
#include "tmop/io/netcdf_header.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"  // printable

#ifdef TMOP_WITH_EXODUS
#include <exodusII.h>
#include <sys/stat.h>
#endif

namespace tmop {
namespace io {

#ifndef TMOP_WITH_EXODUS

void read_exodus(const std::string& path, Mesh*) {
  throw Error(path +
              ": tmop was built without Exodus II support (install libexodusii-dev and "
              "reconfigure)");
}
void write_exodus(const std::string& path, const Mesh&) {
  throw Error(path +
              ": tmop was built without Exodus II support (install libexodusii-dev and "
              "reconfigure)");
}
void check_exodus_writable(const Mesh&) {
  throw Error("tmop was built without Exodus II support (install libexodusii-dev and reconfigure)");
}

#else

namespace {

struct ExoType {
  const char* name;  // as written; also accepted on read
  CellType type;
};
const ExoType kTypes[] = {
    {"BAR2", CellType::kLine2},          {"BEAM3", CellType::kLine3},
    {"TRI3", CellType::kTri3},           {"TRI6", CellType::kTri6},
    {"QUAD4", CellType::kQuad4},         {"QUAD9", CellType::kQuad9},
    {"TETRA", CellType::kTet4},          {"TETRA10", CellType::kTet10},
    {"PYRAMID", CellType::kPyramid5},    {"WEDGE", CellType::kWedge6},
    {"HEX8", CellType::kHex8},           {"QUAD8", CellType::kQuad8},
    {"HEX20", CellType::kHex20},         {"WEDGE15", CellType::kWedge15},
    {"PYRAMID13", CellType::kPyramid13}, {"PYRAMID14", CellType::kPyramid14},
    {"HEX27", CellType::kHex27},         {"WEDGE18", CellType::kWedge18},
};
// Other names for the same types, accepted on read.
const ExoType kAliases[] = {
    {"BEAM2", CellType::kLine2},       {"TRUSS2", CellType::kLine2},
    {"BAR3", CellType::kLine3},        {"TRUSS3", CellType::kLine3},
    {"BAR", CellType::kLine2},         {"TRI", CellType::kTri3},
    {"TRIANGLE", CellType::kTri3},     {"TRISHELL", CellType::kTri3},
    {"SHELL3", CellType::kTri3},       {"QUAD", CellType::kQuad4},
    {"SHELL", CellType::kQuad4},       {"SHELL4", CellType::kQuad4},
    {"SHELL9", CellType::kQuad9},      {"TETRA4", CellType::kTet4},
    {"TET4", CellType::kTet4},         {"TET10", CellType::kTet10},
    {"PYRAMID5", CellType::kPyramid5}, {"PYRA5", CellType::kPyramid5},
    {"WEDGE6", CellType::kWedge6},     {"HEX", CellType::kHex8},
    {"SHELL8", CellType::kQuad8},      {"QUAD", CellType::kQuad8},
    {"HEX", CellType::kHex20},         {"WEDGE", CellType::kWedge15},
    {"TETRA", CellType::kTet10},       {"TET", CellType::kTet10},
    {"TRI", CellType::kTri6},          {"TRIANGLE", CellType::kTri6},
    {"QUAD", CellType::kQuad9},        {"SHELL", CellType::kQuad9},
    {"PYRAMID", CellType::kPyramid13}, {"PYRAMID", CellType::kPyramid14},
    {"PYRA13", CellType::kPyramid13},  {"PYRA14", CellType::kPyramid14},
    {"HEX", CellType::kHex27},         {"WEDGE", CellType::kWedge18},
};

bool exo_type(const std::string& name, int nodes, CellType* t) {
  std::string up;
  for (char c : name)
    if (c != ' ' && c != '\0')
      up.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  for (const ExoType& e : kTypes)
    if (up == e.name && cell_num_nodes(e.type) == nodes) return *t = e.type, true;
  for (const ExoType& e : kAliases)
    if (up == e.name && cell_num_nodes(e.type) == nodes) return *t = e.type, true;
  return false;
}

const char* exo_name(CellType t) {
  for (const ExoType& e : kTypes)
    if (e.type == t) return e.name;
  return nullptr;
}

// The Exodus position of Gmsh node i (PATRAN's order, node_order.h).
int exo_index(CellType t, int i) { return patran_index_of_gmsh_node(t, i, PatranFormat::kExodus); }

// Closes the file on every path out of the reader and writer.
struct ExoFile {
  int id = -1;
  ~ExoFile() {
    if (id >= 0) ex_close(id);
  }
};

constexpr int kMaxName = 255;

}  // namespace

void read_exodus(const std::string& path, Mesh* mesh) {
  ex_opts(0);  // no messages on stderr, never abort: errors come back as return codes
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw Error(path + ": cannot open the file");
  const std::uint64_t size = static_cast<std::uint64_t>(st.st_size);
  int cpu_ws = 8, io_ws = 0;
  float version = 0;
  check_exodus_file(path);  // a crafted header must not make libnetcdf allocate (netcdf_header.h)
  ExoFile f;
  f.id = ex_open(path.c_str(), EX_READ, &cpu_ws, &io_ws, &version);
  if (f.id < 0) throw Error(path + ": not a readable Exodus II file (netCDF)");
  // Every buffer below holds 32-bit ints: the API's integer size is this reader's choice, never
  // the file's. Fuzzing found libexodusii reading a connectivity as 64-bit (libnetcdf's int ->
  // long long conversion in ex_get_conn wrote past the buffer) after a sequence of crafted files,
  // though no one file alone reproduced it; ex_set_int64_status(0) rules it out for every
  // ex_get_* below (2 of 2 ctest fuzz.exo runs failed before, 0 of 3 after).
  if (ex_set_int64_status(f.id, 0) < 0)
    throw Error(path + ": cannot set the Exodus II integer size");
  char title[MAX_LINE_LENGTH + 1] = {0};
  int dim = 0, nn = 0, ne = 0, nb = 0, nns = 0, nss = 0;
  if (ex_get_init(f.id, title, &dim, &nn, &ne, &nb, &nns, &nss) < 0)
    throw Error(path + ": cannot read the Exodus II header");
  if (dim < 1 || dim > 3 || nn < 0 || ne < 0 || nb < 0)
    throw Error(path + ": bad Exodus II header (dimension " + std::to_string(dim) + ", " +
                std::to_string(nn) + " nodes, " + std::to_string(nb) + " blocks)");
  // Hostile headers: what is declared must fit in the file before it is allocated.
  if (static_cast<std::uint64_t>(nn) * 4 * dim > size || static_cast<std::uint64_t>(nb) * 4 > size)
    throw Error(path + ": the header declares " + std::to_string(nn) + " nodes and " +
                std::to_string(nb) + " blocks, more than the " + std::to_string(size) +
                " bytes of the file hold");
  std::vector<double> x(nn), y(nn), z(nn);
  if (nn > 0 &&
      ex_get_coord(f.id, x.data(), dim > 1 ? y.data() : nullptr, dim > 2 ? z.data() : nullptr) < 0)
    throw Error(path + ": cannot read the Exodus II coordinates");
  mesh->space_dim = 3;
  mesh->coords.resize(3 * static_cast<std::size_t>(nn));
  for (int v = 0; v < nn; ++v) {
    mesh->coords[3 * v] = x[v];
    mesh->coords[3 * v + 1] = dim > 1 ? y[v] : 0.0;
    mesh->coords[3 * v + 2] = dim > 2 ? z[v] : 0.0;
  }
  const int first = mesh->num_cells();
  std::vector<int> ids(nb);
  if (nb > 0 && ex_get_ids(f.id, EX_ELEM_BLOCK, ids.data()) < 0)
    throw Error(path + ": cannot read the Exodus II element block ids");
  const std::vector<std::string> names = exodus_names(f.id, EX_ELEM_BLOCK, nb);
  for (std::size_t b = 0; b < ids.size(); ++b) {
    const int id = ids[b];
    char type[MAX_STR_LENGTH + 1] = {0};
    int count = 0, npe = 0, edges = 0, faces = 0, attrs = 0;
    if (ex_get_block(f.id, EX_ELEM_BLOCK, id, type, &count, &npe, &edges, &faces, &attrs) < 0)
      throw Error(path + ": cannot read element block " + std::to_string(id));
    if (count == 0) continue;
    CellType t;
    if (!exo_type(type, npe, &t))
      throw Error(path + ": element block " + std::to_string(id) + ": unsupported element type '" +
                  printable(type) + "' with " + std::to_string(npe) + " nodes");
    if (count < 0 || static_cast<std::uint64_t>(count) * npe * 4 > size)
      throw Error(path + ": element block " + std::to_string(id) + " declares " +
                  std::to_string(count) + " elements, more than the file holds");
    std::vector<int> conn(static_cast<std::size_t>(count) * npe);
    if (ex_get_conn(f.id, EX_ELEM_BLOCK, id, conn.data(), nullptr, nullptr) < 0)
      throw Error(path + ": cannot read the connectivity of element block " + std::to_string(id));
    std::int32_t nodes[kMaxCellNodes];
    for (int e = 0; e < count; ++e) {
      for (int i = 0; i < npe; ++i) {
        const int v = conn[static_cast<std::size_t>(e) * npe + exo_index(t, i)];
        if (v < 1 || v > nn)
          throw Error(path + ": element block " + std::to_string(id) + ", element " +
                      std::to_string(e + 1) + ": node " + std::to_string(v) +
                      " is out of range 1.." + std::to_string(nn));
        nodes[i] = v - 1;
      }
      mesh->add_cell(t, nodes, id, 0);
    }
    if (!names[b].empty()) mesh->set_physical_name(cell_dim(t), id, names[b]);
  }
  read_exodus_side_sets(path, f.id, size, nss, dim, first, mesh->num_cells() - first, mesh);
}

void check_exodus_writable(const Mesh& mesh) {
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (!exo_name(mesh.cell_types[c]))
      throw Error(std::string("cannot write ") + cell_name(mesh.cell_types[c]) +
                  " cells to Exodus II (cell " + std::to_string(c) + " is the first)");
}

namespace {

struct OutBlock {
  int id;
  CellType type;
  std::vector<int> cells;
};

// One block per (region, type) in order of first appearance; id = region while it is free.
std::vector<OutBlock> make_blocks(const Mesh& mesh) {
  std::vector<OutBlock> blocks;
  std::vector<int> used;
  int max_id = 0;
  for (int r : mesh.cell_region) max_id = std::max(max_id, r);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    OutBlock* b = nullptr;
    for (OutBlock& o : blocks)
      if (o.type == mesh.cell_types[c] && mesh.cell_region[o.cells[0]] == mesh.cell_region[c])
        b = &o;
    if (!b) {
      int id = mesh.cell_region[c];
      if (id <= 0 || std::find(used.begin(), used.end(), id) != used.end()) id = ++max_id;
      used.push_back(id);
      blocks.push_back({id, mesh.cell_types[c], {}});
      b = &blocks.back();
    }
    b->cells.push_back(c);
  }
  return blocks;
}

// Cell c's 1-based Exodus element number: blocks in order, cells in block order.
std::vector<int> element_numbers(const Mesh& mesh, const std::vector<OutBlock>& blocks) {
  std::vector<int> number(mesh.num_cells(), 0);
  int next = 1;
  for (const OutBlock& b : blocks)
    for (int c : b.cells) number[c] = next++;
  return number;
}

void write_blocks(const std::string& path, int exo, const Mesh& mesh,
                  const std::vector<OutBlock>& blocks) {
  for (const OutBlock& b : blocks) {
    const int npe = cell_num_nodes(b.type);
    if (ex_put_block(exo, EX_ELEM_BLOCK, b.id, exo_name(b.type),
                     static_cast<std::int64_t>(b.cells.size()), npe, 0, 0, 0) < 0)
      throw Error(path + ": cannot write element block " + std::to_string(b.id));
    std::vector<int> conn(b.cells.size() * npe);
    for (std::size_t k = 0; k < b.cells.size(); ++k)
      for (int i = 0; i < npe; ++i)
        conn[k * npe + exo_index(b.type, i)] = mesh.cell(b.cells[k])[i] + 1;
    if (ex_put_conn(exo, EX_ELEM_BLOCK, b.id, conn.data(), nullptr, nullptr) < 0)
      throw Error(path + ": cannot write the connectivity of element block " +
                  std::to_string(b.id));
  }
  std::vector<std::string> names;
  for (const OutBlock& b : blocks) {
    const std::string* name = mesh.physical_name(cell_dim(b.type), mesh.cell_region[b.cells[0]]);
    names.push_back(name ? name->substr(0, kMaxName) : std::string());
  }
  if (std::all_of(names.begin(), names.end(), [](const std::string& n) { return n.empty(); }))
    return;
  std::vector<char*> ptr;
  for (std::string& n : names) ptr.push_back(&n[0]);
  if (ex_put_names(exo, EX_ELEM_BLOCK, ptr.data()) < 0)
    throw Error(path + ": cannot write the Exodus II block names");
}

}  // namespace

void write_exodus(const std::string& path, const Mesh& mesh) {
  check_exodus_writable(mesh);
  ex_opts(0);
  TempFile tmp(path, "exo");
  tmp.close_fd();
  {
    int cpu_ws = 8, io_ws = 8;
    ExoFile f;
    f.id = ex_create(tmp.name().c_str(), EX_CLOBBER, &cpu_ws, &io_ws);
    if (f.id < 0) throw Error(path + ": cannot create the Exodus II file");
    ex_set_max_name_length(f.id, kMaxName);  // before ex_put_init: names up to 255 characters
    const int dim = mesh.space_dim == 2 && mesh.plane_z != 0 ? 3 : mesh.space_dim;
    const std::vector<OutBlock> blocks = make_blocks(mesh);
    const std::vector<ExoSideSet> sides =
        plan_exodus_side_sets(mesh, element_numbers(mesh, blocks), dim);
    const int nb = static_cast<int>(blocks.size()), nss = static_cast<int>(sides.size());
    if (ex_put_init(f.id, "tmop", dim, mesh.num_vertices(), mesh.num_cells(), nb, 0, nss) < 0)
      throw Error(path + ": cannot write the Exodus II header");
    const int n = mesh.num_vertices();
    std::vector<double> x(n), y(n), z(n);
    for (int v = 0; v < n; ++v) {
      x[v] = coord(mesh, v, 0);
      y[v] = coord(mesh, v, 1);
      z[v] = coord(mesh, v, 2);
    }
    if (n > 0 && ex_put_coord(f.id, x.data(), y.data(), dim > 2 ? z.data() : nullptr) < 0)
      throw Error(path + ": cannot write the Exodus II coordinates");
    write_blocks(path, f.id, mesh, blocks);
    write_exodus_side_sets(path, f.id, sides);
    const int id = f.id;
    f.id = -1;
    if (ex_close(id) < 0) throw Error(path + ": cannot finish the Exodus II file");
  }
  tmp.commit();
}

#endif  // TMOP_WITH_EXODUS

}  // namespace io
}  // namespace tmop
