// tmop/io/openmesh_io.cc
// Writing .obj .off .ply through OpenMesh 9 (shared library, so its writers register themselves).
// tmop reads these formats itself (surface_read.cc) and reads and writes .stl itself (stl.cc).
//
// The dimension-2 linear cells (tri3, quad4) become faces (these formats hold any polygon; tmop
// has no others); lower-dimensional cells (boundary lines, points) are dropped because OpenMesh
// writes faces only; 3D and quadratic cells are refused, and so is a mesh without faces (the file
// could not be read back) and a face OpenMesh cannot add (non-manifold or inconsistently
// oriented). 2D meshes are written with z = 0 and read back as 2D. Precision: OpenMesh 9 writes
// coordinates as float32 whatever the point type, so these files keep ~7 digits
// (docs/formats.md). GCC 12 reports a false -Wmaybe-uninitialized inside OpenMesh's
// VectorT<double> copies when its templates are instantiated here; the warning is about
// OpenMesh's code, not ours.
#if !defined(__clang__)  // clang has no such warning (and -Werror refuses the unknown name)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tmop/io/formats.h"

namespace tmop {
namespace io {
namespace {

struct DoubleTraits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
typedef OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits> PolyMesh;

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

void check_openmesh_writable(const std::string& ext, const Mesh& mesh) {
  // OpenMesh writes float32: a larger coordinate would be written as inf and not read back (a
  // fuzz finding, tests/fuzz/regressions/obj/).
  const double max = std::numeric_limits<float>::max();
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < mesh.space_dim; ++k)
      if (!(std::abs(mesh.vertex(v)[k]) <= max))
        throw Error("cannot write vertex " + std::to_string(v) + " to ." + ext +
                    ": a coordinate does not fit in float32");
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
