// tmop/io/surface_read.cc
// Reading .obj, .off and .ply (internal to io/; OpenMesh writes them, openmesh_io.cc). tmop reads
// these itself because OpenMesh's readers report no positions and silently skip or alter what
// they cannot use: a garbage OBJ line is ignored, a face with an out-of-range or repeated index is
// dropped, NaN is read as a coordinate, a non-manifold face gets copies of its vertices, an OFF
// '#' comment or counts on the OFF line give an empty mesh after seconds of parsing, and an OFF
// face colour of -1 made it allocate 16 GB. Every problem is reported as "FILE:LINE: what" (text)
// or "FILE:byte N: what" (binary data); declared counts are checked against the file size before
// anything is allocated.
//
// Accepted: OBJ v (x y z [w] or x y z r g b), vt, vn, f with v, v/vt, v//vn or v/vt/vn corners
// (indices among those defined so far; negative = relative), and the grouping, material and
// free-form statements (skipped, as are l and p); anything else is an error. OFF with the ST, C, N
// prefixes, '#' comments, counts on the header line, per-face colours; binary OFF in OpenMesh's
// layout (little-endian int32 counts, float32 coordinates, int32 corner count and indices per
// face). PLY ASCII and binary of both byte orders, any elements and properties; vertex x y z and
// face vertex_indices (or vertex_index) are used. Faces must have 3 or 4 distinct corners (tmop
// has triangles and quadrilaterals); data after the last record is an error. Coordinates are
// read as the file has them: ASCII ones as doubles, binary ones as their float32 / float64.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"

namespace tmop {
namespace io {
namespace {

// What a reader collects: coordinates and faces with the byte offset of each face's record.
struct Surface {
  std::int64_t num_vertices = 0;
  std::vector<double> coords;                 // 3 per vertex
  std::vector<std::int32_t> face_offsets{0};  // face f has nodes [offsets[f], offsets[f + 1])
  std::vector<std::int32_t> face_nodes;
  std::vector<std::size_t> face_pos;
  bool binary = false;              // positions are reported as bytes, not lines
  SurfaceRepair* repair = nullptr;  // reference geometry: drop / split bad faces (mesh_io.h)
};

// The most corners of a face the repair splits into a fan.
constexpr int kMaxPolygon = 64;

constexpr std::int64_t kMaxCount = std::numeric_limits<std::int32_t>::max() - 1;

struct Token {
  std::string_view text;
  std::size_t pos;  // byte offset in the file
};

// The whitespace-separated tokens of data[begin, end), up to a '#' that starts a token (a
// comment to the end of the line in OBJ and OFF).
void split(std::string_view data, std::size_t begin, std::size_t end, std::vector<Token>* out) {
  out->clear();
  std::size_t i = begin;
  while (i < end) {
    while (i < end && is_space(data[i])) ++i;
    if (i >= end || data[i] == '#') break;
    const std::size_t start = i;
    while (i < end && !is_space(data[i])) ++i;
    out->push_back({data.substr(start, i - start), start});
  }
}

bool parse_double(std::string_view t, double* v) {
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b < e && *b == '+') ++b;
  auto r = std::from_chars(b, e, *v);
  return r.ec == std::errc() && r.ptr == e;
}

bool parse_int(std::string_view t, std::int64_t* v) {
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b < e && *b == '+') ++b;
  auto r = std::from_chars(b, e, *v);
  return r.ec == std::errc() && r.ptr == e;
}

// Lines of a text file, with the byte offset of each.
class Lines {
 public:
  explicit Lines(std::string_view data) : data_(data) {}
  // The next line's [begin, end) without its '\n'; false at the end of the data.
  bool next(std::size_t* begin, std::size_t* end) {
    if (pos_ >= data_.size()) return false;
    *begin = pos_;
    std::size_t e = data_.find('\n', pos_);
    if (e == std::string_view::npos) e = data_.size();
    *end = e;
    pos_ = e + 1;
    return true;
  }
  std::size_t pos() const { return std::min(pos_, data_.size()); }

 private:
  std::string_view data_;
  std::size_t pos_ = 0;
};

class FaceCollector {
 public:
  FaceCollector(const Scanner& s, Surface* out) : s_(s), out_(out) {}
  // tmop has triangles and quadrilaterals only.
  void check_size(std::int64_t n, std::size_t pos) const {
    if (n < 3) fail(pos, "face has " + std::to_string(n) + " vertices, at least 3 are needed");
    if (out_->repair && n > kMaxPolygon)
      fail(pos, "face has " + std::to_string(n) + " vertices, more than " +
                    std::to_string(kMaxPolygon) + " (a fan of them is no surface)");
    if (n > 4 && !out_->repair)
      fail(pos, "face has " + std::to_string(n) +
                    " vertices; tmop reads triangles and quadrilaterals only");
  }
  // Checks that no corner repeats (a degenerate face; OpenMesh dropped such faces silently), then
  // adds the face.
  // Repairing, a face with a repeated corner is dropped and one of more than 4 corners becomes
  // a fan of triangles around its first corner (both counted).
  void add(const std::int32_t* nodes, int n, std::size_t pos) {
    check_size(n, pos);
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (nodes[i] == nodes[j]) {
          if (out_->repair) {
            ++out_->repair->dropped_degenerate;
            return;
          }
          fail(pos, "face uses vertex " + std::to_string(nodes[i] + index_base_) + " twice");
        }
    if (n > 4) {
      ++out_->repair->split_polygons;
      for (int k = 1; k + 1 < n; ++k) {
        const std::int32_t tri[3] = {nodes[0], nodes[k], nodes[k + 1]};
        push(tri, 3, pos);
      }
      return;
    }
    push(nodes, n, pos);
  }
  void set_index_base(int base) { index_base_ = base; }
  [[noreturn]] void fail(std::size_t pos, const std::string& what) const {
    if (out_->binary) s_.fail_byte(pos, what);
    s_.fail_at(pos, what);
  }

 private:
  void push(const std::int32_t* nodes, int n, std::size_t pos) {
    out_->face_nodes.insert(out_->face_nodes.end(), nodes, nodes + n);
    out_->face_offsets.push_back(static_cast<std::int32_t>(out_->face_nodes.size()));
    out_->face_pos.push_back(pos);
  }
  const Scanner& s_;
  Surface* out_;
  int index_base_ = 0;  // how indices are numbered in messages: 1 in OBJ, 0 in OFF / PLY
};

// ---------------------------------------------------------------------------------------------
// OBJ: line-based statements.

bool is_skipped_obj_statement(std::string_view k) {
  // Grouping, display, material and free-form statements are skipped, as OpenMesh skipped them,
  // and so are points and lines: tmop reads faces only from surface formats.
  static const char* const kSkipped[] = {
      "o",     "g",        "s",        "mg",         "usemtl",    "mtllib", "lod",
      "bevel", "c_interp", "d_interp", "shadow_obj", "trace_obj", "maplib", "usemap",
      "vp",    "cstype",   "deg",      "bmat",       "step",      "curv",   "curv2",
      "surf",  "parm",     "trim",     "hole",       "scrv",      "sp",     "end",
      "con",   "call",     "csh",      "l",          "p"};
  for (const char* s : kSkipped)
    if (k == s) return true;
  return false;
}

void read_obj(const Scanner& s, std::string_view data, Surface* out) {
  FaceCollector faces(s, out);
  faces.set_index_base(1);
  std::int64_t nvt = 0, nvn = 0;
  std::vector<Token> tok;
  std::vector<std::int32_t> nodes;
  Lines lines(data);
  std::size_t b, e;
  // index: the OBJ index text of one corner component; defined: how many of that kind exist so
  // far. Returns the 0-based index.
  auto resolve = [&](const Token& t, std::string_view text, std::int64_t defined,
                     const char* kind) -> std::int64_t {
    std::int64_t v;
    if (!parse_int(text, &v))
      s.fail_at(t.pos,
                std::string("expected a ") + kind + " index, got '" + printable(t.text) + "'");
    if (v == 0) s.fail_at(t.pos, std::string(kind) + " index 0 (OBJ indices start at 1)");
    const std::int64_t i = v > 0 ? v - 1 : defined + v;  // negative: relative to the last one
    if (i < 0 || i >= defined)
      s.fail_at(t.pos, std::string(kind) + " index " + std::to_string(v) +
                           " out of range: " + std::to_string(defined) + " defined so far");
    return i;
  };
  while (lines.next(&b, &e)) {
    split(data, b, e, &tok);
    if (tok.empty()) continue;
    const std::string_view k = tok[0].text;
    if (k == "v" || k == "vt" || k == "vn") {
      const std::size_t lo = k == "v" ? 3 : k == "vt" ? 1 : 3;
      const std::size_t hi = k == "v" ? 7 : 3;  // v x y z [w] or v x y z r g b (colours)
      if (tok.size() - 1 < lo || tok.size() - 1 > hi)
        s.fail_at(tok[0].pos, "'" + std::string(k) + "' needs " +
                                  (lo == hi ? std::to_string(lo)
                                            : std::to_string(lo) + " to " + std::to_string(hi)) +
                                  " numbers, got " + std::to_string(tok.size() - 1));
      for (std::size_t i = 1; i < tok.size(); ++i) {
        double v;
        if (!parse_double(tok[i].text, &v))
          s.fail_at(tok[i].pos, "expected a number, got '" + printable(tok[i].text) + "'");
        if (!std::isfinite(v)) s.fail_at(tok[i].pos, "coordinate is not finite");
        if (k == "v" && i <= 3) out->coords.push_back(v);
      }
      if (k == "v") {
        if (out->num_vertices >= kMaxCount) s.fail_at(tok[0].pos, "too many vertices");
        ++out->num_vertices;
      } else {
        ++(k == "vt" ? nvt : nvn);
      }
    } else if (k == "f") {
      nodes.clear();
      faces.check_size(static_cast<std::int64_t>(tok.size()) - 1, tok[0].pos);
      for (std::size_t i = 1; i < tok.size(); ++i) {
        // v, v/vt, v//vn or v/vt/vn
        const std::string_view t = tok[i].text;
        const std::size_t s1 = t.find('/');
        const std::string_view vtext = t.substr(0, s1);
        nodes.push_back(
            static_cast<std::int32_t>(resolve(tok[i], vtext, out->num_vertices, "vertex")));
        if (s1 == std::string_view::npos) continue;
        const std::size_t s2 = t.find('/', s1 + 1);
        const std::string_view ttext = t.substr(s1 + 1, s2 - s1 - 1);
        if (!ttext.empty()) resolve(tok[i], ttext, nvt, "texture coordinate");
        if (s2 == std::string_view::npos) continue;
        const std::string_view ntext = t.substr(s2 + 1);
        if (ntext.empty() || ntext.find('/') != std::string_view::npos)
          s.fail_at(tok[i].pos, "malformed face corner '" + printable(t) + "'");
        resolve(tok[i], ntext, nvn, "normal");
      }
      faces.add(nodes.data(), static_cast<int>(nodes.size()), tok[0].pos);
    } else if (!is_skipped_obj_statement(k)) {
      s.fail_at(tok[0].pos, "unknown OBJ statement '" + printable(k) + "'");
    }
  }
  if (out->num_vertices == 0) s.fail_at(0, "no vertices ('v' lines)");
}

// ---------------------------------------------------------------------------------------------
// OFF: header keyword, counts, one vertex per line, one face per line.

void read_off(const Scanner& s, std::string_view data, Surface* out) {
  Lines lines(data);
  std::vector<Token> tok;
  std::size_t b, e;
  // The header keyword: [ST][C][N][4][n]OFF, then BINARY for the binary form.
  do {
    if (!lines.next(&b, &e)) s.fail_at(0, "not an OFF file: expected OFF");
    split(data, b, e, &tok);
  } while (tok.empty());
  std::string_view key = tok[0].text;
  const bool st = key.substr(0, 2) == "ST";
  if (st) key.remove_prefix(2);
  const bool colors = !key.empty() && key[0] == 'C';
  if (colors) key.remove_prefix(1);
  const bool normals = !key.empty() && key[0] == 'N';
  if (normals) key.remove_prefix(1);
  if (key == "4OFF" || key == "nOFF" || key == "4nOFF")
    s.fail_at(tok[0].pos, "only 3D OFF files are supported, not '" + printable(tok[0].text) + "'");
  if (key != "OFF") s.fail_at(tok[0].pos, "not an OFF file: expected OFF");
  std::size_t first = 1;
  if (tok.size() > 1 && tok[1].text == "BINARY") {
    out->binary = true;
    first = 2;
  }
  if (out->binary) {
    // OpenMesh's binary layout (what it writes and reads): little-endian int32 counts nv nf ne,
    // nv x 3 float32, then per face an int32 corner count and that many int32 indices.
    if (tok.size() > first) s.fail_at(tok[first].pos, "unexpected data after OFF BINARY");
    if (st || colors || normals)
      s.fail_at(tok[0].pos,
                "binary OFF with colours, normals or texture coordinates is not supported");
    std::size_t p = lines.pos();
    Scanner bin(s.path(), data);
    bin.set_pos(p);
    auto i32 = [&](const char* what) { return bin.binary<std::int32_t>(false, what); };
    const std::int32_t nv = i32("vertex count"), nf = i32("face count");
    i32("edge count");
    if (nv < 0 || nf < 0) s.fail_byte(p, "negative vertex or face count");
    bin.check_count_binary(static_cast<std::uint64_t>(nv), 12, "vertex");
    out->coords.reserve(3 * static_cast<std::size_t>(nv));
    for (std::int32_t v = 0; v < nv; ++v)
      for (int k = 0; k < 3; ++k) {
        const std::size_t at = bin.pos();
        const float x = bin.binary<float>(false, "coordinate");
        if (!std::isfinite(x))
          s.fail_byte(at, "coordinate of vertex " + std::to_string(v) + " is not finite");
        out->coords.push_back(x);
      }
    out->num_vertices = nv;
    bin.check_count_binary(static_cast<std::uint64_t>(nf), 16, "face");
    FaceCollector faces(s, out);
    std::int32_t nodes[kMaxPolygon];
    for (std::int32_t f = 0; f < nf; ++f) {
      const std::size_t at = bin.pos();
      const std::int32_t n = i32("face corner count");
      faces.check_size(n, at);
      for (int i = 0; i < n; ++i) {
        const std::size_t ip = bin.pos();
        nodes[i] = i32("vertex index");
        if (nodes[i] < 0 || nodes[i] >= nv)
          s.fail_byte(ip, "vertex index " + std::to_string(nodes[i]) + " out of range 0.." +
                              std::to_string(nv - 1));
      }
      faces.add(nodes, n, at);
    }
    if (bin.remaining() > 0)
      s.fail_byte(bin.pos(), std::to_string(bin.remaining()) + " bytes after the last face");
    return;
  }
  // Counts: on the header line or the next non-comment line.
  std::vector<Token> counts(tok.begin() + static_cast<std::ptrdiff_t>(first), tok.end());
  while (counts.empty()) {
    if (!lines.next(&b, &e)) s.fail_at(data.size(), "unexpected end of file, expected counts");
    split(data, b, e, &counts);
  }
  if (counts.size() < 2 || counts.size() > 3)
    s.fail_at(counts[0].pos, "expected 'vertices faces [edges]' counts");
  std::int64_t nc[3] = {0, 0, 0};
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (!parse_int(counts[i].text, &nc[i]) || nc[i] < 0 || nc[i] > kMaxCount)
      s.fail_at(counts[i].pos, "expected a count, got '" + printable(counts[i].text) + "'");
  {
    Scanner c(s.path(), data);
    c.set_pos(counts.back().pos + counts.back().text.size());
    c.check_count(static_cast<std::uint64_t>(nc[0]), 6, "vertex");
    c.check_count(static_cast<std::uint64_t>(nc[1]), 6, "face");
  }
  const std::size_t need = 3 + (normals ? 3 : 0) + (st ? 2 : 0);
  out->coords.reserve(3 * static_cast<std::size_t>(nc[0]));
  for (std::int64_t v = 0; v < nc[0]; ++v) {
    do {
      if (!lines.next(&b, &e))
        s.fail_at(data.size(), "unexpected end of file after " + std::to_string(v) + " of " +
                                   std::to_string(nc[0]) + " vertices");
      split(data, b, e, &tok);
    } while (tok.empty());
    // Colours (C) may have 1 (index), 3 or 4 components, so allow up to 4 more values.
    if (tok.size() < need || tok.size() > need + (colors ? 4 : 0))
      s.fail_at(tok[0].pos, "vertex line has " + std::to_string(tok.size()) + " values, expected " +
                                std::to_string(need) + (colors ? " plus a colour" : ""));
    for (std::size_t i = 0; i < tok.size(); ++i) {
      double x;
      if (!parse_double(tok[i].text, &x))
        s.fail_at(tok[i].pos, "expected a number, got '" + printable(tok[i].text) + "'");
      if (!std::isfinite(x)) s.fail_at(tok[i].pos, "coordinate is not finite");
      if (i < 3) out->coords.push_back(x);
    }
  }
  out->num_vertices = nc[0];
  FaceCollector faces(s, out);
  std::int32_t nodes[kMaxPolygon];
  for (std::int64_t f = 0; f < nc[1]; ++f) {
    do {
      if (!lines.next(&b, &e))
        s.fail_at(data.size(), "unexpected end of file after " + std::to_string(f) + " of " +
                                   std::to_string(nc[1]) + " faces");
      split(data, b, e, &tok);
    } while (tok.empty());
    std::int64_t n;
    if (!parse_int(tok[0].text, &n))
      s.fail_at(tok[0].pos, "expected a face corner count, got '" + printable(tok[0].text) + "'");
    faces.check_size(n, tok[0].pos);
    if (tok.size() < static_cast<std::size_t>(n) + 1)
      s.fail_at(tok[0].pos, "face line has " + std::to_string(tok.size() - 1) +
                                " vertex indices, its count says " + std::to_string(n));
    for (std::int64_t i = 0; i < n; ++i) {
      const Token& t = tok[static_cast<std::size_t>(i) + 1];
      std::int64_t v;
      if (!parse_int(t.text, &v))
        s.fail_at(t.pos, "expected a vertex index, got '" + printable(t.text) + "'");
      if (v < 0 || v >= nc[0])
        s.fail_at(t.pos, "vertex index " + std::to_string(v) + " out of range 0.." +
                             std::to_string(nc[0] - 1));
      nodes[i] = static_cast<std::int32_t>(v);
    }
    // What follows the indices is the face's colour (1, 3 or 4 values).
    const std::size_t rest = tok.size() - 1 - static_cast<std::size_t>(n);
    if (rest > 4)
      s.fail_at(tok[static_cast<std::size_t>(n) + 1].pos,
                "unexpected '" + printable(tok[static_cast<std::size_t>(n) + 1].text) +
                    "' after the face's vertex indices");
    for (std::size_t i = static_cast<std::size_t>(n) + 1; i < tok.size(); ++i) {
      double x;
      if (!parse_double(tok[i].text, &x))
        s.fail_at(tok[i].pos, "expected a colour value, got '" + printable(tok[i].text) + "'");
    }
    faces.add(nodes, static_cast<int>(n), tok[0].pos);
  }
  while (lines.next(&b, &e)) {
    split(data, b, e, &tok);
    if (!tok.empty()) s.fail_at(tok[0].pos, "unexpected data after the last face");
  }
}

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

}  // namespace

void read_surface(const std::string& path, const std::string& ext, const std::string& data,
                  Mesh* mesh, SurfaceRepair* repair) {
  Scanner s(path, data);
  if (s.at_end()) s.fail_at(0, "empty file");
  Surface surface;
  surface.repair = repair;
  if (ext == "obj")
    read_obj(s, data, &surface);
  else if (ext == "off")
    read_off(s, data, &surface);
  else
    read_ply(s, data, &surface);
  mesh->space_dim = 3;
  mesh->coords = std::move(surface.coords);
  const std::size_t nf = surface.face_pos.size();
  mesh->cell_types.reserve(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const int n = surface.face_offsets[f + 1] - surface.face_offsets[f];
    mesh->add_cell(n == 3 ? CellType::kTri3 : CellType::kQuad4,
                   surface.face_nodes.data() + surface.face_offsets[f]);
  }
}

}  // namespace io
}  // namespace tmop
