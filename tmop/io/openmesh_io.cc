#include "tmop/io/formats.h"
namespace tmop {
namespace io {
void read_openmesh(const std::string& path, Mesh*) { throw Error(path + ": not implemented"); }
void write_openmesh(const std::string&, const std::string&, const Mesh&, const WriteOptions&) {
  throw Error("not implemented");
}
}  // namespace io
}  // namespace tmop
