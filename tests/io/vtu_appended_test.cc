// .vtu variants tmop does not write but must read (ParaView / VTK write them): raw appended
// data, zlib-compressed blocks, UInt32 headers and big-endian byte order. The files are built
// here byte by byte from the VTK XML format description.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <fstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

template <typename T>
std::string bytes_of(const std::vector<T>& v, bool big_endian) {
  std::string out;
  for (const T& x : v) {
    char b[sizeof(T)];
    std::memcpy(b, &x, sizeof(T));
    if (big_endian)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.append(b, sizeof(T));
  }
  return out;
}

std::string header_word(std::uint64_t v, bool uint64, bool big_endian) {
  return uint64 ? bytes_of(std::vector<std::uint64_t>{v}, big_endian)
                : bytes_of(std::vector<std::uint32_t>{static_cast<std::uint32_t>(v)}, big_endian);
}

// One appended block: [header][data], compressed as VTK does (blocks of block_size bytes).
std::string block(const std::string& data, bool uint64, bool big_endian, bool zlib) {
  if (!zlib) return header_word(data.size(), uint64, big_endian) + data;
  const std::size_t block_size = 64;  // small, so that several blocks are exercised
  std::vector<std::string> parts;
  for (std::size_t p = 0; p < data.size(); p += block_size) {
    const std::string chunk = data.substr(p, block_size);
    uLongf n = compressBound(chunk.size());
    std::string z(n, '\0');
    compress2(reinterpret_cast<Bytef*>(&z[0]), &n, reinterpret_cast<const Bytef*>(chunk.data()),
              chunk.size(), 6);
    z.resize(n);
    parts.push_back(z);
  }
  std::string out = header_word(parts.size(), uint64, big_endian) +
                    header_word(block_size, uint64, big_endian) +
                    header_word(data.size() % block_size, uint64, big_endian);
  for (const std::string& z : parts) out += header_word(z.size(), uint64, big_endian);
  for (const std::string& z : parts) out += z;
  return out;
}

void check(bool uint64, bool big_endian, bool zlib) {
  SCOPED_TRACE(std::string("uint64 ") + (uint64 ? "1" : "0") + " big " + (big_endian ? "1" : "0") +
               " zlib " + (zlib ? "1" : "0"));
  const std::string dir = test::temp_dir();
  // Two tets and a wedge sharing nodes, plus a float32 cell field.
  const std::vector<double> xyz = {0, 0, 0, 1,   0,    0,     0,   1,   0,
                                   0, 0, 1, 1.5, 0.25, 0.125, 0.1, 0.2, 0.3};
  const std::vector<std::int32_t> conn = {0, 1, 2, 3, 1, 2, 3, 4, 0, 1, 2, 3, 4, 5};
  const std::vector<std::int32_t> offsets = {4, 8, 14};
  const std::vector<std::uint8_t> types = {10, 10, 13};
  const std::vector<float> q = {0.5f, 0.25f, -1.0f};
  const std::vector<std::int32_t> phys = {7, 7, 9};
  std::string app;
  std::vector<std::size_t> off;
  for (const std::string& d :
       {bytes_of(xyz, big_endian), bytes_of(conn, big_endian), bytes_of(offsets, big_endian),
        bytes_of(types, big_endian), bytes_of(q, big_endian), bytes_of(phys, big_endian)}) {
    off.push_back(app.size());
    app += block(d, uint64, big_endian, zlib);
  }
  auto arr = [&](const char* type, const char* name, int comps, std::size_t o) {
    return std::string("<DataArray type=\"") + type + "\"" + (name[0] ? " Name=\"" : "") + name +
           (name[0] ? "\"" : "") + " NumberOfComponents=\"" + std::to_string(comps) +
           "\" format=\"appended\" offset=\"" + std::to_string(o) + "\"/>\n";
  };
  std::string xml =
      std::string("<?xml version=\"1.0\"?>\n<!-- written by a test -->\n") +
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" +
      (big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
      (uint64 ? "UInt64" : "UInt32") + "\"" +
      (zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") +
      ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"6\" NumberOfCells=\"3\">\n" + "<Points>\n" +
      arr("Float64", "", 3, off[0]) + "</Points>\n<Cells>\n" +
      arr("Int32", "connectivity", 1, off[1]) + arr("Int32", "offsets", 1, off[2]) +
      arr("UInt8", "types", 1, off[3]) + "</Cells>\n<CellData>\n" + arr("Float32", "q", 1, off[4]) +
      arr("Int32", "gmsh:physical", 1, off[5]) + "</CellData>\n</Piece>\n</UnstructuredGrid>\n" +
      "<AppendedData encoding=\"raw\">\n   _" + app + "\n</AppendedData>\n</VTKFile>\n";
  const std::string path = dir + "/appended.vtu";
  std::ofstream(path, std::ios::binary) << xml;
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.coords, xyz);
  ASSERT_EQ(m.num_cells(), 3);
  EXPECT_EQ(m.cell_types[0], CellType::kTet4);
  EXPECT_EQ(m.cell_types[2], CellType::kWedge6);
  // VTK wedge 0 1 2 3 4 5 is Gmsh wedge 0 2 1 3 5 4.
  EXPECT_EQ(std::vector<std::int32_t>(m.cell(2), m.cell(2) + 6),
            (std::vector<std::int32_t>{0, 2, 1, 3, 5, 4}));
  EXPECT_EQ(m.cell_region, (std::vector<std::int32_t>{7, 7, 9}));
  ASSERT_EQ(m.cell_data.size(), 1u);
  EXPECT_EQ(m.cell_data[0].values, (std::vector<double>{0.5, 0.25, -1.0}));
}

TEST(VtuAppended, RawUInt32LittleEndian) { check(false, false, false); }
TEST(VtuAppended, RawUInt64BigEndian) { check(true, true, false); }
TEST(VtuAppended, ZlibUInt64LittleEndian) { check(true, false, true); }
TEST(VtuAppended, ZlibUInt32BigEndian) { check(false, true, true); }

}  // namespace
}  // namespace tmop
