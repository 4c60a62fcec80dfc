#include "tmop/io/scanner.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace tmop {
namespace io {

namespace {

// What a non-regular file is, for the message.
const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void not_regular(const std::string& path, mode_t mode) {
  throw Error(path + ": not a regular file (" + file_kind(mode) + ")");
}

std::size_t skip_spaces(std::string_view s, std::size_t i) {
  while (i < s.size() && is_space(s[i])) ++i;
  return i;
}

// The first whitespace-separated token at or after i (it may be cut by the end of the prefix).
std::string_view first_token(std::string_view s, std::size_t* i) {
  *i = skip_spaces(s, *i);
  std::size_t e = *i;
  while (e < s.size() && !is_space(s[e])) ++e;
  return s.substr(*i, e - *i);
}

// t is `word`, or (cut by the end of the prefix) the start of it.
bool token_is(std::string_view t, std::string_view word, bool cut) {
  return t == word || (cut && word.substr(0, t.size()) == t);
}

}  // namespace

void check_regular_file(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) not_regular(path, st.st_mode);
}

void check_magic(const std::string& path, const std::string& ext, std::string_view head,
                 std::uint64_t size) {
  Scanner s(path, head);
  const bool whole = head.size() == size;  // the head is the whole file
  std::size_t i = 0;
  if (ext == "msh") {
    const std::string_view t = first_token(head, &i);
    if (i == head.size()) return;  // only whitespace so far: the reader decides
    if (!token_is(t, "$MeshFormat", !whole && i + t.size() == head.size()))
      s.fail_at(i, "not a Gmsh file: expected $MeshFormat");
  } else if (ext == "vtk") {
    const std::string_view magic = "# vtk DataFile Version";
    const std::string_view start = head.substr(0, magic.size());
    if (!head.empty() && (start != magic.substr(0, start.size()) ||
                          (whole && start.size() < magic.size() && head.find('\n') < magic.size())))
      s.fail_at(0, "not a VTK legacy file: first line must be '# vtk DataFile Version x.y'");
  } else if (ext == "vtu") {
    if (head.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // UTF-8 byte order mark
    i = skip_spaces(head, i);
    if (i < head.size() && head[i] != '<')
      s.fail_at(i, "not a VTK XML file: expected '<' (an XML document), got '" +
                       printable(head.substr(i, 8)) + "'");
  } else if (ext == "stl") {
    // Binary: an 80-byte header and a triangle count that the file size matches exactly.
    std::uint32_t n = 0;
    if (head.size() >= 84) std::memcpy(&n, head.data() + 80, 4);
    if (size >= 84 && static_cast<std::uint64_t>(n) * 50 + 84 == size) return;
    const std::string_view t = first_token(head, &i);
    if (i == head.size()) return;
    std::string lower(t.substr(0, 5));
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (token_is(lower, "solid", !whole && i + t.size() == head.size())) return;
    if (size < 84) s.fail_byte(size, "binary STL shorter than its 84-byte header");
    s.fail_byte(80, "binary STL declares " + std::to_string(n) + " triangles, the file size " +
                        std::to_string(size) + " does not match");
  } else if (ext == "ply") {
    const std::string_view t = first_token(head, &i);
    if (i < head.size() && !token_is(t, "ply", !whole && i + t.size() == head.size()))
      s.fail_at(0, "not a PLY file: expected 'ply'");
  } else if (ext == "mesh" || ext == "obj" || ext == "off") {
    // Text (OFF BINARY only after its header line): a NUL byte before the first line ends is
    // binary data.
    const std::size_t nul = head.substr(0, head.find('\n')).find('\0');
    if (nul != std::string_view::npos)
      s.fail_at(nul, "binary data (a NUL byte) where a text file was expected");
  }
}

std::string read_file(const std::string& path, const std::string& ext) {
  // stat first: opening a FIFO blocks, a device never ends, a directory "reads" as empty.
  struct stat st;
  if (::stat(path.c_str(), &st) != 0)
    throw Error(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) not_regular(path, st.st_mode);
  // O_NONBLOCK: if the path was swapped for a FIFO since the stat, open does not wait for it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) throw Error(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  std::string data;
  try {
    if (::fstat(fd, &st) != 0) throw Error(path + ": cannot open for reading");
    if (!S_ISREG(st.st_mode)) not_regular(path, st.st_mode);
    const std::uint64_t size = static_cast<std::uint64_t>(st.st_size);
    // The first bytes decide whether the rest is worth reading: a 3 GB file of NUL bytes named
    // .msh fails here, after 64 KiB.
    constexpr std::size_t kHead = 1 << 16;
    std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(size, kHead));
    data.resize(want);
    std::size_t have = 0;
    bool eof = false;
    auto fill = [&]() {
      while (have < data.size()) {
        const ssize_t n = ::read(fd, &data[have], data.size() - have);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw Error(path + ": read error (" + std::strerror(errno) + ")");
        if (n == 0) {
          eof = true;
          break;
        }
        have += static_cast<std::size_t>(n);
      }
      data.resize(have);
    };
    fill();
    check_magic(path, ext, data, eof ? have : std::max<std::uint64_t>(size, have));
    if (!eof && have == want) {
      data.resize(static_cast<std::size_t>(std::max<std::uint64_t>(size, have)));
      fill();
      // A file that grew while being read: the rest, probed with a small buffer first so the
      // common case (nothing more) does not reallocate the whole content.
      while (!eof) {
        char probe[4096];
        const ssize_t n = ::read(fd, probe, sizeof probe);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw Error(path + ": read error (" + std::strerror(errno) + ")");
        if (n == 0) break;
        data.append(probe, static_cast<std::size_t>(n));
      }
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return data;
}

std::string printable(std::string_view token) {
  std::string out(token.substr(0, 32));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  if (token.size() > 32) out += "...";
  return out;
}

void Scanner::skip_space() {
  while (pos_ < data_.size() && is_space(data_[pos_])) ++pos_;
}

bool Scanner::at_end() {
  skip_space();
  return pos_ >= data_.size();
}

bool Scanner::try_token(std::string_view* out) {
  skip_space();
  if (pos_ >= data_.size()) return false;
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !is_space(data_[pos_])) ++pos_;
  *out = data_.substr(start, pos_ - start);
  return true;
}

std::string_view Scanner::token() {
  std::string_view t;
  if (!try_token(&t)) fail("unexpected end of file");
  return t;
}

std::int64_t Scanner::integer(std::int64_t lo, std::int64_t hi, const char* what) {
  skip_space();
  const std::size_t start = pos_;
  if (pos_ >= data_.size()) fail(std::string("unexpected end of file, expected ") + what);
  const char* b = data_.data() + pos_;
  const char* e = data_.data() + data_.size();
  if (*b == '+') ++b;  // from_chars rejects a leading '+'
  std::int64_t v = 0;
  auto r = std::from_chars(b, e, v);
  if (r.ec != std::errc() || (r.ptr < e && !is_space(*r.ptr))) {
    std::string_view t = token();
    fail_at(start, std::string("expected ") + what + ", got '" + printable(t) + "'");
  }
  if (v < lo || v > hi)
    fail_at(start, std::string(what) + " " + std::to_string(v) + " out of range " +
                       std::to_string(lo) + ".." + std::to_string(hi));
  pos_ = static_cast<std::size_t>(r.ptr - data_.data());
  return v;
}

double Scanner::real(const char* what, bool finite_only) {
  skip_space();
  const std::size_t start = pos_;
  if (pos_ >= data_.size()) fail(std::string("unexpected end of file, expected ") + what);
  const char* b = data_.data() + pos_;
  const char* e = data_.data() + data_.size();
  if (*b == '+') ++b;
  double v = 0;
  auto r = std::from_chars(b, e, v);
  if (r.ec == std::errc::result_out_of_range) fail_at(start, std::string(what) + " out of range");
  if (r.ec != std::errc() || (r.ptr < e && !is_space(*r.ptr))) {
    std::string_view t = token();
    fail_at(start, std::string("expected ") + what + ", got '" + printable(t) + "'");
  }
  if (finite_only && !std::isfinite(v)) fail_at(start, std::string(what) + " is not finite");
  pos_ = static_cast<std::size_t>(r.ptr - data_.data());
  return v;
}

std::string_view Scanner::line() {
  const std::size_t start = pos_;
  std::size_t end = data_.find('\n', pos_);
  if (end == std::string_view::npos) end = data_.size();
  pos_ = std::min(end + 1, data_.size());
  std::string_view l = data_.substr(start, end - start);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  return l;
}

void Scanner::skip_line() { line(); }

static std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

bool Scanner::skip_to_line(std::string_view text) {
  while (pos_ < data_.size()) {
    if (trim(line()) == text) return true;
  }
  return false;
}

const char* Scanner::bytes(std::size_t n, const char* what) {
  if (n > remaining())
    fail_byte(pos_, std::string("unexpected end of data reading ") + what + " (" +
                        std::to_string(n) + " bytes needed, " + std::to_string(remaining()) +
                        " left)");
  const char* p = data_.data() + pos_;
  pos_ += n;
  return p;
}

void Scanner::check_count(std::uint64_t count, std::size_t min_bytes_each, const char* what) const {
  // The last item needs no separator after it, hence the + 1.
  if (count > (remaining() + 1) / std::max<std::size_t>(min_bytes_each, 1))
    fail(std::string("declared ") + what + " count " + std::to_string(count) +
         " cannot fit in the " + std::to_string(remaining()) + " bytes left in the file");
}

void Scanner::check_count_binary(std::uint64_t count, std::size_t bytes_each,
                                 const char* what) const {
  if (count > remaining() / std::max<std::size_t>(bytes_each, 1))
    fail_byte(pos_, std::string("declared ") + what + " count " + std::to_string(count) +
                        " cannot fit in the " + std::to_string(remaining()) +
                        " bytes left in the file");
}

int Scanner::line_of(std::size_t pos) const {
  pos = std::min(pos, data_.size());
  return 1 + static_cast<int>(std::count(data_.begin(), data_.begin() + pos, '\n'));
}

void Scanner::fail_at(std::size_t pos, const std::string& what) const {
  throw Error(path_ + ":" + std::to_string(line_of(pos)) + ": " + what);
}

void Scanner::fail_byte(std::size_t pos, const std::string& what) const {
  throw Error(path_ + ":byte " + std::to_string(pos) + ": " + what);
}

}  // namespace io
}  // namespace tmop
