#include "tmop/io/scanner.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace tmop {
namespace io {

std::string read_file(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw Error(path + ": cannot open for reading");
  std::string data;
  if (std::fseek(f, 0, SEEK_END) == 0) {
    long size = std::ftell(f);
    if (size > 0) data.reserve(static_cast<std::size_t>(size));
    std::fseek(f, 0, SEEK_SET);
  }
  char buf[1 << 16];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0) data.append(buf, n);
  const bool bad = std::ferror(f);
  std::fclose(f);
  if (bad) throw Error(path + ": read error");
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
