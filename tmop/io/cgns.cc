// tmop/io/cgns.cc
// CGNS (.cgns) through libcgns (Debian's 3.4, HDF5 files). Only built with the library (CMake
// finds cgnslib.h and libcgns: TMOP_WITH_CGNS); without it reading and writing fail with
// "FILE: tmop was built without CGNS support".
//
// Read: the first base; every unstructured zone of it, merged (vertices of zone k follow those
// of zone k - 1; zones are not glued at shared points); structured zones are refused. Every
// element section becomes cells; MIXED sections (the CGNS 3.x layout: type, nodes, type, ...)
// are split per element. Regions: a section named "Region_R_..." (tmop's own) gives region R,
// any other section the number in its Descriptor "tmop_region" (tmop's named sections) or else
// its 1-based section number; such a section's name is the physical name of (dimension of its
// cells, region) (Mesh::physical_names). Boundary conditions (ZoneBC_t) name boundary regions
// on read and are written for every boundary region (cgns_bc.h). Flow solutions are not read.
// Write: one base "Base", one zone "Zone1", one section per (region, type), named
// "Region_R_TYPE", the elements' sections first, element numbers 1..N in section order; coordinates
// as RealDouble. A region with a physical name whose cells are of one type is one section named by
// it instead (CGNS node names: 1 to 32 characters, no '/'; the first of equal names only), with the
// region in a Descriptor "tmop_region"; other names are not written.
//
// Types and node order (CGNS SIDS, "Unstructured Grid Element Numbering Conventions"): NODE,
// BAR_2/3, TRI_3/6, QUAD_4/8/9, TETRA_4/10, PYRA_5/13/14, PENTA_6/15/18, HEXA_8/20/27, with the
// mid-edge, face and centre nodes in PATRAN's order (node_order.h: HEXA_27's faces and centre
// differ from Exodus's).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "tmop/io/atomic_file.h"
#include "tmop/io/cgns_bc.h"
#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"

#ifdef TMOP_WITH_CGNS
#include <cgnslib.h>
#include <sys/stat.h>
#endif

namespace tmop {
namespace io {

#ifndef TMOP_WITH_CGNS

void read_cgns(const std::string& path, Mesh*) {
  throw Error(path + ": tmop was built without CGNS support (install libcgns-dev and reconfigure)");
}
void write_cgns(const std::string& path, const Mesh&) {
  throw Error(path + ": tmop was built without CGNS support (install libcgns-dev and reconfigure)");
}
void check_cgns_writable(const Mesh&) {
  throw Error("tmop was built without CGNS support (install libcgns-dev and reconfigure)");
}

#else

namespace {

struct CgType {
  CGNS_ENUMT(ElementType_t) cg;
  CellType type;
};
const CgType kTypes[] = {
    {CGNS_ENUMV(NODE), CellType::kVertex},       {CGNS_ENUMV(BAR_2), CellType::kLine2},
    {CGNS_ENUMV(BAR_3), CellType::kLine3},       {CGNS_ENUMV(TRI_3), CellType::kTri3},
    {CGNS_ENUMV(TRI_6), CellType::kTri6},        {CGNS_ENUMV(QUAD_4), CellType::kQuad4},
    {CGNS_ENUMV(QUAD_9), CellType::kQuad9},      {CGNS_ENUMV(TETRA_4), CellType::kTet4},
    {CGNS_ENUMV(TETRA_10), CellType::kTet10},    {CGNS_ENUMV(PYRA_5), CellType::kPyramid5},
    {CGNS_ENUMV(PENTA_6), CellType::kWedge6},    {CGNS_ENUMV(HEXA_8), CellType::kHex8},
    {CGNS_ENUMV(QUAD_8), CellType::kQuad8},      {CGNS_ENUMV(HEXA_20), CellType::kHex20},
    {CGNS_ENUMV(PENTA_15), CellType::kWedge15},  {CGNS_ENUMV(PYRA_13), CellType::kPyramid13},
    {CGNS_ENUMV(PYRA_14), CellType::kPyramid14}, {CGNS_ENUMV(HEXA_27), CellType::kHex27},
    {CGNS_ENUMV(PENTA_18), CellType::kWedge18},
};

bool from_cgns(int cg, CellType* t) {
  for (const CgType& e : kTypes)
    if (static_cast<int>(e.cg) == cg) return *t = e.type, true;
  return false;
}
bool to_cgns(CellType t, CGNS_ENUMT(ElementType_t) * cg) {
  for (const CgType& e : kTypes)
    if (e.type == t) return *cg = e.cg, true;
  return false;
}

// The CGNS position of Gmsh node i (PATRAN's order, node_order.h).
int cg_index(CellType t, int i) { return patran_index_of_gmsh_node(t, i, PatranFormat::kCgns); }

struct CgFile {
  int fn = -1;
  ~CgFile() {
    if (fn >= 0) cg_close(fn);
  }
};

[[noreturn]] void cg_fail(const std::string& path, const std::string& what) {
  // libcgns's message can quote bytes of the file (a zone type name, say): control bytes become
  // '?' and it is cut at 200 characters, so the error stays one printable line (a fuzz finding).
  std::string msg = cg_get_error();
  std::replace(msg.begin(), msg.end(), '\n', ' ');
  for (char& c : msg)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (msg.size() > 200) msg = msg.substr(0, 200) + "...";
  throw Error(path + ": " + what + (msg.empty() ? "" : " (" + msg + ")"));
}

bool tmop_section_name(const char* name, int* region) {
  char rest[64];
  return std::sscanf(name, "Region_%d_%63s", region, rest) == 2;
}

// A named section's region: its "tmop_region" descriptor, else its number S.
int named_section_region(int fn, int Z, int S) {
  int n = 0, region = S;
  if (cg_goto(fn, 1, "Zone_t", Z, "Elements_t", S, "end") != CG_OK || cg_ndescriptors(&n) != CG_OK)
    return region;
  for (int d = 1; d <= n; ++d) {
    char name[64] = {0};
    char* text = nullptr;
    if (cg_descriptor_read(d, name, &text) != CG_OK) continue;
    if (std::strcmp(name, "tmop_region") == 0 && text) std::sscanf(text, "%d", &region);
    if (text) cg_free(text);
  }
  return region;
}

// Adds the cells of section S of zone Z (vertices offset by base, nv of them).
CgSectionCells read_section(const std::string& path, int fn, int Z, int S, cgsize_t base,
                            cgsize_t nv, std::uint64_t file_size, Mesh* mesh) {
  char name[64] = {0};
  CGNS_ENUMT(ElementType_t) type;
  cgsize_t start = 0, end = 0;
  int nbndry = 0, parent = 0;
  if (cg_section_read(fn, 1, Z, S, name, &type, &start, &end, &nbndry, &parent) != CG_OK)
    cg_fail(path, "cannot read element section " + std::to_string(S));
  cgsize_t size = 0;
  if (cg_ElementDataSize(fn, 1, Z, S, &size) != CG_OK || size < 0 ||
      static_cast<std::uint64_t>(size) > file_size)
    cg_fail(path, "bad size of element section " + std::to_string(S));
  std::vector<cgsize_t> data(static_cast<std::size_t>(size));
  if (size > 0 && cg_elements_read(fn, 1, Z, S, data.data(), nullptr) != CG_OK)
    cg_fail(path, "cannot read element section " + std::to_string(S));
  CgSectionCells cells;
  cells.start = start;
  cells.first = mesh->num_cells();
  int region = 0;
  const bool named = !tmop_section_name(name, &region);
  if (named) region = named_section_region(fn, Z, S);
  const bool mixed = type == CGNS_ENUMV(MIXED);
  std::int32_t nodes[kMaxCellNodes];
  for (std::size_t p = 0; p < data.size();) {
    CellType t;
    const int cg = mixed ? static_cast<int>(data[p++]) : static_cast<int>(type);
    if (!from_cgns(cg, &t))
      throw Error(path + ": section '" + name + "': unsupported CGNS element type " +
                  std::to_string(cg));
    const int nn = cell_num_nodes(t);
    if (p + nn > data.size()) throw Error(path + ": section '" + name + "' is truncated");
    for (int i = 0; i < nn; ++i) {
      const cgsize_t v = data[p + cg_index(t, i)];
      if (v < 1 || v > nv)
        throw Error(path + ": section '" + name + "': node " + std::to_string(v) +
                    " is out of range 1.." + std::to_string(nv));
      nodes[i] = static_cast<std::int32_t>(base + v - 1);
    }
    p += nn;
    mesh->add_cell(t, nodes, region, 0);
  }
  if (named && !data.empty())
    mesh->set_physical_name(cell_dim(mesh->cell_types.back()), region, name);
  cells.count = mesh->num_cells() - cells.first;
  return cells;
}

void read_zone(const std::string& path, int fn, int Z, int cell_dim, std::uint64_t file_size,
               Mesh* mesh) {
  CGNS_ENUMT(ZoneType_t) zt;
  if (cg_zone_type(fn, 1, Z, &zt) != CG_OK) cg_fail(path, "cannot read zone " + std::to_string(Z));
  if (zt != CGNS_ENUMV(Unstructured))
    throw Error(path + ": zone " + std::to_string(Z) + " is structured (tmop reads unstructured)");
  char name[64] = {0};
  cgsize_t size[3] = {0, 0, 0};
  if (cg_zone_read(fn, 1, Z, name, size) != CG_OK)
    cg_fail(path, "cannot read zone " + std::to_string(Z));
  const cgsize_t nv = size[0];
  if (nv < 0 || static_cast<std::uint64_t>(nv) * 8 > file_size ||
      mesh->coords.size() / 3 + static_cast<std::uint64_t>(nv) > 0x7fffffff)
    throw Error(path + ": zone '" + std::string(name) + "' declares " + std::to_string(nv) +
                " vertices, more than the file holds");
  const cgsize_t base = static_cast<cgsize_t>(mesh->coords.size() / 3);
  std::vector<double> xyz[3];
  const char* names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  cgsize_t lo = 1, hi = nv;
  for (int k = 0; k < 3; ++k) {
    xyz[k].assign(static_cast<std::size_t>(nv), 0.0);
    if (nv > 0 &&
        cg_coord_read(fn, 1, Z, names[k], CGNS_ENUMV(RealDouble), &lo, &hi, xyz[k].data()) !=
            CG_OK &&
        k < 2)
      cg_fail(path, std::string("cannot read ") + names[k]);
  }
  for (cgsize_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) mesh->coords.push_back(xyz[k][static_cast<std::size_t>(v)]);
  int ns = 0;
  if (cg_nsections(fn, 1, Z, &ns) != CG_OK) cg_fail(path, "cannot count the element sections");
  std::vector<CgSectionCells> sections;
  for (int S = 1; S <= ns; ++S)
    sections.push_back(read_section(path, fn, Z, S, base, nv, file_size, mesh));
  read_cgns_bcs(path, fn, Z, cell_dim, file_size, sections, mesh);
}

}  // namespace

void read_cgns(const std::string& path, Mesh* mesh) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw Error(path + ": cannot open the file");
  CgFile f;
  if (cg_open(path.c_str(), CG_MODE_READ, &f.fn) != CG_OK) {
    f.fn = -1;
    cg_fail(path, "not a readable CGNS file");
  }
  int nb = 0;
  if (cg_nbases(f.fn, &nb) != CG_OK || nb < 1) throw Error(path + ": no CGNS base in the file");
  int nz = 0;
  if (cg_nzones(f.fn, 1, &nz) != CG_OK || nz < 1) throw Error(path + ": no zone in the first base");
  char base[64] = {0};
  int cell_dim = 0, phys_dim = 0;
  if (cg_base_read(f.fn, 1, base, &cell_dim, &phys_dim) != CG_OK)
    cg_fail(path, "cannot read the first base");
  mesh->space_dim = 3;
  for (int Z = 1; Z <= nz; ++Z)
    read_zone(path, f.fn, Z, cell_dim, static_cast<std::uint64_t>(st.st_size), mesh);
}

void check_cgns_writable(const Mesh& mesh) {
  CGNS_ENUMT(ElementType_t) cg = CGNS_ENUMV(ElementTypeNull);
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (!to_cgns(mesh.cell_types[c], &cg))
      throw Error(std::string("cannot write ") + cell_name(mesh.cell_types[c]) +
                  " cells to CGNS (cell " + std::to_string(c) + " is the first)");
}

namespace {

// The physical name of the section's region when it can name the section: the region's only
// section, a valid CGNS node name not taken yet and not of tmop's own Region_ form; otherwise
// "Region_R_TYPE".
std::string section_name(const Mesh& mesh, const std::vector<std::pair<int, CellType> >& keys,
                         const std::pair<int, CellType>& k, std::vector<std::string>* used) {
  const std::string plain = "Region_" + std::to_string(k.first) + "_" + cell_name(k.second);
  const std::string* name = mesh.physical_name(cell_dim(k.second), k.first);
  int sections = 0;
  for (const auto& o : keys) sections += o.first == k.first;
  if (!name || sections != 1 || name->empty() || name->size() > 32 ||
      name->find('/') != std::string::npos || name->compare(0, 7, "Region_") == 0 ||
      std::find(used->begin(), used->end(), *name) != used->end())
    return plain;
  used->push_back(*name);
  return *name;
}

// Writes the sections; returns each cell's element number.
std::vector<cgsize_t> write_sections(const std::string& path, int fn, int Z, const Mesh& mesh) {
  std::vector<cgsize_t> number(static_cast<std::size_t>(mesh.num_cells()), 0);
  // (region, type) in order of first appearance, the elements' first: element numbers
  // 1..size[1] are the zone's cells, as VTK's reader (its BC patches) and solvers expect.
  std::vector<std::pair<int, CellType> > keys;
  const int top = mesh.dim();
  for (int pass = 0; pass < 2; ++pass)
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const std::pair<int, CellType> k(mesh.cell_region[c], mesh.cell_types[c]);
      if ((cell_dim(k.second) == top) == (pass == 0) &&
          std::find(keys.begin(), keys.end(), k) == keys.end())
        keys.push_back(k);
    }
  cgsize_t next = 1;
  std::vector<std::string> used;
  for (const auto& k : keys) {
    const int nn = cell_num_nodes(k.second);
    std::vector<cgsize_t> conn;
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (mesh.cell_region[c] != k.first || mesh.cell_types[c] != k.second) continue;
      number[c] = next + static_cast<cgsize_t>(conn.size() / nn);
      const std::size_t at = conn.size();
      conn.resize(at + nn);
      for (int i = 0; i < nn; ++i) conn[at + cg_index(k.second, i)] = mesh.cell(c)[i] + 1;
    }
    const cgsize_t count = static_cast<cgsize_t>(conn.size() / nn);
    CGNS_ENUMT(ElementType_t) cg = CGNS_ENUMV(ElementTypeNull);
    to_cgns(k.second, &cg);
    const std::string name = section_name(mesh, keys, k, &used);
    int S = 0;
    if (cg_section_write(fn, 1, Z, name.c_str(), cg, next, next + count - 1, 0, conn.data(), &S) !=
        CG_OK)
      cg_fail(path, "cannot write section " + name);
    next += count;
    if (name.compare(0, 7, "Region_") == 0) continue;
    if (cg_goto(fn, 1, "Zone_t", Z, "Elements_t", S, "end") != CG_OK ||
        cg_descriptor_write("tmop_region", std::to_string(k.first).c_str()) != CG_OK)
      cg_fail(path, "cannot write the region of section " + name);
  }
  return number;
}

}  // namespace

void write_cgns(const std::string& path, const Mesh& mesh) {
  check_cgns_writable(mesh);
  TempFile tmp(path, "cgns");
  tmp.close_fd();
  {
    CgFile f;
    if (cg_open(tmp.name().c_str(), CG_MODE_WRITE, &f.fn) != CG_OK) {
      f.fn = -1;
      cg_fail(path, "cannot create the CGNS file");
    }
    int B = 0, Z = 0;
    const int top = std::max(1, mesh.dim());
    if (cg_base_write(f.fn, "Base", top, 3, &B) != CG_OK) cg_fail(path, "cannot write");
    cgsize_t size[3] = {mesh.num_vertices(), 0, 0};
    for (int c = 0; c < mesh.num_cells(); ++c) size[1] += cell_dim(mesh.cell_types[c]) == top;
    if (cg_zone_write(f.fn, B, "Zone1", size, CGNS_ENUMV(Unstructured), &Z) != CG_OK)
      cg_fail(path, "cannot write the zone");
    const char* names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
    std::vector<double> x(static_cast<std::size_t>(mesh.num_vertices()));
    for (int k = 0; k < 3; ++k) {
      for (int v = 0; v < mesh.num_vertices(); ++v) x[v] = coord(mesh, v, k);
      int C = 0;
      if (cg_coord_write(f.fn, B, Z, CGNS_ENUMV(RealDouble), names[k], x.data(), &C) != CG_OK)
        cg_fail(path, std::string("cannot write ") + names[k]);
    }
    write_cgns_bcs(path, f.fn, B, Z, mesh, write_sections(path, f.fn, Z, mesh));
    const int fn = f.fn;
    f.fn = -1;
    if (cg_close(fn) != CG_OK) cg_fail(path, "cannot finish the CGNS file");
  }
  tmp.commit();
}

#endif  // TMOP_WITH_CGNS

}  // namespace io
}  // namespace tmop
