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

#include "tmop/io/surface_read_internal.h"

namespace tmop {
namespace io {
namespace surface_read {
namespace {
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

}  // namespace
}  // namespace surface_read

using surface_read::Surface;

void read_surface(const std::string& path, const std::string& ext, const std::string& data,
                  Mesh* mesh, SurfaceRepair* repair) {
  Scanner s(path, data);
  if (s.at_end()) s.fail_at(0, "empty file");
  Surface surface;
  surface.repair = repair;
  if (ext == "obj")
    surface_read::read_obj(s, data, &surface);
  else if (ext == "off")
    surface_read::read_off(s, data, &surface);
  else
    surface_read::read_ply(s, data, &surface);
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
