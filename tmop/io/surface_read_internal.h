// tmop/io/surface_read_internal.h
// What the .obj / .off (surface_read.cc) and .ply (surface_read_ply.cc) readers share: the
// surface they collect, tokens and lines with their byte offsets, the face checks. Internal to
// io/.
#ifndef TMOP_IO_SURFACE_READ_INTERNAL_H_
#define TMOP_IO_SURFACE_READ_INTERNAL_H_

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tmop/io/formats.h"
#include "tmop/io/scanner.h"

namespace tmop {
namespace io {
namespace surface_read {

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
inline void split(std::string_view data, std::size_t begin, std::size_t end,
                  std::vector<Token>* out) {
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

inline bool parse_double(std::string_view t, double* v) {
  const char* b = t.data();
  const char* e = t.data() + t.size();
  if (b < e && *b == '+') ++b;
  auto r = std::from_chars(b, e, *v);
  return r.ec == std::errc() && r.ptr == e;
}

inline bool parse_int(std::string_view t, std::int64_t* v) {
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

void read_ply(const Scanner& s, std::string_view data, Surface* out);

}  // namespace surface_read
}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_SURFACE_READ_INTERNAL_H_
