// tmop/io/text_format.h
// Appending numbers to an output buffer for the ASCII writers. Doubles use std::to_chars'
// shortest representation that reads back to the same bit pattern (as exact as "%.17g", shorter
// and locale-independent), so ASCII round trips are bit-exact.
#ifndef TMOP_IO_TEXT_FORMAT_H_
#define TMOP_IO_TEXT_FORMAT_H_

#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>

namespace tmop {
namespace io {

inline void append_double(std::string* out, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out->append(buf, r.ptr);
}

inline void append_int(std::string* out, std::int64_t v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof(buf), v);
  out->append(buf, r.ptr);
}

// Raw bytes of a value, optionally byte-swapped (VTK legacy binary is big-endian).
template <typename T>
void append_binary(std::string* out, T v, bool swap = false) {
  char buf[sizeof(T)];
  std::memcpy(buf, &v, sizeof(T));
  if (swap)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) {
      char t = buf[i];
      buf[i] = buf[sizeof(T) - 1 - i];
      buf[sizeof(T) - 1 - i] = t;
    }
  out->append(buf, sizeof(T));
}

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_TEXT_FORMAT_H_
