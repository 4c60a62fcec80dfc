// tmop/io/openmesh_io.cc
// Surface formats .obj .off .ply .stl through OpenMesh 9 (shared library, so its readers and
// writers register themselves). Read: OpenMesh::IO::read_mesh into a PolyMesh with double
// coordinates; faces with 3 / 4 vertices become tri3 / quad4 cells, anything else is an error.
// STL stores triangles only (OpenMesh merges equal corner points into shared vertices).
// Precision: OpenMesh 9 passes coordinates through float32 on read and write in all of these
// formats, whatever the point type, so they keep ~7 digits (docs/formats.md). Write: the
// dimension-2 linear cells (tri3, quad4) become faces; lower-dimensional cells (boundary lines,
// points) are dropped because these formats cannot hold them; 3D or quadratic cells are an error.
// Before handing a file to OpenMesh, the declared counts of OFF and PLY headers and the size of a
// binary STL are checked against the file size, because OpenMesh trusts them. GCC 12 reports a
// false -Wmaybe-uninitialized inside OpenMesh's VectorT<double> copies when its templates are
// instantiated here; the warning is about OpenMesh's code, not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"

namespace tmop {
namespace io {
namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> PolyMesh;

std::string lower_ext(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  std::string e = dot == std::string::npos ? "" : path.substr(dot + 1);
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Guards against headers that declare more items than the file can hold.
void check_header(const std::string& path, const std::string& ext) {
  const std::string data = read_file(path);
  Scanner s(path, data);
  if (s.at_end()) s.fail("empty file");
  s.set_pos(0);
  if (ext == "off") {
    const std::string_view first = s.line();
    if (first.find("OFF") == std::string_view::npos) s.fail_at(0, "not an OFF file: expected OFF");
    if (first.find("BINARY") != std::string_view::npos) return;  // counts are binary too
    s.set_pos(0);
    s.token();
    const std::int64_t nv = s.integer(0, 1LL << 40, "vertex count");
    const std::int64_t nf = s.integer(0, 1LL << 40, "face count");
    s.check_count(static_cast<std::uint64_t>(nv), 6, "vertex");
    s.check_count(static_cast<std::uint64_t>(nf), 6, "face");
  } else if (ext == "ply") {
    if (s.token() != "ply") s.fail_at(0, "not a PLY file: expected 'ply'");
    std::string_view t;
    while (s.try_token(&t) && t != "end_header") {
      if (t != "element") continue;
      s.token();
      const std::int64_t n = s.integer(0, 1LL << 40, "element count");
      s.check_count(static_cast<std::uint64_t>(n), 1, "element");
    }
  } else if (ext == "stl") {
    const bool ascii =
        data.compare(0, 5, "solid") == 0 && data.find("facet", 0) != std::string::npos;
    if (!ascii) {
      if (data.size() < 84) s.fail_byte(data.size(), "binary STL shorter than its 84-byte header");
      std::uint32_t n;
      std::memcpy(&n, data.data() + 80, 4);
      if (static_cast<std::uint64_t>(n) * 50 + 84 != data.size())
        s.fail_byte(80, "binary STL declares " + std::to_string(n) + " triangles, the file size " +
                            std::to_string(data.size()) + " does not match");
    }
  }
}

// OpenMesh prints progress ("[OBJWriter] : write file") to stdout and its own diagnostics to
// stderr; tmop reports through Status, so both are silenced while OpenMesh runs (and restored).
class QuietOpenMesh {
 public:
  QuietOpenMesh()
      : log_(omlog().is_enabled()), out_(omout().is_enabled()), err_(omerr().is_enabled()) {
    omlog().disable();
    omout().disable();
    omerr().disable();
  }
  ~QuietOpenMesh() {
    if (log_) omlog().enable();
    if (out_) omout().enable();
    if (err_) omerr().enable();
  }

 private:
  bool log_, out_, err_;
};

}  // namespace

void read_openmesh(const std::string& path, Mesh* mesh) {
  const std::string ext = lower_ext(path);
  check_header(path, ext);
  PolyMesh pm;
  OpenMesh::IO::Options opt;
  QuietOpenMesh quiet;
  if (!OpenMesh::IO::read_mesh(pm, path, opt))
    throw Error(path + ":1: OpenMesh could not parse this ." + ext + " file");
  mesh->space_dim = 3;
  mesh->coords.reserve(3 * pm.n_vertices());
  for (auto vh : pm.vertices()) {
    const auto& p = pm.point(vh);
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]))
        throw Error(path + ":1: vertex " + std::to_string(vh.idx()) +
                    " has a non-finite coordinate");
      mesh->coords.push_back(p[k]);
    }
  }
  std::int32_t nodes[4];
  for (auto fh : pm.faces()) {
    int n = 0;
    for (auto vh : pm.fv_range(fh)) {
      if (n < 4) nodes[n] = vh.idx();
      ++n;
    }
    if (n != 3 && n != 4)
      throw Error(path + ":1: face " + std::to_string(fh.idx()) + " has " + std::to_string(n) +
                  " vertices; tmop reads triangles and quadrilaterals only");
    mesh->add_cell(n == 3 ? CellType::kTri3 : CellType::kQuad4, nodes);
  }
}

void write_openmesh(const std::string& path, const std::string& ext, const Mesh& mesh,
                    const WriteOptions& options) {
  QuietOpenMesh quiet;  // also silences add_face's "complex edge" complaints
  PolyMesh pm;
  std::vector<PolyMesh::VertexHandle> vh(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    vh[v] = pm.add_vertex(PolyMesh::Point(coord(mesh, v, 0), coord(mesh, v, 1), coord(mesh, v, 2)));
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_types[c];
    if (cell_dim(t) < 2) continue;
    if (t != CellType::kTri3 && t != CellType::kQuad4)
      throw Error(std::string("cannot write ") + cell_name(t) + " cells to ." + ext +
                  " (surface formats hold tri3 and quad4 only)");
    std::vector<PolyMesh::VertexHandle> f;
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const int v = mesh.cell(c)[k];
      if (v < 0 || v >= mesh.num_vertices())
        throw Error("cannot write: cell " + std::to_string(c) + " refers to a missing vertex");
      f.push_back(vh[v]);
    }
    if (!pm.add_face(f).is_valid())
      throw Error("cannot write cell " + std::to_string(c) + " to ." + ext +
                  ": OpenMesh needs a manifold, consistently oriented surface");
  }
  OpenMesh::IO::Options opt;
  if (options.binary && ext != "obj") opt += OpenMesh::IO::Options::Binary;
  if (!OpenMesh::IO::write_mesh(pm, path, opt, 17))
    throw Error("OpenMesh could not write the ." + ext + " file");
}

}  // namespace io
}  // namespace tmop
