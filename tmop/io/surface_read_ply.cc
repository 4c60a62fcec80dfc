// tmop/io/surface_read_ply.cc
// Reading .ply, ASCII and binary of both byte orders (surface_read.cc has the contract and the
// .obj / .off readers).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "tmop/io/surface_read_internal.h"

namespace tmop {
namespace io {
namespace surface_read {
namespace {
// ---------------------------------------------------------------------------------------------
// PLY: header of elements and properties, then the records in ASCII or binary.

enum class PlyType { kInt8, kUInt8, kInt16, kUInt16, kInt32, kUInt32, kFloat32, kFloat64 };

bool ply_type(std::string_view t, PlyType* out) {
  struct Name {
    const char* a;
    const char* b;
    PlyType type;
  };
  static const Name kNames[] = {
      {"char", "int8", PlyType::kInt8},        {"uchar", "uint8", PlyType::kUInt8},
      {"short", "int16", PlyType::kInt16},     {"ushort", "uint16", PlyType::kUInt16},
      {"int", "int32", PlyType::kInt32},       {"uint", "uint32", PlyType::kUInt32},
      {"float", "float32", PlyType::kFloat32}, {"double", "float64", PlyType::kFloat64}};
  for (const Name& n : kNames)
    if (t == n.a || t == n.b) {
      *out = n.type;
      return true;
    }
  return false;
}

std::size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::kInt8:
    case PlyType::kUInt8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUInt16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUInt32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 1;
}

bool ply_float(PlyType t) { return t == PlyType::kFloat32 || t == PlyType::kFloat64; }

struct PlyProperty {
  std::string name;
  bool list = false;
  PlyType count_type = PlyType::kUInt8;
  PlyType type = PlyType::kFloat32;
};

struct PlyElement {
  std::string name;
  std::int64_t count = 0;
  std::size_t header_pos = 0;
  std::vector<PlyProperty> props;
};

template <typename T>
double load(const char* p, bool swap) {
  char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap) std::reverse(b, b + sizeof(T));
  T v;
  std::memcpy(&v, b, sizeof(T));
  return static_cast<double>(v);
}

double ply_load(PlyType t, const char* p, bool swap) {
  switch (t) {
    case PlyType::kInt8:
      return load<std::int8_t>(p, swap);
    case PlyType::kUInt8:
      return load<std::uint8_t>(p, swap);
    case PlyType::kInt16:
      return load<std::int16_t>(p, swap);
    case PlyType::kUInt16:
      return load<std::uint16_t>(p, swap);
    case PlyType::kInt32:
      return load<std::int32_t>(p, swap);
    case PlyType::kUInt32:
      return load<std::uint32_t>(p, swap);
    case PlyType::kFloat32:
      return load<float>(p, swap);
    case PlyType::kFloat64:
      return load<double>(p, swap);
  }
  return 0;
}

}  // namespace

void read_ply(const Scanner& s, std::string_view data, Surface* out) {
  Lines lines(data);
  std::vector<Token> tok;
  std::size_t b, e;
  if (!lines.next(&b, &e) || (split(data, b, e, &tok), tok.size() != 1 || tok[0].text != "ply"))
    s.fail_at(0, "not a PLY file: expected 'ply'");
  std::string format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && lines.next(&b, &e)) {
    split(data, b, e, &tok);
    if (tok.empty()) continue;
    const std::string_view k = tok[0].text;
    if (k == "comment" || k == "obj_info") continue;
    if (k == "end_header") {
      ended = true;
    } else if (k == "format") {
      if (tok.size() != 3 || (tok[1].text != "ascii" && tok[1].text != "binary_little_endian" &&
                              tok[1].text != "binary_big_endian"))
        s.fail_at(tok[0].pos, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      format = std::string(tok[1].text);
    } else if (k == "element") {
      std::int64_t n;
      if (tok.size() != 3 || !parse_int(tok[2].text, &n) || n < 0 || n > kMaxCount)
        s.fail_at(tok[0].pos, "expected 'element NAME COUNT'");
      elements.push_back({std::string(tok[1].text), n, tok[0].pos, {}});
    } else if (k == "property") {
      if (elements.empty()) s.fail_at(tok[0].pos, "property before any element");
      PlyProperty p;
      bool ok;
      if (tok.size() == 5 && tok[1].text == "list") {
        p.list = true;
        ok = ply_type(tok[2].text, &p.count_type) && !ply_float(p.count_type) &&
             ply_type(tok[3].text, &p.type);
        p.name = std::string(tok[4].text);
      } else {
        ok = tok.size() == 3 && ply_type(tok[1].text, &p.type);
        if (ok) p.name = std::string(tok[2].text);
      }
      if (!ok)
        s.fail_at(tok[0].pos, "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'");
      elements.back().props.push_back(p);
    } else {
      s.fail_at(tok[0].pos, "unknown PLY header line '" + printable(k) + "'");
    }
  }
  if (!ended) s.fail_at(data.size(), "unexpected end of file in the PLY header (no end_header)");
  if (format.empty()) s.fail_at(0, "PLY header has no 'format' line");
  const std::size_t data_start = lines.pos();

  const bool ascii = format == "ascii";
  // No element's count may exceed what the data can hold: checked for each on its own first (a
  // huge count is the problem to report, before any property is judged), then cumulatively while
  // reading, before anything is allocated.
  auto check_count = [ascii](const PlyElement& el, const Scanner& at) {
    std::size_t min_bytes = 0;  // a record's smallest size: "0 " per value, or empty lists
    for (const PlyProperty& p : el.props)
      min_bytes += ascii ? 2 : ply_size(p.list ? p.count_type : p.type);
    if (ascii)
      at.check_count(static_cast<std::uint64_t>(el.count), std::max<std::size_t>(min_bytes, 1),
                     "element");
    else
      at.check_count_binary(static_cast<std::uint64_t>(el.count), min_bytes, "element");
  };
  {
    Scanner start(s.path(), data);
    start.set_pos(data_start);
    for (const PlyElement& el : elements) check_count(el, start);
  }
  // The properties tmop uses: vertex x y z, face vertex_indices.
  const PlyElement* vertex = nullptr;
  for (const PlyElement& el : elements)
    if (el.name == "vertex") vertex = &el;
  if (!vertex) s.fail_at(0, "PLY header has no 'element vertex'");
  int axis_of[3] = {-1, -1, -1};  // property index of x, y, z
  for (int k = 0; k < 3; ++k) {
    const char* axis[3] = {"x", "y", "z"};
    for (std::size_t i = 0; i < vertex->props.size(); ++i)
      if (!vertex->props[i].list && vertex->props[i].name == axis[k])
        axis_of[k] = static_cast<int>(i);
    if (axis_of[k] < 0)
      s.fail_at(vertex->header_pos, std::string("element vertex has no property ") + axis[k]);
  }
  out->num_vertices = vertex->count;
  const std::int64_t nv = vertex->count;
  int face_list = -1;
  for (const PlyElement& el : elements) {
    if (el.name != "face") continue;
    for (std::size_t i = 0; i < el.props.size(); ++i)
      if (el.props[i].list &&
          (el.props[i].name == "vertex_indices" || el.props[i].name == "vertex_index"))
        face_list = static_cast<int>(i);
    if (face_list < 0) s.fail_at(el.header_pos, "element face has no list property vertex_indices");
    if (ply_float(el.props[static_cast<std::size_t>(face_list)].type))
      s.fail_at(el.header_pos, "face vertex indices must be integers");
  }

  out->binary = !ascii;
  const bool swap = format == "binary_big_endian";
  FaceCollector faces(s, out);
  std::vector<std::int32_t> nodes;
  Scanner r(s.path(), data);
  r.set_pos(data_start);
  for (const PlyElement& el : elements) {
    check_count(el, r);
    const bool is_face = el.name == "face";
    const bool is_vertex = &el == vertex;
    if (is_vertex) out->coords.assign(3 * static_cast<std::size_t>(el.count), 0.0);
    for (std::int64_t rec = 0; rec < el.count; ++rec) {
      if (ascii) r.skip_space();
      const std::size_t rec_pos = r.pos();
      for (std::size_t pi = 0; pi < el.props.size(); ++pi) {
        const PlyProperty& p = el.props[pi];
        const bool indices = is_face && static_cast<int>(pi) == face_list;
        std::int64_t n = 1;
        if (p.list) {
          if (ascii) {
            n = r.integer(0, kMaxCount, "list length");
          } else {
            const std::size_t at = r.pos();
            const double c =
                ply_load(p.count_type, r.bytes(ply_size(p.count_type), "list length"), swap);
            if (c < 0) s.fail_byte(at, "negative list length");
            n = static_cast<std::int64_t>(c);
            if (static_cast<std::uint64_t>(n) > r.remaining() / ply_size(p.type))
              s.fail_byte(at,
                          "list length " + std::to_string(n) + " runs past the end of the file");
          }
        }
        if (indices) {
          faces.check_size(n, rec_pos);
          nodes.clear();
        }
        const char* what = el.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z")
                               ? "coordinate"
                               : p.name.c_str();
        for (std::int64_t i = 0; i < n; ++i) {
          const std::size_t at = ascii ? (r.skip_space(), r.pos()) : r.pos();
          double v;
          if (ascii) {
            v = ply_float(p.type) ? r.real(what)
                                  : static_cast<double>(r.integer(
                                        std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::max(), "integer"));
          } else {
            v = ply_load(p.type, r.bytes(ply_size(p.type), what), swap);
            if (!std::isfinite(v)) s.fail_byte(at, std::string(what) + " is not finite");
          }
          if (is_vertex)
            for (int k = 0; k < 3; ++k)
              if (static_cast<int>(pi) == axis_of[k])
                out->coords[3 * static_cast<std::size_t>(rec) + static_cast<std::size_t>(k)] = v;
          if (indices) {
            if (v < 0 || v >= static_cast<double>(nv)) {
              const std::string what = "vertex index " + std::to_string(static_cast<long long>(v)) +
                                       " out of range 0.." + std::to_string(nv - 1);
              if (ascii) s.fail_at(at, what);
              s.fail_byte(at, what);
            }
            nodes.push_back(static_cast<std::int32_t>(v));
          }
        }
        if (indices) faces.add(nodes.data(), static_cast<int>(n), rec_pos);
      }
    }
  }
  if (ascii) {
    if (!r.at_end()) r.fail("unexpected data after the last PLY element");
  } else if (r.remaining() > 0) {
    s.fail_byte(r.pos(), std::to_string(r.remaining()) + " bytes after the last PLY element");
  }
}

}  // namespace surface_read
}  // namespace io
}  // namespace tmop
