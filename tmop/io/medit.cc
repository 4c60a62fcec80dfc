// tmop/io/medit.cc
// Medit / INRIA .mesh, ASCII (MeshVersionFormatted 1 or 2, Dimension 2 or 3). Each element keyword
// is followed by a count and rows of node indices (1-based) plus a reference, which maps to
// Mesh::cell_region. Vertex references go to point_data "medit:ref" (meshio's name) so they
// round-trip. Corners, Ridges, Required*, Normals and Tangents sections are skipped.
//
// Node order: Gmsh's own .mesh writer, reading its output back, and meshio all use the Gmsh order
// for Edges, Triangles, Quadrilaterals, Tetrahedra, Hexahedra, Prisms, Pyramids, EdgesP2 and
// TrianglesP2; TetrahedraP2 has mid-edge nodes 8 and 9 swapped (checked against Gmsh 4.8's output
// for the same elements as .msh). Cells are written grouped by keyword, in the table order below,
// so a mixed mesh reads back grouped by type.
#include <cmath>
#include <limits>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();

struct Keyword {
  const char* name;
  CellType type;
  int perm[10];  // Medit node i is Gmsh node perm[i]; empty = identity
  bool permuted;
};

const Keyword kKeywords[] = {
    {"Edges", CellType::kLine2, {}, false},
    {"EdgesP2", CellType::kLine3, {}, false},
    {"Triangles", CellType::kTri3, {}, false},
    {"TrianglesP2", CellType::kTri6, {}, false},
    {"Quadrilaterals", CellType::kQuad4, {}, false},
    {"Tetrahedra", CellType::kTet4, {}, false},
    {"TetrahedraP2", CellType::kTet10, {0, 1, 2, 3, 4, 5, 6, 7, 9, 8}, true},
    {"Pyramids", CellType::kPyramid5, {}, false},
    {"Prisms", CellType::kWedge6, {}, false},
    {"Hexahedra", CellType::kHex8, {}, false},
};

// Sections tmop does not use, with the number of values per row (-1: space dimension).
struct Skipped {
  const char* name;
  int values;
};
const Skipped kSkipped[] = {
    {"Corners", 1},
    {"RequiredVertices", 1},
    {"Ridges", 1},
    {"RequiredEdges", 1},
    {"RequiredTriangles", 1},
    {"RequiredQuadrilaterals", 1},
    {"RequiredTetrahedra", 1},
    {"Normals", -1},
    {"NormalAtVertices", 2},
    {"Tangents", -1},
    {"TangentAtVertices", 2},
    {"TangentAtEdges", 3},
};

class MeditReader {
 public:
  MeditReader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {}

  void read() {
    if (s_.at_end()) s_.fail("empty file");
    std::string_view t;
    bool have_vertices = false;
    bool have_version = false;
    while (next_keyword(&t)) {
      const std::size_t p = s_.pos() - t.size();
      if (t == "MeshVersionFormatted") {
        s_.integer(1, 4, "mesh version");
        have_version = true;
      } else if (t == "Dimension") {
        // A second Vertices or Dimension section would leave the first one's data behind
        // (two medit:ref arrays, coordinates of another dimension): refused.
        if (dim_ != 0) s_.fail_at(p, "repeated Dimension section");
        dim_ = static_cast<int>(s_.integer(2, 3, "dimension"));
      } else if (t == "Vertices") {
        if (dim_ == 0) s_.fail_at(p, "Vertices before Dimension");
        if (have_vertices) s_.fail_at(p, "repeated Vertices section");
        read_vertices();
        have_vertices = true;
      } else if (t == "End") {
        break;
      } else if (const Keyword* k = find_keyword(t)) {
        if (!have_vertices) s_.fail_at(p, std::string(t) + " before Vertices");
        if (cell_dim(k->type) > dim_)
          s_.fail_at(
              p, std::string(t) + " (3D cells) in a Dimension " + std::to_string(dim_) + " file");
        read_cells(*k);
      } else if (const Skipped* sk = find_skipped(t)) {
        const std::int64_t n = s_.integer(0, kMaxInt32, "count");
        const int values = sk->values < 0 ? dim_ : sk->values;
        s_.check_count(static_cast<std::uint64_t>(n), 2 * values, "row");
        for (std::int64_t i = 0; i < n * values; ++i) s_.token();
      } else {
        s_.fail_at(p, "unknown keyword '" + printable(t) + "'");
      }
      if (!have_version) s_.fail_at(p, "not a Medit file: expected MeshVersionFormatted first");
    }
    if (!have_vertices) s_.fail("no Vertices section");
  }

 private:
  bool next_keyword(std::string_view* t) {
    while (s_.try_token(t)) {
      if ((*t)[0] != '#') return true;
      s_.skip_line();
    }
    return false;
  }
  static const Keyword* find_keyword(std::string_view t) {
    for (const Keyword& k : kKeywords)
      if (t == k.name) return &k;
    return nullptr;
  }
  static const Skipped* find_skipped(std::string_view t) {
    for (const Skipped& k : kSkipped)
      if (t == k.name) return &k;
    return nullptr;
  }

  void read_vertices() {
    const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of vertices");
    s_.check_count(static_cast<std::uint64_t>(n), 2 * (dim_ + 1), "vertex");
    mesh_->coords.resize(static_cast<std::size_t>(3 * n), 0.0);
    DataArray refs{"medit:ref", 1, std::vector<double>(static_cast<std::size_t>(n))};
    for (std::int64_t v = 0; v < n; ++v) {
      for (int k = 0; k < dim_; ++k)
        mesh_->coords[static_cast<std::size_t>(3 * v + k)] = s_.real("coordinate");
      refs.values[static_cast<std::size_t>(v)] =
          static_cast<double>(s_.integer(-kMaxInt32, kMaxInt32, "vertex reference"));
    }
    nv_ = n;
    mesh_->point_data.push_back(std::move(refs));
  }

  void read_cells(const Keyword& k) {
    const int nn = cell_num_nodes(k.type);
    const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of cells");
    s_.check_count(static_cast<std::uint64_t>(n), 2 * (nn + 1), "cell");
    std::int32_t nodes[kMaxCellNodes];
    for (std::int64_t c = 0; c < n; ++c) {
      for (int i = 0; i < nn; ++i) {
        const std::int64_t v = s_.integer(1, nv_, "vertex index");
        nodes[k.permuted ? k.perm[i] : i] = static_cast<std::int32_t>(v - 1);
      }
      const std::int64_t ref = s_.integer(-kMaxInt32, kMaxInt32, "reference");
      mesh_->add_cell(k.type, nodes, static_cast<int>(ref), 0);
    }
  }

  Scanner s_;
  Mesh* mesh_;
  int dim_ = 0;
  std::int64_t nv_ = 0;
};

}  // namespace

void read_medit(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  MeditReader(path, data, mesh).read();
}

void check_medit_writable(const Mesh& mesh) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    bool known = false;
    for (const Keyword& k : kKeywords) known |= k.type == mesh.cell_types[c];
    if (!known)
      throw Error(std::string("cannot write ") + cell_name(mesh.cell_types[c]) +
                  " cells to Medit .mesh (cell " + std::to_string(c) + " is the first)");
  }
}

void write_medit(const Mesh& mesh, const WriteOptions& options, std::string* out) {
  // A planar mesh off z = 0 is written in 3D, so its plane survives.
  const int d = mesh.space_dim == 2 && mesh.plane_z != 0 ? 3 : mesh.space_dim;
  check_medit_writable(mesh);
  const DataArray* refs = nullptr;
  for (const DataArray& a : mesh.point_data)
    if (a.name == "medit:ref" && a.components == 1 &&
        a.values.size() == static_cast<std::size_t>(mesh.num_vertices()))
      refs = &a;
  // "Dimension" and its value on two lines, as Gmsh writes it: Gmsh 4.8's reader takes the line
  // after "Dimension" as the value and recognises only "Dimension 3" on one line, so a one-line
  // "Dimension 2" made it skip the Vertices keyword ("Wrong node index 0"). meshio and tmop
  // read both forms.
  out->append("MeshVersionFormatted 2\nDimension\n");
  append_int(out, d);
  out->append("\nVertices\n");
  append_int(out, mesh.num_vertices());
  out->push_back('\n');
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    for (int k = 0; k < d; ++k) {
      append_double(out, coord(mesh, v, k));
      out->push_back(' ');
    }
    append_int(out, refs ? static_cast<std::int64_t>(refs->values[v]) : 0);
    out->push_back('\n');
  }
  for (const Keyword& k : kKeywords) {
    int count = 0;
    for (CellType t : mesh.cell_types) count += t == k.type;
    if (count == 0) continue;
    out->append(k.name);
    out->push_back('\n');
    append_int(out, count);
    out->push_back('\n');
    const int nn = cell_num_nodes(k.type);
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (mesh.cell_types[c] != k.type) continue;
      for (int i = 0; i < nn; ++i) {
        append_int(out, mesh.cell(c)[k.permuted ? k.perm[i] : i] + 1);
        out->push_back(' ');
      }
      append_int(out, mesh.cell_region[c]);
      out->push_back('\n');
    }
  }
  out->append("End\n");
}

}  // namespace io
}  // namespace tmop
