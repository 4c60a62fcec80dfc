// tmop/io/vtk.cc
// VTK legacy format, DATASET UNSTRUCTURED_GRID (and, on read, POLYDATA with VERTICES / LINES /
// POLYGONS of 1 / 2 / 3-4 points), ASCII or BINARY (big-endian, as the format requires). Reads both
// cell layouts: "CELLS n size" with [npts, ids...] rows (versions <= 4.2) and "CELLS nOffsets
// nConn" + OFFSETS / CONNECTIVITY arrays (version 5.1, what meshio writes). Attributes read:
// SCALARS (1-4 components, LOOKUP_TABLE line), VECTORS, NORMALS, TENSORS and FIELD arrays, into
// Mesh::point_data / cell_data; tag arrays and dataset-level FIELD names per vtk_common.h. The
// writer is vtk_write.cc. Node order converted by node_order.h. Array names are read with VTK's
// "%XX" decoding.
#include <cmath>
#include <limits>

#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"
#include "tmop/io/vtk_common.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();

int type_size(std::string_view t) {
  if (t == "unsigned_char" || t == "char" || t == "bit") return 1;
  if (t == "unsigned_short" || t == "short") return 2;
  if (t == "unsigned_int" || t == "int" || t == "float") return 4;
  if (t == "unsigned_long" || t == "long" || t == "double" || t == "vtktypeint64" ||
      t == "vtktypeuint64" || t == "vtkIdType")
    return 8;
  return 0;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// VTK's name encoding (vtkDataWriter::EncodeString): %XX for a space, '%', '"' and bytes outside
// printable ASCII, so any name is one token.
std::string decode_name(std::string_view n) {
  std::string out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (n[i] == '%' && i + 2 < n.size() && hex_digit(n[i + 1]) >= 0 && hex_digit(n[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hex_digit(n[i + 1]) * 16 + hex_digit(n[i + 2])));
      i += 2;
    } else {
      out.push_back(n[i]);
    }
  }
  return out;
}

class VtkReader {
 public:
  VtkReader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {}

  void read() {
    if (s_.at_end()) s_.fail("empty file");
    s_.set_pos(0);
    const std::string_view header = s_.line();
    if (header.rfind("# vtk DataFile Version", 0) != 0)
      s_.fail_at(0, "not a VTK legacy file: first line must be '# vtk DataFile Version x.y'");
    s_.line();  // title
    s_.skip_space();
    const std::size_t fpos = s_.pos();
    const std::string_view format = s_.line();
    if (format.rfind("ASCII", 0) == 0)
      binary_ = false;
    else if (format.rfind("BINARY", 0) == 0)
      binary_ = true;
    else
      s_.fail_at(fpos, "expected ASCII or BINARY");
    keyword("DATASET");
    const std::size_t dpos = (s_.skip_space(), s_.pos());
    const std::string_view dataset = s_.token();
    const bool poly = dataset == "POLYDATA";
    if (dataset != "UNSTRUCTURED_GRID" && !poly)
      s_.fail_at(dpos, "only DATASET UNSTRUCTURED_GRID and POLYDATA are supported");
    bool have_points = false, have_cells = false, have_types = false;
    std::vector<std::int64_t> offsets, conn, types;
    if (poly) {  // cells come from VERTICES / LINES / POLYGONS sections, types from row lengths
      offsets.assign(1, 0);
      have_cells = have_types = true;
    }
    std::vector<DataArray> field;
    std::string_view t;
    while (s_.try_token(&t)) {
      const std::size_t p = s_.pos() - t.size();
      if (t == "POINTS") {
        const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of points");
        const std::string_view type = value_type();
        check_count(n * 3, type);
        std::vector<double> xyz;
        read_reals(n * 3, type, &xyz, "point coordinate");
        mesh_->coords = std::move(xyz);
        have_points = true;
      } else if (poly && (t == "VERTICES" || t == "LINES" || t == "POLYGONS")) {
        cells_pos_ = types_pos_ = p;
        flat_ = types_at_ = offsets_at_ = conn_at_ = ValuesAt();
        read_poly_section(t, p, &offsets, &conn, &types);
      } else if (t == "CELLS" && !poly) {
        cells_pos_ = p;
        read_cells(&offsets, &conn);
        have_cells = true;
      } else if (t == "CELL_TYPES") {
        types_pos_ = p;
        const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of cell types");
        if (binary_) s_.skip_line();
        check_count(n, "int");
        types_at_ = values_at("int");
        read_ints(n, "int", &types, "cell type");
        have_types = true;
      } else if (t == "CELL_DATA" || t == "POINT_DATA") {
        const bool cell = t == "CELL_DATA";
        const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of data items");
        read_attributes(n, cell ? &mesh_->cell_data : &mesh_->point_data);
      } else if (t == "FIELD") {  // dataset-level field data: physical names (vtk_common.h)
        read_field(-1, &field);
      } else if (t == "METADATA") {
        skip_metadata();
      } else {
        s_.fail_at(p, "unexpected keyword '" + printable(t) + "'");
      }
    }
    if (!have_points) s_.fail("no POINTS section");
    if (have_cells != have_types) s_.fail("CELLS and CELL_TYPES must both be present");
    build_cells(offsets, conn, types);
    for (const DataArray& a : mesh_->point_data)
      if (a.values.size() != mesh_->coords.size() / 3 * a.components)
        s_.fail("POINT_DATA array '" + printable(a.name) + "' does not have one value per point");
    for (const DataArray& a : mesh_->cell_data)
      if (a.values.size() != mesh_->cell_types.size() * a.components)
        s_.fail("CELL_DATA array '" + printable(a.name) + "' does not have one value per cell");
    std::string bad;
    if (!extract_tag_arrays(mesh_, &bad))
      s_.fail("tag array '" + bad + "' must hold one integer per cell");
    names_from_field_data(field, mesh_);
  }

 private:
  void keyword(const char* k) {
    const std::size_t p = (s_.skip_space(), s_.pos());
    std::string_view t;
    if (!s_.try_token(&t)) s_.fail(std::string("unexpected end of file, expected ") + k);
    if (t != k) s_.fail_at(p, std::string("expected ") + k + ", got '" + printable(t) + "'");
  }

  std::string_view value_type() {
    const std::size_t p = (s_.skip_space(), s_.pos());
    const std::string_view type = s_.token();
    if (type_size(type) == 0) s_.fail_at(p, "unknown data type '" + printable(type) + "'");
    if (binary_) s_.skip_line();
    return type;
  }

  void check_count(std::int64_t n, std::string_view type) {
    if (binary_)
      s_.check_count_binary(static_cast<std::uint64_t>(n), type_size(type), "value");
    else
      s_.check_count(static_cast<std::uint64_t>(n), 2, "value");
  }

  double binary_value(std::string_view type, const char* what) {
    const int size = type_size(type);
    if (type == "float") return s_.binary<float>(true, what);
    if (type == "double") return s_.binary<double>(true, what);
    if (type == "char") return s_.binary<std::int8_t>(true, what);
    if (type == "unsigned_char" || type == "bit") return s_.binary<std::uint8_t>(true, what);
    if (type == "short") return s_.binary<std::int16_t>(true, what);
    if (type == "unsigned_short") return s_.binary<std::uint16_t>(true, what);
    if (type == "int") return s_.binary<std::int32_t>(true, what);
    if (type == "unsigned_int") return s_.binary<std::uint32_t>(true, what);
    if (type == "unsigned_long" || type == "vtktypeuint64")
      return static_cast<double>(s_.binary<std::uint64_t>(true, what));
    (void)size;
    return static_cast<double>(s_.binary<std::int64_t>(true, what));
  }

  // finite: refuse NaN and infinities (coordinates; data values keep them: VTK writes NaN where
  // a value does not apply, and the arrays' users check what they take).
  void read_reals(std::int64_t n, std::string_view type, std::vector<double>* out, const char* what,
                  bool finite = true) {
    out->resize(static_cast<std::size_t>(n));
    if (binary_ && type == "double") {  // the common case, without per-value type dispatch
      for (std::int64_t i = 0; i < n; ++i) {
        const std::size_t p = s_.pos();
        const double v = s_.binary<double>(true, what);
        if (finite && !std::isfinite(v)) s_.fail_byte(p, std::string(what) + " is not finite");
        (*out)[static_cast<std::size_t>(i)] = v;
      }
      return;
    }
    for (std::int64_t i = 0; i < n; ++i) {
      const std::size_t p = s_.pos();
      const double v = binary_ ? binary_value(type, what) : s_.real(what, finite);
      if (finite && !std::isfinite(v)) s_.fail_byte(p, std::string(what) + " is not finite");
      (*out)[static_cast<std::size_t>(i)] = v;
    }
  }

  void read_ints(std::int64_t n, std::string_view type, std::vector<std::int64_t>* out,
                 const char* what) {
    out->resize(static_cast<std::size_t>(n));
    if (binary_ && type == "int") {  // the common case, without per-value type dispatch
      for (std::int64_t i = 0; i < n; ++i)
        (*out)[static_cast<std::size_t>(i)] = s_.binary<std::int32_t>(true, what);
      return;
    }
    for (std::int64_t i = 0; i < n; ++i) {
      if (binary_) {
        const std::size_t p = s_.pos();
        const double v = binary_value(type, what);
        if (v != std::floor(v) || std::fabs(v) > 9e15)
          s_.fail_byte(p, std::string(what) + " is not an integer");
        (*out)[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(v);
      } else {
        (*out)[static_cast<std::size_t>(i)] =
            s_.integer(std::numeric_limits<std::int64_t>::min(),
                       std::numeric_limits<std::int64_t>::max(), what);
      }
    }
  }

  void read_cells(std::vector<std::int64_t>* offsets, std::vector<std::int64_t>* conn) {
    const std::int64_t a = s_.integer(0, kMaxInt32, "number of cells");
    const std::int64_t b =
        s_.integer(0, std::numeric_limits<std::int64_t>::max(), "cell list size");
    const std::size_t save = s_.pos();
    std::string_view t;
    if (s_.try_token(&t) && t == "OFFSETS") {  // version 5.1 layout
      const std::string_view otype = value_type();
      check_count(a, otype);
      offsets_at_ = values_at(otype);
      read_ints(a, otype, offsets, "cell offset");
      keyword("CONNECTIVITY");
      const std::string_view ctype = value_type();
      check_count(b, ctype);
      conn_at_ = values_at(ctype);
      flat_ = ValuesAt();
      read_ints(b, ctype, conn, "cell node index");
      if (!offsets->empty() && ((*offsets)[0] != 0 || offsets->back() != b))
        s_.fail("OFFSETS must start at 0 and end at the CONNECTIVITY size");
      return;
    }
    s_.set_pos(save);
    if (binary_) s_.skip_line();
    check_count(b, "int");
    flat_ = values_at("int");
    offsets_at_ = conn_at_ = ValuesAt();
    std::vector<std::int64_t> flat;
    read_ints(b, "int", &flat, "cell list entry");
    offsets->assign(1, 0);
    conn->clear();
    conn->reserve(static_cast<std::size_t>(b));
    std::size_t i = 0;
    for (std::int64_t c = 0; c < a; ++c) {
      if (i >= flat.size())
        s_.fail("CELLS list is shorter than its " + std::to_string(a) + " cells");
      const std::int64_t npts = flat[i++];
      if (npts < 0 || static_cast<std::uint64_t>(npts) > flat.size() - i)
        s_.fail("cell " + std::to_string(c) + " has a bad node count " + std::to_string(npts));
      conn->insert(conn->end(), flat.begin() + static_cast<std::ptrdiff_t>(i),
                   flat.begin() + static_cast<std::ptrdiff_t>(i + npts));
      i += static_cast<std::size_t>(npts);
      offsets->push_back(static_cast<std::int64_t>(conn->size()));
    }
    if (i != flat.size()) s_.fail("CELLS size " + std::to_string(b) + " does not match its rows");
  }

  // POLYDATA: each row's length decides its cell type; only the shapes tmop has are accepted
  // (no poly-vertices, polylines, polygons beyond quads, triangle strips).
  void read_poly_section(std::string_view name, std::size_t pos, std::vector<std::int64_t>* offsets,
                         std::vector<std::int64_t>* conn, std::vector<std::int64_t>* types) {
    std::vector<std::int64_t> off, cn;
    read_cells(&off, &cn);
    for (std::size_t c = 0; c + 1 < off.size(); ++c) {
      const std::int64_t n = off[c + 1] - off[c];
      int vtk = 0;
      if (name == "VERTICES" && n == 1) vtk = 1;
      if (name == "LINES" && n == 2) vtk = 3;
      if (name == "POLYGONS" && n == 3) vtk = 5;
      if (name == "POLYGONS" && n == 4) vtk = 9;
      if (vtk == 0)
        s_.fail_at(pos, std::string(name) + " row " + std::to_string(c) + " has " +
                            std::to_string(n) +
                            " points; tmop reads single vertices, 2-point lines, triangles and "
                            "quadrilaterals");
      types->push_back(vtk);
      for (std::int64_t k = off[c]; k < off[c + 1]; ++k)
        conn->push_back(cn[static_cast<std::size_t>(k)]);
      offsets->push_back(static_cast<std::int64_t>(conn->size()));
    }
  }

  void build_cells(const std::vector<std::int64_t>& offsets, const std::vector<std::int64_t>& conn,
                   const std::vector<std::int64_t>& types) {
    const std::size_t ncells = offsets.empty() ? 0 : offsets.size() - 1;
    if (types.size() != ncells)
      s_.fail("CELL_TYPES has " + std::to_string(types.size()) + " entries for " +
              std::to_string(ncells) + " cells");
    const std::int64_t nv = static_cast<std::int64_t>(mesh_->coords.size() / 3);
    std::int32_t nodes[kMaxCellNodes];
    mesh_->cell_types.reserve(ncells);
    for (std::size_t c = 0; c < ncells; ++c) {
      CellType type;
      // The range check comes first: a cast of 2^32 + 9 to int would make it a quad.
      if (types[c] < 0 || types[c] > 255 || !cell_type_from_vtk(static_cast<int>(types[c]), &type))
        fail_value(types_at_, static_cast<std::int64_t>(c), types_pos_,
                   "cell " + std::to_string(c) + ": unsupported VTK cell type " +
                       std::to_string(types[c]) + io::unsupported_vtk_type_note(types[c]));
      const std::int64_t b = offsets[c], e = offsets[c + 1];
      // Where cell c's node count is: OFFSETS[c + 1] (5.1), its count entry in a legacy list.
      const bool flat = flat_.start != kNoPos;
      if (e - b != cell_num_nodes(type) || b < 0 || e > static_cast<std::int64_t>(conn.size()))
        fail_value(
            flat ? flat_ : offsets_at_, flat ? b + static_cast<std::int64_t>(c) : e, cells_pos_,
            "cell " + std::to_string(c) + " (" + cell_name(type) + ") has " +
                std::to_string(e - b) + " nodes, expected " + std::to_string(cell_num_nodes(type)));
      const int* p = gmsh_index_of_vtk_node(type);
      for (int i = 0; i < cell_num_nodes(type); ++i) {
        const std::int64_t v = conn[static_cast<std::size_t>(b + i)];
        if (v < 0 || v >= nv)
          fail_value(flat ? flat_ : conn_at_, b + i + (flat ? static_cast<std::int64_t>(c) + 1 : 0),
                     cells_pos_,
                     "cell " + std::to_string(c) + " refers to point " + std::to_string(v) +
                         ", out of range 0.." + std::to_string(nv - 1));
        nodes[p[i]] = static_cast<std::int32_t>(v);
      }
      mesh_->add_cell(type, nodes);
    }
  }

  void add_array(std::string name, int comps, std::int64_t n, std::string_view type,
                 std::vector<DataArray>* out) {
    check_count(n * comps, type);
    DataArray a;
    a.name = std::move(name);
    a.components = comps;
    read_reals(n * comps, type, &a.values, "data value", /*finite=*/false);
    out->push_back(std::move(a));
  }

  // Reads attribute blocks until the next section keyword.
  void read_attributes(std::int64_t n, std::vector<DataArray>* out) {
    std::string_view t;
    while (true) {
      const std::size_t save = s_.pos();
      if (!s_.try_token(&t)) return;
      const std::size_t p = s_.pos() - t.size();
      if (t == "SCALARS") {
        const std::string name = decode_name(s_.token());
        const std::size_t tp = (s_.skip_space(), s_.pos());
        const std::string_view type = s_.token();
        if (type_size(type) == 0) s_.fail_at(tp, "unknown data type '" + printable(type) + "'");
        // Optional component count on the same line.
        int comps = 1;
        const std::string_view rest = s_.line();
        if (!rest.empty()) {
          Scanner r(s_.path(), rest);
          std::string_view c;
          if (r.try_token(&c)) {
            if (c.size() != 1 || c[0] < '1' || c[0] > '4')
              s_.fail_at(tp, "SCALARS component count must be 1..4");
            comps = c[0] - '0';
          }
        }
        const std::size_t lp = (s_.skip_space(), s_.pos());
        std::string_view lt;
        if (s_.try_token(&lt) && lt == "LOOKUP_TABLE") {
          s_.token();
          if (binary_) s_.skip_line();
        } else {
          s_.set_pos(lp);
        }
        add_array(name, comps, n, type, out);
      } else if (t == "VECTORS" || t == "NORMALS" || t == "TENSORS") {
        const std::string name = decode_name(s_.token());
        const std::string_view type = value_type();
        add_array(name, t == "TENSORS" ? 9 : 3, n, type, out);
      } else if (t == "FIELD") {
        read_field(n, out);
      } else if (t == "LOOKUP_TABLE") {
        s_.token();
        const std::int64_t size = s_.integer(0, kMaxInt32, "lookup table size");
        if (binary_) s_.skip_line();
        check_count(4 * size, binary_ ? "unsigned_char" : "float");
        std::vector<double> ignored;
        read_reals(4 * size, binary_ ? "unsigned_char" : "float", &ignored, "lookup table value");
      } else if (t == "METADATA") {
        skip_metadata();
      } else if (t == "COLOR_SCALARS" || t == "TEXTURE_COORDINATES") {
        s_.fail_at(p, std::string(t) + " attributes are not supported");
      } else {
        s_.set_pos(save);
        return;
      }
    }
  }

  // n < 0: dataset-level field, any tuple counts.
  void read_field(std::int64_t n, std::vector<DataArray>* out) {
    s_.token();  // field name
    const std::int64_t k = s_.integer(0, 100000, "number of field arrays");
    for (std::int64_t i = 0; i < k; ++i) {
      s_.skip_space();
      const std::size_t p = s_.pos();
      const std::string name = decode_name(s_.token());
      const std::int64_t comps = s_.integer(1, 1000, "number of components");
      const std::int64_t tuples = s_.integer(0, kMaxInt32, "number of tuples");
      const std::string_view type = value_type();
      if (n >= 0 && tuples != n)
        s_.fail_at(p, "field array '" + printable(name) + "' has " + std::to_string(tuples) +
                          " tuples, expected " + std::to_string(n));
      add_array(name, static_cast<int>(comps), tuples, type, out);
      skip_metadata_if_present();
    }
  }

  void skip_metadata_if_present() {
    const std::size_t save = s_.pos();
    std::string_view t;
    if (s_.try_token(&t) && t == "METADATA")
      skip_metadata();
    else
      s_.set_pos(save);
  }

  // METADATA blocks end at an empty line.
  void skip_metadata() {
    s_.skip_line();
    while (s_.remaining() > 0) {
      std::string_view l = s_.line();
      bool blank = true;
      for (char c : l) blank &= is_space(c);
      if (blank) return;
    }
  }

  Scanner s_;
  Mesh* mesh_;
  bool binary_ = false;
  std::size_t cells_pos_ = 0;  // where CELLS / CELL_TYPES start: cell errors point there
  std::size_t types_pos_ = 0;  // (when the value's own place is unknown: POLYDATA sections)
  // Where the values of an array start and, in binary files, each value's size: errors in cell
  // c point at its value (fail_value), found again only when an error is raised.
  static constexpr std::size_t kNoPos = static_cast<std::size_t>(-1);
  struct ValuesAt {
    std::size_t start = kNoPos;
    int size = 0;  // bytes per value; 0 in ASCII
  };
  ValuesAt types_at_, offsets_at_, conn_at_, flat_;  // flat_: a legacy CELLS list

  ValuesAt values_at(std::string_view type) {
    ValuesAt a;
    a.start = s_.pos();
    a.size = binary_ ? type_size(type) : 0;
    return a;
  }

  // Fails at value `index` of the array at `a` (at `fallback`, a section, when unknown).
  [[noreturn]] void fail_value(const ValuesAt& a, std::int64_t index, std::size_t fallback,
                               const std::string& what) {
    if (a.start == kNoPos || index < 0) s_.fail_at(fallback, what);
    if (a.size > 0) s_.fail_byte(a.start + static_cast<std::size_t>(index) * a.size, what);
    Scanner sc(s_.path(), s_.data());
    sc.set_pos(a.start);
    std::string_view t;
    for (std::int64_t i = 0; i < index && sc.try_token(&t); ++i) {
    }
    sc.skip_space();
    s_.fail_at(sc.pos(), what);
  }
};

}  // namespace

void read_vtk(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  VtkReader(path, data, mesh).read();
}

}  // namespace io
}  // namespace tmop
