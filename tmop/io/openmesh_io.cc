// tmop/io/openmesh_io.cc
// Surface formats .obj .off .ply through OpenMesh 9 (shared library, so its readers and writers
// register themselves); .stl is tmop's own (stl.cc).
//
// Read: scan_surface (surface_scan.h) validates the whole file first and reports the first
// problem with its line or byte, because OpenMesh reports no positions and silently drops or
// alters what it cannot use. Then OpenMesh::IO::read_mesh reads it into a PolyMesh with double
// coordinates, and its faces must agree with the scan's; the cells are built from the scan's
// faces (tri3 / quad4) and OpenMesh's coordinates of the file's vertices. OpenMesh adds copies of
// the vertices of a face that would make an edge or vertex non-manifold; those copies are not
// used, so such surfaces read as they are in the file.
// Precision: OpenMesh 9 passes coordinates through float32 on read and write in all of these
// formats, whatever the point type, so they keep ~7 digits (docs/formats.md).
//
// Write: the dimension-2 linear cells (tri3, quad4) become faces (these formats hold any
// polygon; tmop has no others); lower-dimensional cells (boundary lines, points) are dropped
// because OpenMesh writes faces only; 3D and quadratic cells are refused, and so is a mesh
// without faces (the file could not be read back) and a face OpenMesh cannot add (non-manifold or
// inconsistently oriented). 2D meshes are written with z = 0 and read back as 2D. GCC 12 reports
// a false -Wmaybe-uninitialized inside OpenMesh's VectorT<double> copies when its templates are
// instantiated here; the warning is about OpenMesh's code, not ours.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <stdlib.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"
#include "tmop/io/surface_scan.h"

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

// The OFF text OpenMesh gets, as the scan read it, with byte offsets unchanged: every comment ('#'
// at the start of a token, to the end of its line) blanked out and the counts moved off the
// header line. OpenMesh's OFF reader knows neither (meshio writes a comment; "OFF 8 6 0" is
// common): it reads an empty mesh, after seconds of parsing for some files.
std::string off_text_for_openmesh(const std::string& data) {
  std::string out = data;
  bool token_start = true;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] == '#' && token_start) {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
      token_start = true;
      continue;
    }
    token_start = is_space(out[i]);
  }
  // The first token is the header keyword (the scan checked it); the character after it becomes
  // the line break OpenMesh expects.
  std::size_t i = 0;
  while (i < out.size() && is_space(out[i])) ++i;
  while (i < out.size() && !is_space(out[i])) ++i;
  if (i < out.size() && out[i] != '\n' && out[i] != '\r') out[i] = '\n';
  return out;
}

// A temporary file holding `text` (none when `skip`), removed when this goes out of scope.
struct TempCopy {
  TempCopy(const std::string& ext, const std::string& text, bool skip) {
    if (skip) return;
    const char* tmpdir = std::getenv("TMPDIR");
    std::string tmpl =
        std::string(tmpdir && *tmpdir ? tmpdir : "/tmp") + "/tmop-read-XXXXXX." + ext;
    const int fd = ::mkstemps(&tmpl[0], static_cast<int>(ext.size() + 1));
    if (fd < 0) throw Error(tmpl + ": cannot create a temporary copy for OpenMesh");
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    path = tmpl;
    if (done != text.size()) throw Error(tmpl + ": cannot write a temporary copy for OpenMesh");
  }
  ~TempCopy() {
    if (!path.empty()) ::unlink(path.c_str());
  }
  TempCopy(const TempCopy&) = delete;
  TempCopy& operator=(const TempCopy&) = delete;
  std::string path;
};

// The PolyMesh of the mesh's faces; throws Error("cannot write ...") for what the format cannot
// hold. Shared by write_openmesh and check_openmesh_writable so that a refusal comes before a
// long optimization, not after it.
void build_polymesh(const std::string& ext, const Mesh& mesh, PolyMesh* pm) {
  QuietOpenMesh quiet;  // also silences add_face's "complex edge" complaints
  int faces = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_types[c];
    if (cell_dim(t) == 3)
      throw Error(std::string("cannot write ") + cell_name(t) + " cells to ." + ext +
                  " (a surface format: faces only; cell " + std::to_string(c) + " is the first)");
    if (cell_dim(t) == 2 && t != CellType::kTri3 && t != CellType::kQuad4)
      throw Error(std::string("cannot write ") + cell_name(t) + " cells to ." + ext +
                  " (linear polygons only: the mid-edge nodes would be lost; cell " +
                  std::to_string(c) + " is the first)");
    faces += cell_dim(t) == 2;
  }
  if (faces == 0) throw Error("cannot write a mesh without triangles or quadrilaterals to ." + ext);
  std::vector<PolyMesh::VertexHandle> vh(mesh.num_vertices());
  for (int v = 0; v < mesh.num_vertices(); ++v)
    vh[v] =
        pm->add_vertex(PolyMesh::Point(coord(mesh, v, 0), coord(mesh, v, 1), coord(mesh, v, 2)));
  std::vector<PolyMesh::VertexHandle> f;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_types[c]) != 2) continue;
    f.clear();
    for (int k = 0; k < mesh.cell_size(c); ++k) f.push_back(vh[mesh.cell(c)[k]]);
    if (!pm->add_face(f).is_valid())
      throw Error("cannot write cell " + std::to_string(c) + " to ." + ext +
                  ": OpenMesh needs a manifold, consistently oriented surface");
  }
}

}  // namespace

void read_openmesh(const std::string& path, Mesh* mesh) {
  const std::string ext = lower_ext(path);
  const std::string data = read_file(path);
  const SurfaceScan scan = scan_surface(path, ext, data);
  PolyMesh pm;
  OpenMesh::IO::Options opt;
  {
    // OpenMesh reads from the path: its stream readers depend on state left by earlier reads
    // (the OFF reader's binary flag), so a changed text goes through a temporary file.
    const std::string text = ext == "off" && !scan.binary ? off_text_for_openmesh(data) : data;
    TempCopy copy(ext, text, text == data);
    QuietOpenMesh quiet;
    if (!OpenMesh::IO::read_mesh(pm, copy.path.empty() ? path : copy.path, opt))
      throw Error(path + ":1: OpenMesh could not parse this ." + ext + " file");
  }
  // OpenMesh must have read what the scan found; a difference is reported, never papered over.
  Scanner s(path, data);
  auto fail_face = [&](std::int64_t f, const std::string& what) {
    if (scan.binary) s.fail_byte(scan.face_pos[static_cast<std::size_t>(f)], what);
    s.fail_at(scan.face_pos[static_cast<std::size_t>(f)], what);
  };
  const std::int64_t nv = scan.num_vertices;
  if (static_cast<std::int64_t>(pm.n_vertices()) < nv ||
      static_cast<std::int64_t>(pm.n_faces()) != scan.num_faces())
    s.fail_at(0, "OpenMesh read " + std::to_string(pm.n_vertices()) + " vertices and " +
                     std::to_string(pm.n_faces()) + " faces, the file has " + std::to_string(nv) +
                     " and " + std::to_string(scan.num_faces()));
  std::int64_t f = 0;
  for (auto fh : pm.faces()) {
    const std::int32_t* want = scan.face_nodes.data() + scan.face_offsets[f];
    const int n = scan.face_offsets[f + 1] - scan.face_offsets[f];
    int k = 0;
    for (auto vh : pm.fv_range(fh)) {
      // A copy OpenMesh made for a non-manifold face must sit where the file's vertex is.
      const bool same =
          k < n && (vh.idx() == want[k] ||
                    (vh.idx() >= nv && pm.point(vh) == pm.point(PolyMesh::VertexHandle(want[k]))));
      if (!same) fail_face(f, "OpenMesh read this face differently from the file");
      ++k;
    }
    if (k != n) fail_face(f, "OpenMesh read this face differently from the file");
    ++f;
  }
  mesh->space_dim = 3;
  mesh->coords.reserve(static_cast<std::size_t>(3 * nv));
  for (std::int64_t v = 0; v < nv; ++v) {
    const auto& p = pm.point(PolyMesh::VertexHandle(static_cast<int>(v)));
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(p[k]))  // the scan checked the text; float32 can still overflow
        throw Error(path + ":1: vertex " + std::to_string(v) +
                    " has a coordinate beyond the float32 range OpenMesh reads");
      mesh->coords.push_back(p[k]);
    }
  }
  for (std::int64_t g = 0; g < scan.num_faces(); ++g) {
    const int n = scan.face_offsets[g + 1] - scan.face_offsets[g];
    mesh->add_cell(n == 3 ? CellType::kTri3 : CellType::kQuad4,
                   scan.face_nodes.data() + scan.face_offsets[g]);
  }
}

void check_openmesh_writable(const std::string& ext, const Mesh& mesh) {
  PolyMesh pm;
  build_polymesh(ext, mesh, &pm);
}

void write_openmesh(const std::string& path, const std::string& ext, const Mesh& mesh,
                    const WriteOptions& options) {
  PolyMesh pm;
  build_polymesh(ext, mesh, &pm);
  QuietOpenMesh quiet;
  OpenMesh::IO::Options opt;
  if (options.binary && ext != "obj") opt += OpenMesh::IO::Options::Binary;
  if (!OpenMesh::IO::write_mesh(pm, path, opt, 17))
    throw Error("OpenMesh could not write the ." + ext + " file");
}

}  // namespace io
}  // namespace tmop
