// tmop/io/stl.cc
// STL, ASCII and binary, read and written by tmop itself. OpenMesh's STL writer leaves a blank
// line inside every facet (meshio rejects such files and Gmsh 4.8 loses facets after it) and
// writes empty facets for quadrilaterals; its reader drops degenerate facets without a word.
// STL has no vertex list: reading merges corners with bit-identical coordinates (-0 = +0) into
// one vertex, numbered in order of first appearance.
//
// ASCII grammar (keywords case-insensitive, whitespace free):
//   solid [name]
//     facet normal nx ny nz
//       outer loop  vertex x y z  vertex x y z  vertex x y z  endloop
//     endfacet ...
//   endsolid [name]
// (several solids may follow each other). Binary: 80-byte header, uint32 triangle count, then per
// triangle 12 little-endian float32 (normal, 3 corners) and a uint16 attribute. A file is binary
// when its size is exactly 84 + 50 * count, otherwise ASCII when it starts with "solid": some
// binary writers put "solid" in the header too.
//
// Writing: tri3 cells only; the facet normal is the unit normal of the corners (0 0 0 for a
// degenerate triangle). ASCII coordinates are written in the shortest form that reads back to the
// same double, so ASCII STL round trips are exact; binary STL holds float32.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

struct Corner {
  double x[3];
  bool operator==(const Corner& o) const {
    return x[0] == o.x[0] && x[1] == o.x[1] && x[2] == o.x[2];
  }
};

struct CornerHash {
  std::size_t operator()(const Corner& c) const {
    std::size_t h = 1469598103934665603ull;
    for (double v : c.x) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, 8);
      h = (h ^ bits) * 1099511628211ull;
    }
    return h;
  }
};

// Collects triangles, merging equal corners.
class TriangleSoup {
 public:
  TriangleSoup(Mesh* mesh, SurfaceRepair* repair) : mesh_(mesh), repair_(repair) {}
  // Returns false when two corners are equal (a degenerate facet tmop cannot hold as a tri3),
  // unless repairing: then the facet is dropped (and counted) before any of its corners is added.
  bool add(Corner c[3]) {
    for (int k = 0; k < 3; ++k)
      for (double& v : c[k].x) v += 0.0;  // -0 becomes +0, so both merge
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) {
      if (!repair_) return false;
      ++repair_->dropped_degenerate;
      return true;
    }
    std::int32_t nodes[3];
    for (int k = 0; k < 3; ++k) {
      auto it = index_.find(c[k]);
      if (it == index_.end()) {
        it = index_.emplace(c[k], mesh_->add_vertex(c[k].x)).first;
      }
      nodes[k] = it->second;
    }
    mesh_->add_cell(CellType::kTri3, nodes);
    return true;
  }

 private:
  Mesh* mesh_;
  SurfaceRepair* repair_;
  std::unordered_map<Corner, std::int32_t, CornerHash> index_;
};

bool keyword_is(std::string_view t, const char* k) {
  const std::size_t n = std::strlen(k);
  if (t.size() != n) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(t[i])) != k[i]) return false;
  return true;
}

void read_ascii(Scanner* s, Mesh* mesh, SurfaceRepair* repair) {
  TriangleSoup soup(mesh, repair);
  std::string_view t;
  // expect(): the next token must be keyword k.
  auto expect = [&](const char* k) {
    const std::size_t at = (s->skip_space(), s->pos());
    if (!s->try_token(&t))
      s->fail_at(at, std::string("unexpected end of file, expected '") + k + "'");
    if (!keyword_is(t, k))
      s->fail_at(at, std::string("expected '") + k + "', got '" + printable(t) + "'");
  };
  int solids = 0;
  while (!s->at_end()) {
    expect("solid");
    s->skip_line();  // the solid's name
    ++solids;
    for (;;) {
      const std::size_t at = (s->skip_space(), s->pos());
      if (!s->try_token(&t)) s->fail_at(at, "unexpected end of file, expected 'endsolid'");
      if (keyword_is(t, "endsolid")) {
        s->skip_line();
        break;
      }
      if (!keyword_is(t, "facet"))
        s->fail_at(at, "expected 'facet' or 'endsolid', got '" + printable(t) + "'");
      expect("normal");
      // Normals are not used (tmop computes its own); they must be numbers, but some writers
      // put nan for degenerate facets, so they need not be finite.
      for (int k = 0; k < 3; ++k) {
        const std::size_t np = (s->skip_space(), s->pos());
        const std::string_view n = s->token();
        double v;
        const char* b = n.data() + (n[0] == '+');
        auto r = std::from_chars(b, n.data() + n.size(), v);
        if (r.ptr != n.data() + n.size() ||
            (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
          s->fail_at(np, "expected a normal component, got '" + printable(n) + "'");
      }
      expect("outer");
      expect("loop");
      Corner c[3];
      int corners = 0;
      for (;;) {
        const std::size_t vp = (s->skip_space(), s->pos());
        if (!s->try_token(&t)) s->fail_at(vp, "unexpected end of file, expected 'endloop'");
        if (keyword_is(t, "endloop")) break;
        if (!keyword_is(t, "vertex"))
          s->fail_at(vp, "expected 'vertex' or 'endloop', got '" + printable(t) + "'");
        if (corners == 3)
          s->fail_at(vp, "facet has more than 3 vertices; STL facets are triangles");
        for (double& x : c[corners].x) x = s->real("coordinate");
        ++corners;
      }
      if (corners < 3)
        s->fail_at(at, "facet has " + std::to_string(corners) + " vertices, expected 3");
      expect("endfacet");
      if (!soup.add(c)) s->fail_at(at, "facet has two equal corners (a degenerate triangle)");
    }
  }
  if (solids == 0 || mesh->num_cells() == 0) s->fail_at(0, "no facets");
}

void read_binary(Scanner* s, Mesh* mesh, SurfaceRepair* repair) {
  const std::string_view d = s->data();
  if (d.size() < 84) s->fail_byte(d.size(), "binary STL shorter than its 84-byte header");
  std::uint32_t n;
  std::memcpy(&n, d.data() + 80, 4);
  if (static_cast<std::uint64_t>(n) * 50 + 84 != d.size())
    s->fail_byte(80, "binary STL declares " + std::to_string(n) + " triangles, the file size " +
                         std::to_string(d.size()) + " does not match");
  if (n == 0) s->fail_byte(80, "no triangles");
  TriangleSoup soup(mesh, repair);
  mesh->coords.reserve(static_cast<std::size_t>(n) * 3);  // at most 3 per triangle, usually 1/2
  for (std::uint32_t f = 0; f < n; ++f) {
    const std::size_t rec = 84 + static_cast<std::size_t>(f) * 50;
    Corner c[3];
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) {
        const std::size_t at = rec + 12 + 12 * k + 4 * j;
        float v;
        std::memcpy(&v, d.data() + at, 4);
        if (!std::isfinite(v))
          s->fail_byte(at, "coordinate of triangle " + std::to_string(f) + " is not finite");
        c[k].x[j] = v;
      }
    if (!soup.add(c))
      s->fail_byte(
          rec, "triangle " + std::to_string(f) + " has two equal corners (a degenerate triangle)");
  }
}

// The unit normal of a triangle, 0 for a degenerate one.
void normal(const Mesh& mesh, const std::int32_t* n, double out[3]) {
  double u[3], v[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = coord(mesh, n[1], k) - coord(mesh, n[0], k);
    v[k] = coord(mesh, n[2], k) - coord(mesh, n[0], k);
  }
  out[0] = u[1] * v[2] - u[2] * v[1];
  out[1] = u[2] * v[0] - u[0] * v[2];
  out[2] = u[0] * v[1] - u[1] * v[0];
  const double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  for (int k = 0; k < 3; ++k) out[k] = len > 0 ? out[k] / len : 0.0;
}

}  // namespace

namespace {

// Binary STL: two vertices of triangles that differ as doubles but are one point in float32
// would be merged by the next read (a fuzz finding: an ASCII STL read and written binary lost a
// vertex), so they are refused like the corners of one triangle.
void check_float32_distinct(const Mesh& mesh) {
  std::unordered_map<Corner, std::int32_t, CornerHash> seen;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_types[c] != CellType::kTri3) continue;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = mesh.cell(c)[k];
      Corner f{{0, 0, 0}}, d{{0, 0, 0}};
      for (int j = 0; j < 3; ++j) {
        d.x[j] = coord(mesh, v, j) + 0.0;
        f.x[j] = static_cast<double>(static_cast<float>(d.x[j])) + 0.0;
      }
      const auto it = seen.emplace(f, v);
      if (it.second || it.first->second == v) continue;
      Corner e{{0, 0, 0}};
      for (int j = 0; j < 3; ++j) e.x[j] = coord(mesh, it.first->second, j) + 0.0;
      if (!(e == d))
        throw Error("cannot write to binary .stl: vertices " + std::to_string(it.first->second) +
                    " and " + std::to_string(v) +
                    " are one point in float32 (STL keeps corners by coordinates: the file would "
                    "not read back)");
    }
  }
}

}  // namespace

void check_stl_writable(const Mesh& mesh, const WriteOptions& options) {
  int triangles = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_types[c];
    if (cell_dim(t) < 2) continue;  // boundary lines and points: STL has no place for them
    if (t != CellType::kTri3)
      throw Error(std::string("cannot write ") + cell_name(t) +
                  " cells to .stl (STL holds linear triangles only; cell " + std::to_string(c) +
                  " is the first)");
    ++triangles;
  }
  if (triangles == 0) throw Error("cannot write a mesh without triangles to .stl");
  // STL stores each triangle's corners by their coordinates; a reader (tmop's too) cannot hold
  // a triangle with two equal corners, so such a file would not read back. Compared as written:
  // float32 in binary STL (corners 1e-9 apart collapse), exact doubles in ASCII. Equal vertices
  // in different triangles are fine: the reader merges them into one.
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_types[c] != CellType::kTri3) continue;
    double x[3][3];
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) {
        const double v = coord(mesh, mesh.cell(c)[k], j);
        x[k][j] = (options.binary ? static_cast<double>(static_cast<float>(v)) : v) + 0.0;
      }
    for (int k = 0; k < 3; ++k) {
      const int l = (k + 1) % 3;
      if (x[k][0] == x[l][0] && x[k][1] == x[l][1] && x[k][2] == x[l][2])
        throw Error("cannot write triangle " + std::to_string(c) + " to " +
                    (options.binary ? "binary .stl: its vertices " : ".stl: its vertices ") +
                    std::to_string(mesh.cell(c)[k]) + " and " + std::to_string(mesh.cell(c)[l]) +
                    (options.binary ? " are one point in float32" : " are one point") +
                    " (STL keeps corners by coordinates: the file would not read back)");
    }
  }
  if (options.binary) check_float32_distinct(mesh);
  if (options.binary) {
    const double max = std::numeric_limits<float>::max();
    for (int v = 0; v < mesh.num_vertices(); ++v)
      for (int k = 0; k < mesh.space_dim; ++k)
        if (!(std::abs(mesh.vertex(v)[k]) <= max))
          throw Error("cannot write vertex " + std::to_string(v) +
                      " to binary .stl: a coordinate does not fit in float32");
  }
}

void read_stl(const std::string& path, const std::string& data, Mesh* mesh, SurfaceRepair* repair) {
  mesh->space_dim = 3;
  Scanner s(path, data);
  if (s.at_end()) s.fail_at(0, "empty file");
  std::uint32_t n = 0;
  if (data.size() >= 84) std::memcpy(&n, data.data() + 80, 4);
  const bool binary_size =
      data.size() >= 84 && static_cast<std::uint64_t>(n) * 50 + 84 == data.size();
  s.set_pos(0);
  s.skip_space();
  std::string_view first;
  const bool solid = !binary_size && s.try_token(&first) && keyword_is(first, "solid");
  s.set_pos(0);
  if (solid)
    read_ascii(&s, mesh, repair);
  else
    read_binary(&s, mesh, repair);
}

void write_stl(const Mesh& mesh, const WriteOptions& options, std::string* out) {
  check_stl_writable(mesh, options);
  double nrm[3];
  if (options.binary) {
    std::string header = "tmop binary STL";  // must not start with "solid"
    header.resize(80, '\0');
    out->append(header);
    std::uint32_t n = 0;
    for (CellType t : mesh.cell_types) n += t == CellType::kTri3;
    append_binary(out, n);
    for (int c = 0; c < mesh.num_cells(); ++c) {
      if (mesh.cell_types[c] != CellType::kTri3) continue;
      normal(mesh, mesh.cell(c), nrm);
      for (double x : nrm) append_binary(out, static_cast<float>(x));
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
          append_binary(out, static_cast<float>(coord(mesh, mesh.cell(c)[k], j)));
      append_binary(out, std::uint16_t{0});
    }
    return;
  }
  out->append("solid tmop\n");
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_types[c] != CellType::kTri3) continue;
    normal(mesh, mesh.cell(c), nrm);
    out->append("facet normal");
    for (double x : nrm) {
      out->push_back(' ');
      append_double(out, x);
    }
    out->append("\n  outer loop\n");
    for (int k = 0; k < 3; ++k) {
      out->append("    vertex");
      for (int j = 0; j < 3; ++j) {
        out->push_back(' ');
        append_double(out, coord(mesh, mesh.cell(c)[k], j));
      }
      out->push_back('\n');
    }
    out->append("  endloop\nendfacet\n");
  }
  out->append("endsolid tmop\n");
}

}  // namespace io
}  // namespace tmop
