// tmop/io/ugrid.cc
// AFLR3 / UG_IO UGRID (.ugrid), from the UG_IO "UGRID 3D Grid File Type" page: a header of seven
// counts (nodes, boundary trias, boundary quads, tets, pyramids ("pents 5"), prisms ("pents 6"),
// hexes), then x y z per node, the boundary trias, the boundary quads, one surface ID per
// boundary face (trias first), then the tets, pyramids, prisms and hexes, node indices 1-based.
// Optional trailing records (reconnection flags, boundary conditions, ...) are ignored.
//
// The encoding is named by the suffix before .ugrid, as AFLR3 does:
//   NAME.ugrid      ASCII
//   NAME.b8.ugrid   C binary (no record marks), big-endian, 8-byte reals, 4-byte integers
//   NAME.lb8.ugrid  the same, little-endian
//   NAME.r8.ugrid   Fortran unformatted, big-endian: two records (the header; the rest), each
//                   framed by 4-byte byte counts
//   NAME.lr8.ugrid  the same, little-endian
// Other AFLR3 variants (b4, lb4, r4, lr4: 4-byte reals; b8l, lb8l: 8-byte integers) are refused
// with a message naming the supported ones.
//
// Tags: surface IDs <-> Mesh::cell_region of the tri3 / quad4 cells. The format has no volume
// IDs, so volume cells read back with region 0 (the writer drops their regions). Cells read back
// grouped: trias, quads, tets, pyramids, prisms, hexes.
//
// Node order (tmop = Gmsh, element/cell_type.h): tets, prisms, hexes, trias and quads are
// identical (the UGRID prism is right-handed like its tet: base 1 2 3 counter-clockwise seen from
// 4 5 6, unlike VTK's wedge); the UGRID pyramid has its apex third and its base 1 2 5 4, so Gmsh
// node i = UGRID node kBlocks' perm[i] = {1, 0, 3, 4, 2}[i]. This is meshio 5's reading of UGRID
// (tested both ways in tests/io/ugrid_test.cc); tests/data/ugrid/cells.ugrid holds one valid cell
// of each type, written by hand in that order, and each reads with positive corner Jacobians.
#include <cctype>
#include <cmath>
#include <limits>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();

struct Block {
  CellType type;
  int perm[8];  // Gmsh node i = UGRID node perm[i]
};
// In file order: trias, quads (faces with surface IDs), then the volume cells.
const Block kBlocks[6] = {
    {CellType::kTri3, {0, 1, 2}},
    {CellType::kQuad4, {0, 1, 2, 3}},
    {CellType::kTet4, {0, 1, 2, 3}},
    {CellType::kPyramid5, {1, 0, 3, 4, 2}},
    {CellType::kWedge6, {0, 1, 2, 3, 4, 5}},
    {CellType::kHex8, {0, 1, 2, 3, 4, 5, 6, 7}},
};

struct Variant {
  bool binary = false;
  bool swap = false;     // big-endian on this (little-endian) host
  bool fortran = false;  // record marks
};

// The encoding from the suffix before ".ugrid" (case-insensitive); throws Error("UGRID variant
// ...") without the path for the variants tmop does not read or write.
Variant variant_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t last = name.find_last_of('.');
  std::string suffix;
  if (last != std::string::npos && last > 0) {
    const std::size_t prev = name.find_last_of('.', last - 1);
    if (prev != std::string::npos) suffix = name.substr(prev + 1, last - prev - 1);
  }
  for (char& c : suffix) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  Variant v;
  if (suffix == "b8" || suffix == "lb8" || suffix == "r8" || suffix == "lr8") {
    v.binary = true;
    v.swap = suffix[0] != 'l';
    v.fortran = suffix.back() == '8' && suffix.find('r') != std::string::npos;
  } else if (suffix == "b4" || suffix == "lb4" || suffix == "r4" || suffix == "lr4" ||
             suffix == "b8l" || suffix == "lb8l" || suffix == "r8l" || suffix == "lr8l") {
    throw Error("UGRID variant ." + suffix +
                ".ugrid is not supported (ASCII .ugrid, .b8, .lb8, .r8 and .lr8 are)");
  }
  return v;
}

class UgridReader {
 public:
  UgridReader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {
    try {
      v_ = variant_of(path);
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
  }

  void read() {
    if (s_.data().empty()) s_.fail_at(0, "empty file");
    // meshio 5 writes 56 (the byte count of its int64 header array) before its 28 bytes.
    if (v_.fortran) record_mark(28, "header record mark", 56);
    std::int64_t count[7];
    const char* names[7] = {"number of nodes",          "number of boundary trias",
                            "number of boundary quads", "number of tets",
                            "number of pyramids",       "number of prisms",
                            "number of hexes"};
    for (int k = 0; k < 7; ++k) count[k] = integer(0, kMaxInt32 - 1, names[k]);
    if (v_.fortran) record_mark(28, "header record mark", 56);
    check_size(count);
    const std::int64_t nv = count[0];
    if (v_.fortran) record_mark(-1, "data record mark");
    mesh_->space_dim = 3;
    mesh_->coords.resize(static_cast<std::size_t>(3 * nv));
    for (double& x : mesh_->coords) x = real();
    for (int b = 0; b < 6; ++b) read_block(kBlocks[b], count[b + 1], nv);
  }

 private:
  std::int64_t integer(std::int64_t lo, std::int64_t hi, const char* what) {
    if (!v_.binary) return s_.integer(lo, hi, what);
    const std::size_t p = s_.pos();
    const std::int64_t x = s_.binary<std::int32_t>(v_.swap, what);
    if (x < lo || x > hi)
      s_.fail_byte(p, std::string(what) + " " + std::to_string(x) + " is out of range [" +
                          std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return x;
  }
  double real() {
    if (!v_.binary) return s_.real("coordinate");
    const std::size_t p = s_.pos();
    const double x = s_.binary<double>(v_.swap, "coordinate");
    if (!std::isfinite(x)) s_.fail_byte(p, "coordinate is not finite");
    return x;
  }
  // A Fortran record mark: the byte count of the record (bytes < 0: any count; also_ok: a
  // second accepted value).
  void record_mark(std::int64_t bytes, const char* what, std::int64_t also_ok = -1) {
    const std::size_t p = s_.pos();
    const std::int64_t m = s_.binary<std::int32_t>(v_.swap, what);
    if (bytes >= 0 && m != bytes && m != also_ok)
      s_.fail_byte(p, std::string(what) + " is " + std::to_string(m) + ", expected " +
                          std::to_string(bytes));
  }

  // Hostile headers: the declared counts must fit in the file before anything is allocated.
  void check_size(const std::int64_t* count) {
    std::uint64_t ints = 0;
    for (int b = 0; b < 6; ++b)
      ints +=
          static_cast<std::uint64_t>(count[b + 1]) * (cell_num_nodes(kBlocks[b].type) + (b < 2));
    const std::uint64_t reals = 3 * static_cast<std::uint64_t>(count[0]);
    if (v_.binary) {
      const std::uint64_t need = reals * 8 + ints * 4 + (v_.fortran ? 8 : 0);
      if (need > s_.remaining())
        s_.fail_byte(s_.pos(), "the header declares " + std::to_string(need) +
                                   " bytes of data, the file has " +
                                   std::to_string(s_.remaining()) + " left (truncated?)");
    } else {
      s_.check_count(reals + ints, 2, "value");
    }
  }

  void read_block(const Block& b, std::int64_t n, std::int64_t nv) {
    const int nn = cell_num_nodes(b.type);
    const bool face = cell_dim(b.type) == 2;
    std::int32_t ugrid[8], gmsh[8];
    for (std::int64_t c = 0; c < n; ++c) {
      for (int i = 0; i < nn; ++i)
        ugrid[i] = static_cast<std::int32_t>(integer(1, nv, "node index") - 1);
      for (int i = 0; i < nn; ++i) gmsh[i] = ugrid[b.perm[i]];
      mesh_->add_cell(b.type, gmsh, 0, 0);
    }
    // After the quads come the surface IDs of all faces.
    if (face && b.type == CellType::kQuad4) {
      const int nfaces = mesh_->num_cells();
      mesh_->cell_region.resize(static_cast<std::size_t>(nfaces), 0);
      for (int f = 0; f < nfaces; ++f)
        mesh_->cell_region[f] =
            static_cast<std::int32_t>(integer(-kMaxInt32, kMaxInt32, "surface ID"));
    }
  }

  Scanner s_;
  Mesh* mesh_;
  Variant v_;
};

bool ugrid_type(CellType t) {
  for (const Block& b : kBlocks)
    if (b.type == t) return true;
  return false;
}

class UgridWriter {
 public:
  UgridWriter(const Mesh& mesh, const Variant& v, std::string* out)
      : mesh_(mesh), v_(v), out_(out) {}

  void write() {
    std::int32_t count[7] = {mesh_.num_vertices(), 0, 0, 0, 0, 0, 0};
    for (CellType t : mesh_.cell_types)
      for (int b = 0; b < 6; ++b) count[b + 1] += kBlocks[b].type == t;
    if (v_.fortran) mark(28);
    for (int k = 0; k < 7; ++k) integer(count[k], k == 6 ? '\n' : ' ');
    if (v_.fortran) mark(28);
    std::uint64_t bytes = 24 * static_cast<std::uint64_t>(count[0]);
    for (int b = 0; b < 6; ++b)
      bytes += 4 * static_cast<std::uint64_t>(count[b + 1]) *
               (cell_num_nodes(kBlocks[b].type) + (b < 2));
    if (v_.fortran && bytes > static_cast<std::uint64_t>(kMaxInt32))
      throw Error("cannot write a Fortran UGRID record of more than 2 GiB");
    if (v_.fortran) mark(static_cast<std::int32_t>(bytes));
    for (int v = 0; v < mesh_.num_vertices(); ++v)
      for (int k = 0; k < 3; ++k) real(coord(mesh_, v, k), k == 2 ? '\n' : ' ');
    for (int b = 0; b < 6; ++b) {
      cells(kBlocks[b]);
      if (b == 1) surface_ids();
    }
    if (v_.fortran) mark(static_cast<std::int32_t>(bytes));
  }

 private:
  void integer(std::int32_t x, char sep) {
    if (v_.binary) {
      append_binary(out_, x, v_.swap);
    } else {
      append_int(out_, x);
      out_->push_back(sep);
    }
  }
  void real(double x, char sep) {
    if (v_.binary) {
      append_binary(out_, x, v_.swap);
    } else {
      append_double(out_, x);
      out_->push_back(sep);
    }
  }
  void mark(std::int32_t bytes) { append_binary(out_, bytes, v_.swap); }

  void cells(const Block& b) {
    const int nn = cell_num_nodes(b.type);
    for (int c = 0; c < mesh_.num_cells(); ++c) {
      if (mesh_.cell_types[c] != b.type) continue;
      std::int32_t ugrid[8];
      for (int i = 0; i < nn; ++i) ugrid[b.perm[i]] = mesh_.cell(c)[i];
      for (int i = 0; i < nn; ++i) integer(ugrid[i] + 1, i + 1 == nn ? '\n' : ' ');
    }
  }
  void surface_ids() {
    for (CellType t : {CellType::kTri3, CellType::kQuad4})
      for (int c = 0; c < mesh_.num_cells(); ++c)
        if (mesh_.cell_types[c] == t) integer(mesh_.cell_region[c], '\n');
  }

  const Mesh& mesh_;
  Variant v_;
  std::string* out_;
};

}  // namespace

void read_ugrid(const std::string& path, const std::string& data, Mesh* mesh) {
  UgridReader(path, data, mesh).read();
}

void check_ugrid_writable(const std::string& path, const Mesh& mesh) {
  variant_of(path);
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (!ugrid_type(mesh.cell_types[c]))
      throw Error(std::string("cannot write ") + cell_name(mesh.cell_types[c]) +
                  " cells to UGRID (it holds tri3, quad4, tet4, pyramid5, wedge6 and hex8; cell " +
                  std::to_string(c) + " is the first)");
}

void write_ugrid(const std::string& path, const Mesh& mesh, std::string* out) {
  check_ugrid_writable(path, mesh);
  UgridWriter(mesh, variant_of(path), out).write();
}

}  // namespace io
}  // namespace tmop
