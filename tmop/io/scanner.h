// tmop/io/scanner.h
// Scanner: a cursor over a whole file held in memory, shared by every reader. It reads
// whitespace-separated tokens (integers via std::from_chars, doubles via std::from_chars, which
// is exact and locale-independent) and raw binary values, and turns every problem into a
// tmop::Error whose message is "FILE:LINE: what" (text) or "FILE:byte N: what" (binary). Line
// numbers are computed only when an error is raised, so scanning costs nothing extra.
//
// check_count() is the guard against huge declared counts: a count is accepted only when
// count * min_bytes_each fits in the rest of the file, so no reader allocates more than a small
// multiple of the file size.
#ifndef TMOP_IO_SCANNER_H_
#define TMOP_IO_SCANNER_H_

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "tmop/core/status.h"

namespace tmop {
namespace io {

// Reads the whole file; throws Error("FILE: ...") on failure. Only regular files are read (a
// directory, FIFO or device is refused before it is opened for reading); the first 64 KiB are
// checked by check_magic before the rest is read, so a large file of the wrong kind costs 64 KiB.
std::string read_file(const std::string& path, const std::string& ext);
// Throws Error("FILE: not a regular file (a directory)") when path exists and is not a regular
// file (symlinks followed); nothing when it is one or does not exist.
void check_regular_file(const std::string& path);
// Throws the located Error the reader of format `ext` (lower case, no dot) would throw at once
// when `head`, the first bytes of a file of `size` bytes, cannot start such a file (a Gmsh file
// without $MeshFormat, a binary STL whose size does not match its count, ...). Lenient where the
// head is cut: only what the head shows is judged; the reader checks the rest.
void check_magic(const std::string& path, const std::string& ext, std::string_view head,
                 std::uint64_t size);

class Scanner {
 public:
  Scanner(const std::string& path, std::string_view data) : path_(path), data_(data) {}

  const std::string& path() const { return path_; }
  std::string_view data() const { return data_; }
  std::size_t pos() const { return pos_; }
  void set_pos(std::size_t p) { pos_ = p; }
  std::size_t remaining() const { return data_.size() - pos_; }

  // Text.
  void skip_space();
  bool at_end();                          // true when only whitespace is left
  std::string_view token();               // next token; fails at end of file
  bool try_token(std::string_view* out);  // false at end of file
  std::int64_t integer(std::int64_t lo, std::int64_t hi, const char* what);
  // A real number; only finite values unless finite_only is false (data arrays, where VTK
  // writes NaN for "no value": "nan", "inf" and "infinity" in any case, with a sign).
  double real(const char* what, bool finite_only = true);
  std::string_view line();  // rest of the current line without "\r\n"; moves past it
  void skip_line();         // moves past the next '\n'
  // Moves past the next line that, trimmed, equals `text`; false (position at end) if none.
  bool skip_to_line(std::string_view text);

  // Binary (little-endian host assumed; swap=true reverses bytes, e.g. VTK's big-endian data).
  const char* bytes(std::size_t n, const char* what);
  template <typename T>
  T binary(bool swap, const char* what) {
    const char* p = bytes(sizeof(T), what);
    char buf[sizeof(T)];
    std::memcpy(buf, p, sizeof(T));
    if (swap)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(buf[i], buf[sizeof(T) - 1 - i]);
    T v;
    std::memcpy(&v, buf, sizeof(T));
    return v;
  }

  // Fails unless count items of at least min_bytes_each bytes fit in the rest of the file.
  void check_count(std::uint64_t count, std::size_t min_bytes_each, const char* what) const;
  void check_count_binary(std::uint64_t count, std::size_t bytes_each, const char* what) const;

  [[noreturn]] void fail(const std::string& what) const { fail_at(pos_, what); }
  [[noreturn]] void fail_at(std::size_t pos, const std::string& what) const;
  [[noreturn]] void fail_byte(std::size_t pos, const std::string& what) const;
  int line_of(std::size_t pos) const;

 private:
  std::string path_;
  std::string_view data_;
  std::size_t pos_ = 0;
};

// At most 32 characters of a token for an error message, non-printable bytes as '?'.
std::string printable(std::string_view token);

inline bool is_space(char c) {
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_SCANNER_H_
