// tmop/io/su2.cc
// SU2 native mesh (.su2), ASCII (reference: the "Mesh File" page of the SU2 documentation).
// Lines are `KEYWORD= value`; `%` starts a comment line. NDIME (2 or 3), NELEM then one line per
// element "VTK-type node ... [index]", NPOIN ("N" or "N N-domain") then one line per point
// "x y [z] [index ...]", NMARK then per marker MARKER_TAG= name, MARKER_ELEMS= count and its
// boundary elements. Nodes are 0-based; cell types and node order are VTK's (line 3, triangle 5,
// quadrilateral 9, tetrahedron 10, hexahedron 12, prism 13, pyramid 14; node_order.h converts
// the prism). Sections may come in any order (meshio writes NPOIN first), so node indices are
// checked once every section is read. Multi-zone files (NZONE > 1) are refused.
//
// Markers <-> boundary cells: marker cells get a physical tag per marker: the marker's own number
// when its name is a non-negative integer (meshio writes its tags so), otherwise the largest such
// number + 1, + 2, ... in order of appearance, whose Mesh::physical_names entry (dimension
// NDIME - 1) is the marker name. Writing does the
// reverse: one marker per region of the cells of dimension dim() - 1, named by its physical name
// or, without one, by the region number. Element cells (NELEM) carry no tags in SU2; vertex cells
// and cells of lower dimension are not written.
#include <algorithm>
#include <charconv>
#include <limits>
#include <map>
#include <vector>

#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool su2_type(CellType t) {
  switch (t) {
    case CellType::kLine2:
    case CellType::kTri3:
    case CellType::kQuad4:
    case CellType::kTet4:
    case CellType::kHex8:
    case CellType::kWedge6:
    case CellType::kPyramid5:
      return true;
    default:
      return false;
  }
}

// A non-negative integer name ("3"): the marker's own tag.
bool integer_name(std::string_view s, int* v) {
  if (s.empty()) return false;
  auto r = std::from_chars(s.data(), s.data() + s.size(), *v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && *v >= 0;
}

class Su2Reader {
 public:
  Su2Reader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {}

  void read() {
    if (s_.at_end()) s_.fail("empty file");
    bool have_points = false, have_elems = false;
    while (!s_.at_end()) {
      const std::size_t p = s_.pos();
      const std::string_view l = s_.line();
      if (trim(l).empty() || trim(l)[0] == '%') continue;
      const std::size_t eq = l.find('=');
      if (eq == std::string_view::npos)
        s_.fail_at(p, "expected 'KEYWORD= value', got '" + printable(trim(l)) + "'");
      const std::string_view key = trim(l.substr(0, eq));
      value_ = trim(l.substr(eq + 1));
      value_pos_ = static_cast<std::size_t>(value_.data() - s_.data().data());
      if (key == "NDIME") {
        ndime_ = static_cast<int>(value(2, 3, "NDIME"));
      } else if (key == "NZONE") {
        if (value(1, kMaxInt32, "NZONE") != 1)
          s_.fail_at(p, "multi-zone SU2 files are not supported (NZONE must be 1)");
      } else if (key == "IZONE") {
        value(1, 1, "IZONE");
      } else if (key == "NPOIN") {
        if (have_points) s_.fail_at(p, "second NPOIN section");
        read_points();
        have_points = true;
      } else if (key == "NELEM") {
        if (have_elems) s_.fail_at(p, "second NELEM section");
        read_cells(ndim(), 0);
        have_elems = true;
      } else if (key == "NMARK") {
        nmark_ = value(0, kMaxInt32, "NMARK");
        nmark_pos_ = p;
        s_.check_count(static_cast<std::uint64_t>(nmark_), 28, "marker");
      } else if (key == "MARKER_TAG") {
        start_marker(p);
      } else if (key == "MARKER_ELEMS") {
        if (!in_marker_) s_.fail_at(p, "MARKER_ELEMS without a MARKER_TAG before it");
        in_marker_ = false;
        read_cells(ndim() - 1, marker_tag_);
      } else {
        s_.fail_at(p, "unknown keyword '" + printable(key) + "'");
      }
    }
    if (!have_points) s_.fail("no NPOIN section");
    if (!have_elems) s_.fail("no NELEM section");
    if (markers_ != nmark_)
      s_.fail_at(nmark_pos_, "NMARK says " + std::to_string(nmark_) + " markers, the file has " +
                                 std::to_string(markers_));
    check_nodes();
    finish_tags();
  }

 private:
  int ndim() {
    if (ndime_ == 0) s_.fail_at(value_pos_, "NDIME must come before the elements and points");
    return ndime_;
  }

  // The integer after '=' (the whole value unless rest_ok: NPOIN may have a second count).
  std::int64_t value(std::int64_t lo, std::int64_t hi, const char* what, bool rest_ok = false) {
    Scanner v(s_.path(), s_.data().substr(0, value_pos_ + value_.size()));
    v.set_pos(value_pos_);
    const std::int64_t x = v.integer(lo, hi, what);
    if (!rest_ok && !v.at_end()) v.fail(std::string("unexpected text after ") + what);
    return x;
  }

  // A Scanner over the next non-empty line, with the file's line numbers.
  Scanner next_line(const char* what) {
    while (true) {
      if (s_.at_end()) s_.fail(std::string("unexpected end of file, expected ") + what);
      const std::size_t p = s_.pos();
      const std::string_view l = s_.line();
      if (trim(l).empty() || trim(l)[0] == '%') continue;
      Scanner sc(s_.path(), s_.data().substr(0, p + l.size()));
      sc.set_pos(p);
      return sc;
    }
  }

  void read_points() {
    // "NPOIN= N" or "NPOIN= N N-domain" (partitioned meshes): the first count is all points.
    const std::int64_t n = value(0, kMaxInt32 - 1, "NPOIN", true);
    s_.check_count(static_cast<std::uint64_t>(n), 2 * ndim(), "point");
    mesh_->coords.reserve(static_cast<std::size_t>(n) * 3);
    for (std::int64_t i = 0; i < n; ++i) {
      Scanner l = next_line("a point");
      for (int k = 0; k < ndime_; ++k) mesh_->coords.push_back(l.real("coordinate"));
      if (ndime_ == 2) mesh_->coords.push_back(0.0);
    }
  }

  void read_cells(int dim, int region) {
    const std::int64_t n = value(0, kMaxInt32 - 1, dim == ndime_ ? "NELEM" : "MARKER_ELEMS");
    s_.check_count(static_cast<std::uint64_t>(n), 6, "element");
    mesh_->cell_types.reserve(mesh_->cell_types.size() + static_cast<std::size_t>(n));
    std::int32_t nodes[kMaxCellNodes];
    for (std::int64_t i = 0; i < n; ++i) {
      Scanner l = next_line("an element");
      l.skip_space();
      const std::size_t p = l.pos();
      const std::int64_t vtk = l.integer(0, 255, "VTK cell type");
      CellType t;
      if (!cell_type_from_vtk(static_cast<int>(vtk), &t) || !su2_type(t))
        l.fail_at(p, "unsupported SU2 element type " + std::to_string(vtk) +
                         " (SU2 has 3 line, 5 triangle, 9 quadrilateral, 10 tetrahedron, 12 "
                         "hexahedron, 13 prism, 14 pyramid)");
      if (cell_dim(t) != dim)
        l.fail_at(p, std::string(cell_name(t)) + " (dimension " + std::to_string(cell_dim(t)) +
                         ") in a section of dimension-" + std::to_string(dim) + " cells");
      const int* perm = gmsh_index_of_vtk_node(t);
      for (int k = 0; k < cell_num_nodes(t); ++k)
        nodes[perm[k]] = static_cast<std::int32_t>(l.integer(0, kMaxInt32 - 1, "node index"));
      mesh_->add_cell(t, nodes, region, 0);
      cell_pos_.push_back(p);
    }
  }

  // Integer-named markers tag their cells with the number; named ones with -(ordinal) until
  // finish_tags() knows the largest number.
  void start_marker(std::size_t p) {
    if (in_marker_) s_.fail_at(p, "MARKER_TAG without MARKER_ELEMS after the previous one");
    if (value_.empty()) s_.fail_at(p, "empty MARKER_TAG");
    ++markers_;
    in_marker_ = true;
    int tag = 0;
    if (integer_name(value_, &tag)) {
      top_ = std::max(top_, tag);
    } else {
      auto it = std::find(names_.begin(), names_.end(), value_);
      if (it == names_.end()) it = names_.insert(names_.end(), std::string(value_));
      tag = -static_cast<int>(it - names_.begin()) - 1;
    }
    marker_tag_ = tag;
  }

  void finish_tags() {
    for (std::int32_t& r : mesh_->cell_region)
      if (r < 0) r = top_ - r;
    for (std::size_t i = 0; i < names_.size(); ++i)
      mesh_->set_physical_name(ndime_ - 1, top_ + static_cast<int>(i) + 1, names_[i]);
  }

  void check_nodes() {
    const std::int64_t nv = static_cast<std::int64_t>(mesh_->coords.size() / 3);
    for (int c = 0; c < mesh_->num_cells(); ++c)
      for (int k = 0; k < mesh_->cell_size(c); ++k)
        if (mesh_->cell(c)[k] >= nv)
          s_.fail_at(cell_pos_[c], "node index " + std::to_string(mesh_->cell(c)[k]) +
                                       " out of range 0.." + std::to_string(nv - 1));
  }

  Scanner s_;
  Mesh* mesh_;
  int ndime_ = 0;
  std::string_view value_;
  std::size_t value_pos_ = 0;
  std::int64_t nmark_ = 0, markers_ = 0;
  std::size_t nmark_pos_ = 0;
  bool in_marker_ = false;
  int marker_tag_ = 0;
  int top_ = 0;                     // largest integer marker name
  std::vector<std::string> names_;  // the other marker names, in order
  std::vector<std::size_t> cell_pos_;
};

void cell_line(const Mesh& mesh, int c, std::string* out) {
  const CellType t = mesh.cell_types[c];
  append_int(out, vtk_cell_type(t));
  const int* perm = gmsh_index_of_vtk_node(t);
  for (int k = 0; k < cell_num_nodes(t); ++k) {
    out->push_back(' ');
    append_int(out, mesh.cell(c)[perm[k]]);
  }
}

}  // namespace

void read_su2(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  Su2Reader(path, data, mesh).read();
}

void check_su2_writable(const Mesh& mesh) {
  const int d = mesh.dim();
  if (d < 2 || (d == 2 && mesh.space_dim != 2))
    throw Error(
        "cannot write to SU2: it holds planar 2D meshes and 3D volume meshes (this mesh has " +
        std::to_string(d) + "D cells in " + std::to_string(mesh.space_dim) + "D)");
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_types[c];
    if (cell_dim(t) >= d - 1 && !su2_type(t))
      throw Error(std::string("cannot write ") + cell_name(t) +
                  " cells to SU2 (linear cells only; " + "cell " + std::to_string(c) +
                  " is the first)");
    if (cell_dim(t) != d - 1) continue;
    const std::string* name = mesh.physical_name(d - 1, mesh.cell_region[c]);
    if (name && (name->empty() || name->find_first_of(" \t\r\n=%") != std::string::npos))
      throw Error("cannot write marker name '" + printable(*name) +
                  "' to SU2 (marker tags cannot be empty or hold spaces, '=' or '%')");
  }
}

void write_su2(const Mesh& mesh, std::string* out) {
  check_su2_writable(mesh);
  const int d = mesh.dim();
  const int n = mesh.num_vertices();
  int nelem = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) nelem += cell_dim(mesh.cell_types[c]) == d;
  out->append("% written by tmop\nNDIME= " + std::to_string(d) + "\nNELEM= ");
  append_int(out, nelem);
  out->push_back('\n');
  int index = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_types[c]) != d) continue;
    cell_line(mesh, c, out);
    out->push_back(' ');
    append_int(out, index++);
    out->push_back('\n');
  }
  out->append("NPOIN= ");
  append_int(out, n);
  out->push_back('\n');
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < d; ++k) {
      append_double(out, coord(mesh, v, k));
      out->push_back(' ');
    }
    append_int(out, v);
    out->push_back('\n');
  }
  // Markers in order of first appearance of their region.
  std::vector<int> regions;
  std::map<int, std::vector<int>> cells;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_types[c]) != d - 1) continue;
    const int r = mesh.cell_region[c];
    if (!cells.count(r)) regions.push_back(r);
    cells[r].push_back(c);
  }
  out->append("NMARK= " + std::to_string(regions.size()) + "\n");
  for (int r : regions) {
    const std::string* name = mesh.physical_name(d - 1, r);
    out->append("MARKER_TAG= " + (name ? *name : std::to_string(r)) + "\nMARKER_ELEMS= ");
    append_int(out, static_cast<std::int64_t>(cells[r].size()));
    out->push_back('\n');
    for (int c : cells[r]) {
      cell_line(mesh, c, out);
      out->push_back('\n');
    }
  }
}

}  // namespace io
}  // namespace tmop
