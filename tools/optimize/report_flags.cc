// tools/optimize/report_flags.cc
// Reading a run report back (--from_report): report_flags.h. Kept apart from run_report.cc (the
// writer, which needs the recipes and quality libraries) so that tests/fuzz compiles it alone.
#include "tools/optimize/report_flags.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>

namespace tmop_tools {
namespace {

// Text from the report in a message: at most 40 bytes, control bytes and DEL as '?'.
std::string printable(const std::string& s) {
  std::string out = s.substr(0, 40);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

// A minimal reader of the one object apply_report_flags needs: {"name": "value", ...} with
// JSON string escapes (what flags_json writes). Throws the message on malformed text.
class FlatObjectReader {
 public:
  explicit FlatObjectReader(const std::string& text, std::size_t at) : t_(text), i_(at) {}
  std::map<std::string, std::string> read() {
    std::map<std::string, std::string> out;
    expect('{');
    if (peek() == '}') return ++i_, out;
    for (;;) {
      std::string key = string();
      expect(':');
      out[key] = string();
      const char c = peek();
      ++i_;
      if (c == '}') return out;
      if (c != ',') fail("expected ',' or '}'");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) {
    throw tmop::Error("byte " + std::to_string(i_) + ": " + what);
  }
  char peek() {
    while (i_ < t_.size() && std::strchr(" \t\r\n", t_[i_])) ++i_;
    if (i_ >= t_.size()) fail("unexpected end of file");
    return t_[i_];
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  std::string string() {
    expect('"');
    std::string s;
    while (i_ < t_.size() && t_[i_] != '"') {
      char c = t_[i_++];
      if (c == '\\') {
        if (i_ >= t_.size()) break;
        c = t_[i_++];
        if (c == 'n')
          c = '\n';
        else if (c == 't')
          c = '\t';
        else if (c == 'r')
          c = '\r';
        else if (c == 'b')
          c = '\b';
        else if (c == 'f')
          c = '\f';
        else if (c == 'u')
          c = unicode_escape();
        else if (c != '"' && c != '\\' && c != '/')
          fail(std::string("bad escape \\") + printable(std::string(1, c)));
      }
      s += c;
    }
    if (i_ >= t_.size()) fail("unterminated string");
    ++i_;
    return s;
  }
  // The 4 hex digits after \u, below 0x80 (what run_report writes).
  char unicode_escape() {
    if (i_ + 4 > t_.size() || t_.find_first_not_of("0123456789abcdefABCDEF", i_) < i_ + 4)
      fail("bad \\u escape (4 hex digits)");
    const unsigned long u = std::strtoul(t_.substr(i_, 4).c_str(), nullptr, 16);
    i_ += 4;
    if (u >= 0x80) fail("non-ASCII \\u escape");
    return static_cast<char>(u);
  }
  const std::string& t_;
  std::size_t i_;
};

}  // namespace

std::vector<gflags::CommandLineFlagInfo> tool_flags(const std::string& flag_file) {
  std::vector<gflags::CommandLineFlagInfo> all, out;
  gflags::GetAllFlags(&all);
  for (const auto& f : all)
    if (f.filename.find(flag_file) != std::string::npos) out.push_back(f);
  return out;
}

tmop::Status apply_report_flags(const std::string& path, const std::string& flag_file) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return tmop::Status::Failure(path + ": cannot open (" + std::strerror(errno) + ")");
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const std::size_t key = text.find("\"flags\":");
  if (key == std::string::npos)
    return tmop::Status::Failure(path + ": not a tmop_optimize report (no \"flags\" object)");
  std::map<std::string, std::string> flags;
  try {
    flags = FlatObjectReader(text, key + 8).read();
  } catch (const tmop::Error& e) {
    return tmop::Status::Failure(path + ": " + e.what());
  }
  for (const auto& info : tool_flags(flag_file)) {
    const auto it = flags.find(info.name);
    // Defaults stay defaults (the tool tells given flags from defaults: --boundary, --target_*).
    if (it == flags.end() || !info.is_default || it->second == info.default_value ||
        info.name == "output" || info.name == "report" || info.name == "from_report")
      continue;
    if (gflags::SetCommandLineOption(info.name.c_str(), it->second.c_str()).empty())
      return tmop::Status::Failure(path + ": flag --" + info.name + ": bad value '" +
                                   printable(it->second) + "'");
  }
  return tmop::Status::Ok();
}

}  // namespace tmop_tools
