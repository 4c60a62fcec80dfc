// tmop/io/vtu.cc
// VTK XML UnstructuredGrid (.vtu). Read: one Piece; DataArrays in format "ascii", "binary"
// (base64 inline) and "appended" with encoding "raw"; byte_order LittleEndian or BigEndian;
// header_type UInt32 or UInt64; compressor none or vtkZLibDataCompressor. Points, Cells
// (connectivity / offsets / types), PointData and CellData arrays (any numeric type, stored as
// double); tag arrays per vtk_common.h. Write: version 1.0, LittleEndian, UInt64 headers, ascii
// or uncompressed base64 inline (vtu_write.cc). Node order converted by node_order.h.
//
// Binary payloads are checked before use: the declared byte count must match the array size
// implied by NumberOfPoints / NumberOfCells / components, and a compressed block may not claim
// more than zlib's maximum expansion (1032:1) of its compressed size.
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

#include "tmop/io/base64.h"
#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"
#include "tmop/io/vtk_common.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();

struct Tag {
  std::string_view name;
  bool closing = false;
  bool empty = false;  // <x/>
  std::vector<std::pair<std::string_view, std::string>> attrs;
  std::size_t start = 0;  // position of '<'
  const std::string* attr(std::string_view key) const {
    for (const auto& a : attrs)
      if (a.first == key) return &a.second;
    return nullptr;
  }
};

std::string unescape(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out.push_back(s[i]);
      continue;
    }
    static const char* names[][2] = {
        {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}};
    bool done = false;
    for (auto& n : names) {
      if (s.substr(i, std::strlen(n[0])) == n[0]) {
        out += n[1];
        i += std::strlen(n[0]) - 1;
        done = true;
        break;
      }
    }
    if (!done) out.push_back('&');
  }
  return out;
}

int scalar_size(std::string_view t) {
  if (t == "Int8" || t == "UInt8") return 1;
  if (t == "Int16" || t == "UInt16") return 2;
  if (t == "Int32" || t == "UInt32" || t == "Float32") return 4;
  if (t == "Int64" || t == "UInt64" || t == "Float64") return 8;
  return 0;
}

// A number for a message: integers without decimals.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

struct Array {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

class VtuReader {
 public:
  VtuReader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {}

  void read() {
    if (s_.at_end()) s_.fail("empty file");
    Tag t;
    // Root element.
    do {
      if (!next_tag(&t)) s_.fail("not a VTK XML file: no <VTKFile> element");
    } while (t.closing);
    if (t.name != "VTKFile") s_.fail_at(t.start, "not a VTK XML file: root element is not VTKFile");
    const std::string* type = t.attr("type");
    if (!type || *type != "UnstructuredGrid")
      s_.fail_at(t.start, "only VTKFile type=\"UnstructuredGrid\" is supported");
    const std::string* order = t.attr("byte_order");
    swap_ = order && *order == "BigEndian";
    const std::string* header = t.attr("header_type");
    if (header && *header != "UInt32" && *header != "UInt64")
      s_.fail_at(t.start, "header_type must be UInt32 or UInt64");
    header_size_ = header && *header == "UInt64" ? 8 : 4;
    const std::string* comp = t.attr("compressor");
    if (comp && !comp->empty()) {
      if (*comp != "vtkZLibDataCompressor")
        s_.fail_at(t.start,
                   "unsupported compressor '" + printable(*comp) + "' (vtkZLibDataCompressor is)");
      zlib_ = true;
    }
    find_appended();
    read_body();
  }

 private:
  // Next element tag; skips text, <?...?>, <!-- --> and <!...>. False at end of file.
  bool next_tag(Tag* t) {
    const std::string_view d = s_.data();
    while (true) {
      const std::size_t lt = d.find('<', s_.pos());
      if (lt == std::string_view::npos) return false;
      if (d.compare(lt, 4, "<!--") == 0) {
        const std::size_t e = d.find("-->", lt);
        if (e == std::string_view::npos) s_.fail_at(lt, "unterminated comment");
        s_.set_pos(e + 3);
        continue;
      }
      if (lt + 1 < d.size() && (d[lt + 1] == '?' || d[lt + 1] == '!')) {
        const std::size_t e = d.find('>', lt);
        if (e == std::string_view::npos) s_.fail_at(lt, "unterminated declaration");
        s_.set_pos(e + 1);
        continue;
      }
      *t = Tag();
      t->start = lt;
      std::size_t p = lt + 1;
      if (p < d.size() && d[p] == '/') {
        t->closing = true;
        ++p;
      }
      const std::size_t n0 = p;
      while (p < d.size() && !is_space(d[p]) && d[p] != '>' && d[p] != '/') ++p;
      t->name = d.substr(n0, p - n0);
      while (true) {
        while (p < d.size() && is_space(d[p])) ++p;
        if (p >= d.size()) s_.fail_at(lt, "unterminated tag <" + printable(t->name) + ">");
        if (d[p] == '>') {
          ++p;
          break;
        }
        if (d[p] == '/' && p + 1 < d.size() && d[p + 1] == '>') {
          t->empty = true;
          p += 2;
          break;
        }
        const std::size_t a0 = p;
        while (p < d.size() && d[p] != '=' && !is_space(d[p]) && d[p] != '>') ++p;
        const std::string_view key = d.substr(a0, p - a0);
        while (p < d.size() && is_space(d[p])) ++p;
        if (p >= d.size() || d[p] != '=')
          s_.fail_at(p, "malformed attribute in <" + printable(t->name) + ">");
        ++p;
        while (p < d.size() && is_space(d[p])) ++p;
        if (p >= d.size() || (d[p] != '"' && d[p] != '\''))
          s_.fail_at(p, "attribute value must be quoted");
        const char q = d[p++];
        const std::size_t v0 = p;
        const std::size_t v1 = d.find(q, p);
        if (v1 == std::string_view::npos) s_.fail_at(v0, "unterminated attribute value");
        t->attrs.emplace_back(key, unescape(d.substr(v0, v1 - v0)));
        p = v1 + 1;
      }
      s_.set_pos(p);
      return true;
    }
  }

  void find_appended() {
    const std::string_view d = s_.data();
    const std::size_t a = d.find("<AppendedData");
    if (a == std::string_view::npos) return;
    const std::size_t save = s_.pos();
    s_.set_pos(a);
    Tag t;
    next_tag(&t);
    const std::string* enc = t.attr("encoding");
    appended_raw_ = !enc || *enc == "raw";
    const std::size_t u = d.find('_', s_.pos());
    if (u == std::string_view::npos) s_.fail_at(a, "AppendedData without the '_' marker");
    appended_ = u + 1;
    have_appended_ = true;
    appended_start_ = a;
    s_.set_pos(save);
  }

  std::int64_t int_attr(const Tag& t, const char* key, std::int64_t lo, std::int64_t hi,
                        std::int64_t def) {
    const std::string* v = t.attr(key);
    if (!v) {
      if (def >= lo) return def;
      s_.fail_at(t.start, "<" + printable(t.name) + "> needs " + key);
    }
    Scanner sc(s_.path(), *v);
    std::int64_t x = 0;
    try {
      x = sc.integer(lo, hi, key);
    } catch (const Error&) {
      s_.fail_at(t.start, std::string("bad ") + key + " '" + printable(*v) + "'");
    }
    return x;
  }

  void read_body() {
    enum Section { kNone, kPoints, kCells, kPointData, kCellData } section = kNone;
    Tag t;
    bool have_piece = false, have_points = false;
    std::int64_t np = 0, nc = 0;
    std::vector<double> conn, offsets, types;
    bool have_conn = false, have_offsets = false, have_types = false;
    bool in_field = false;
    std::vector<DataArray> field;  // dataset-level FieldData: physical names (vtk_common.h)
    while (next_tag(&t)) {
      if (have_appended_ && t.start >= appended_start_) break;
      if (t.name == "Piece" && !t.closing) {
        if (have_piece) s_.fail_at(t.start, "more than one Piece is not supported");
        have_piece = true;
        np = int_attr(t, "NumberOfPoints", 0, kMaxInt32 - 1, -1);
        nc = int_attr(t, "NumberOfCells", 0, kMaxInt32 - 1, -1);
        // Every point / cell needs at least one byte somewhere in the file.
        s_.check_count(static_cast<std::uint64_t>(np), 1, "point");
        s_.check_count(static_cast<std::uint64_t>(nc), 1, "cell");
      } else if (t.name == "Points" || t.name == "Cells" || t.name == "PointData" ||
                 t.name == "CellData") {
        if (t.closing || t.empty) {
          section = kNone;
        } else {
          if (!have_piece) s_.fail_at(t.start, "<" + printable(t.name) + "> outside <Piece>");
          section = t.name == "Points"      ? kPoints
                    : t.name == "Cells"     ? kCells
                    : t.name == "PointData" ? kPointData
                                            : kCellData;
        }
      } else if (t.name == "FieldData") {
        in_field = !t.closing && !t.empty;
      } else if (t.name == "DataArray" && !t.closing && in_field) {
        const std::string* type = t.attr("type");
        if (!type || scalar_size(*type) == 0 || type->find("Float") == 0) {
          skip_array(t);  // string arrays and the like: not names
        } else {
          Array a = read_array(t, -1, /*finite=*/false);
          field.push_back(DataArray{a.name, a.components, std::move(a.values)});
        }
      } else if (t.name == "DataArray" && !t.closing) {
        const std::string* name = t.attr("Name");
        const std::string nm = name ? *name : "";
        switch (section) {
          case kPoints: {
            Array a = read_array(t, np);
            if (a.components != 3) s_.fail_at(t.start, "Points must have 3 components");
            mesh_->coords = std::move(a.values);
            have_points = true;
            break;
          }
          case kCells:
            if (nm == "connectivity") {
              conn_pos_ = t.start;
              conn = read_array(t, -1).values;
              have_conn = true;
            } else if (nm == "offsets") {
              offsets = read_array(t, nc).values;
              have_offsets = true;
            } else if (nm == "types") {
              types_pos_ = t.start;
              types = read_array(t, nc).values;
              have_types = true;
            } else {
              skip_array(t);
            }
            break;
          case kPointData:
          case kCellData: {
            Array a = read_array(t, section == kPointData ? np : nc, /*finite=*/false);
            (section == kPointData ? mesh_->point_data : mesh_->cell_data)
                .push_back(DataArray{a.name, a.components, std::move(a.values)});
            break;
          }
          default:
            skip_array(t);
        }
      }
    }
    if (!have_piece) s_.fail("no <Piece> element");
    if (!have_points && np > 0) s_.fail("no <Points> array");
    if (nc > 0 && !(have_conn && have_offsets && have_types))
      s_.fail("<Cells> needs connectivity, offsets and types arrays");
    build_cells(nc, conn, offsets, types);
    std::string bad;
    if (!extract_tag_arrays(mesh_, &bad))
      s_.fail("tag array '" + bad + "' must hold one integer per cell");
    names_from_field_data(field, mesh_);
  }

  void skip_array(const Tag& t) {
    if (t.empty) return;
    const std::size_t e = s_.data().find("</DataArray>", s_.pos());
    if (e == std::string_view::npos) s_.fail_at(t.start, "DataArray without </DataArray>");
    s_.set_pos(e + 12);
  }

  // items < 0: any number of tuples. finite: refuse NaN and infinities (points and cells; data
  // arrays keep them: VTK writes NaN where a value does not apply, and the arrays' users check
  // what they take).
  Array read_array(const Tag& t, std::int64_t items, bool finite = true) {
    Array a;
    if (const std::string* n = t.attr("Name")) a.name = *n;
    a.components = static_cast<int>(int_attr(t, "NumberOfComponents", 1, 1000, 1));
    const std::string* type = t.attr("type");
    const int size = type ? scalar_size(*type) : 0;
    if (size == 0)
      s_.fail_at(t.start, "DataArray '" + printable(a.name) + "': unsupported type '" +
                              (type ? printable(*type) : std::string()) + "'");
    const std::string* format = t.attr("format");
    const std::string f = format ? *format : "ascii";
    const std::int64_t expected = items >= 0 ? items * a.components : -1;
    if (f == "ascii") {
      if (t.empty) s_.fail_at(t.start, "empty ascii DataArray");
      const std::size_t e = s_.data().find("</DataArray>", s_.pos());
      if (e == std::string_view::npos) s_.fail_at(t.start, "DataArray without </DataArray>");
      Scanner sc(s_.path(), s_.data().substr(0, e));
      sc.set_pos(s_.pos());
      if (expected >= 0) sc.check_count(static_cast<std::uint64_t>(expected), 2, "value");
      while (!sc.at_end()) {
        if (expected >= 0 && static_cast<std::int64_t>(a.values.size()) >= expected)
          sc.fail("DataArray '" + printable(a.name) + "' has more than " +
                  std::to_string(expected) + " values");
        a.values.push_back(sc.real("value", finite));
      }
      s_.set_pos(e + 12);
    } else if (f == "binary") {
      const std::size_t e = s_.data().find("</DataArray>", s_.pos());
      if (e == std::string_view::npos) s_.fail_at(t.start, "DataArray without </DataArray>");
      std::string raw;
      std::size_t bad = 0;
      const std::size_t p0 = s_.pos();
      if (!base64_decode(s_.data().substr(p0, e - p0), &raw, &bad))
        s_.fail_at(p0 + bad, "invalid base64 character in DataArray '" + printable(a.name) + "'");
      decode_binary(raw, 0, p0, *type, size, finite, &a);
      s_.set_pos(e + 12);
    } else if (f == "appended") {
      if (!have_appended_) s_.fail_at(t.start, "format=\"appended\" but no <AppendedData>");
      if (!appended_raw_) s_.fail_at(t.start, "only raw AppendedData encoding is supported");
      const std::int64_t off =
          int_attr(t, "offset", 0, std::numeric_limits<std::int64_t>::max(), -1);
      if (static_cast<std::uint64_t>(off) >= s_.data().size() - appended_)
        s_.fail_at(t.start, "DataArray offset " + std::to_string(off) + " beyond the file end");
      const std::size_t p0 = appended_ + static_cast<std::size_t>(off);
      decode_binary(s_.data(), p0, p0, *type, size, finite, &a);
      skip_array(t);
    } else {
      s_.fail_at(t.start, "unknown DataArray format '" + printable(f) + "'");
    }
    if (expected >= 0 && static_cast<std::int64_t>(a.values.size()) != expected)
      s_.fail_at(t.start, "DataArray '" + printable(a.name) + "' has " +
                              std::to_string(a.values.size()) + " values, expected " +
                              std::to_string(expected));
    if (a.values.size() % a.components != 0)
      s_.fail_at(t.start,
                 "DataArray '" + printable(a.name) + "' size is not a multiple of its components");
    return a;
  }

  std::uint64_t header_word(std::string_view buf, std::size_t* p, std::size_t file_pos) {
    if (*p + header_size_ > buf.size())
      s_.fail_byte(file_pos + *p, "binary DataArray header is truncated");
    char b[8];
    std::memcpy(b, buf.data() + *p, header_size_);
    if (swap_)
      for (int i = 0; i < header_size_ / 2; ++i) std::swap(b[i], b[header_size_ - 1 - i]);
    *p += header_size_;
    if (header_size_ == 4) {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    std::uint64_t v;
    std::memcpy(&v, b, 8);
    return v;
  }

  // buf[p0...] holds header + payload; file_pos locates errors (decoded bytes for base64).
  void decode_binary(std::string_view buf, std::size_t p0, std::size_t file_pos,
                     const std::string& type, int size, bool finite, Array* a) {
    std::size_t p = p0;
    std::string bytes;
    if (!zlib_) {
      const std::uint64_t n = header_word(buf, &p, file_pos - p0);
      if (n > buf.size() - p)
        s_.fail_byte(file_pos, "binary DataArray '" + printable(a->name) + "' declares " +
                                   std::to_string(n) + " bytes, only " +
                                   std::to_string(buf.size() - p) + " present");
      bytes.assign(buf.data() + p, static_cast<std::size_t>(n));
    } else {
      const std::uint64_t nblocks = header_word(buf, &p, file_pos - p0);
      const std::uint64_t block = header_word(buf, &p, file_pos - p0);
      const std::uint64_t last = header_word(buf, &p, file_pos - p0);
      if (nblocks > (buf.size() - p) / header_size_)
        s_.fail_byte(file_pos, "compressed DataArray declares " + std::to_string(nblocks) +
                                   " blocks, more than the file can hold");
      std::vector<std::uint64_t> csize(static_cast<std::size_t>(nblocks));
      std::uint64_t total_c = 0;
      for (auto& c : csize) {
        c = header_word(buf, &p, file_pos - p0);
        total_c += c;
      }
      if (total_c > buf.size() - p)
        s_.fail_byte(file_pos, "compressed DataArray sizes exceed the data present");
      for (std::uint64_t b = 0; b < nblocks; ++b) {
        const std::uint64_t usize = (b + 1 == nblocks && last != 0) ? last : block;
        if (usize > 1032 * csize[b] + 64)
          s_.fail_byte(file_pos, "compressed block claims an impossible expansion");
        const std::size_t old = bytes.size();
        bytes.resize(old + static_cast<std::size_t>(usize));
        uLongf dest = static_cast<uLongf>(usize);
        const int rc = uncompress(reinterpret_cast<Bytef*>(&bytes[old]), &dest,
                                  reinterpret_cast<const Bytef*>(buf.data() + p),
                                  static_cast<uLong>(csize[b]));
        if (rc != Z_OK || dest != usize)
          s_.fail_byte(file_pos, "zlib data of DataArray '" + printable(a->name) + "' is corrupt");
        p += static_cast<std::size_t>(csize[b]);
      }
    }
    if (bytes.size() % size != 0)
      s_.fail_byte(file_pos, "binary DataArray '" + printable(a->name) + "' byte count " +
                                 std::to_string(bytes.size()) + " is not a multiple of " +
                                 std::to_string(size));
    const std::size_t n = bytes.size() / size;
    a->values.resize(n);
    // Dispatch on the type once, not per value: this loop is the whole cost of binary .vtu.
    if (type == "Float64")
      convert<double>(bytes, a);
    else if (type == "Float32")
      convert<float>(bytes, a);
    else if (type == "Int8")
      convert<std::int8_t>(bytes, a);
    else if (type == "UInt8")
      convert<std::uint8_t>(bytes, a);
    else if (type == "Int16")
      convert<std::int16_t>(bytes, a);
    else if (type == "UInt16")
      convert<std::uint16_t>(bytes, a);
    else if (type == "Int32")
      convert<std::int32_t>(bytes, a);
    else if (type == "UInt32")
      convert<std::uint32_t>(bytes, a);
    else if (type == "Int64")
      convert<std::int64_t>(bytes, a);
    else
      convert<std::uint64_t>(bytes, a);
    if (finite)
      for (double v : a->values)
        if (!std::isfinite(v))
          s_.fail_byte(file_pos, "DataArray '" + printable(a->name) + "' holds a non-finite value");
  }

  template <typename T>
  void convert(const std::string& bytes, Array* a) const {
    const std::size_t n = bytes.size() / sizeof(T);
    for (std::size_t i = 0; i < n; ++i) {
      char b[sizeof(T)];
      std::memcpy(b, bytes.data() + i * sizeof(T), sizeof(T));
      if (swap_)
        for (std::size_t k = 0; k < sizeof(T) / 2; ++k) std::swap(b[k], b[sizeof(T) - 1 - k]);
      T x;
      std::memcpy(&x, b, sizeof(T));
      a->values[i] = static_cast<double>(x);
    }
  }

  void build_cells(std::int64_t nc, const std::vector<double>& conn,
                   const std::vector<double>& offsets, const std::vector<double>& types) {
    const std::int64_t nv = static_cast<std::int64_t>(mesh_->coords.size() / 3);
    std::int32_t nodes[kMaxCellNodes];
    std::int64_t begin = 0;
    mesh_->cell_types.reserve(static_cast<std::size_t>(nc));
    for (std::int64_t c = 0; c < nc; ++c) {
      CellType type;
      const double vt = types[static_cast<std::size_t>(c)];
      // The range check comes before the cast (a double outside int is undefined behaviour).
      if (!(vt >= 0 && vt <= 255) || vt != std::floor(vt) ||
          !cell_type_from_vtk(static_cast<int>(vt), &type))
        s_.fail_at(types_pos_, "cell " + std::to_string(c) + ": unsupported VTK cell type " +
                                   num(vt) +
                                   io::unsupported_vtk_type_note(
                                       vt >= 0 && vt <= 1e9 ? static_cast<std::int64_t>(vt) : -1));
      const double end = offsets[static_cast<std::size_t>(c)];
      // A short connectivity array is the usual damage (truncated or hand-edited file), so it
      // is named as such rather than as a wrong node count.
      if (end > static_cast<double>(conn.size()))
        s_.fail_at(conn_pos_, "cell " + std::to_string(c) + " (" + cell_name(type) +
                                  ") ends at offset " + num(end) +
                                  ", but the connectivity array has only " +
                                  std::to_string(conn.size()) + " values");
      if (end - begin != cell_num_nodes(type))
        s_.fail_at(conn_pos_, "cell " + std::to_string(c) + " (" + cell_name(type) +
                                  "): offsets give " + num(end - begin) + " nodes, expected " +
                                  std::to_string(cell_num_nodes(type)));
      const int* p = gmsh_index_of_vtk_node(type);
      for (int i = 0; i < cell_num_nodes(type); ++i) {
        const double v = conn[static_cast<std::size_t>(begin + i)];
        if (v < 0 || v >= static_cast<double>(nv) || v != std::floor(v))
          s_.fail_at(conn_pos_, "cell " + std::to_string(c) + " refers to point " + num(v) +
                                    ", out of range 0.." + std::to_string(nv - 1));
        nodes[p[i]] = static_cast<std::int32_t>(v);
      }
      mesh_->add_cell(type, nodes);
      begin = static_cast<std::int64_t>(end);
    }
  }

  Scanner s_;
  Mesh* mesh_;
  bool swap_ = false;
  int header_size_ = 4;
  bool zlib_ = false;
  bool have_appended_ = false;
  bool appended_raw_ = true;
  std::size_t appended_ = 0;
  std::size_t appended_start_ = 0;
  std::size_t conn_pos_ = 0;  // connectivity / types DataArray tags: cell errors point there
  std::size_t types_pos_ = 0;
};

}  // namespace

void read_vtu(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  VtuReader(path, data, mesh).read();
}

}  // namespace io
}  // namespace tmop
