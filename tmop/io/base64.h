// tmop/io/base64.h
// Base64 (RFC 4648) as used by VTK XML "binary" arrays. The decoder accepts several separately
// padded chunks in a row (VTK encodes the compression header and the data blocks separately),
// ignores whitespace, and reports the offset of the first invalid character.
#ifndef TMOP_IO_BASE64_H_
#define TMOP_IO_BASE64_H_

#include <string>
#include <string_view>

namespace tmop {
namespace io {

void base64_encode(const unsigned char* data, std::size_t n, std::string* out);
// Appends the decoded bytes to *out. Returns false and sets *bad to the offset of the first
// invalid character on failure.
bool base64_decode(std::string_view text, std::string* out, std::size_t* bad);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_BASE64_H_
