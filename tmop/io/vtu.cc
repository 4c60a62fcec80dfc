#include "tmop/io/formats.h"
namespace tmop {
namespace io {
void read_vtu(const std::string& path, const std::string&, Mesh*) {
  throw Error(path + ": not implemented");
}
void write_vtu(const Mesh&, const WriteOptions&, std::string*) { throw Error("not implemented"); }
}  // namespace io
}  // namespace tmop
