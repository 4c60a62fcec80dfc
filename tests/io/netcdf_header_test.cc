// The netCDF classic header check (io/netcdf_header.cc) that read_exodus runs before libnetcdf:
// crafted headers (cut short, a huge dimension, a huge attribute, absurd counts, bad layout)
// are refused with one line naming the file and byte; files tmop writes pass.
#include "tmop/io/netcdf_header.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "io_test_util.h"
#include "tmop/core/status.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using io::NetcdfHeader;

// Big-endian CDF-1 header bytes.
struct Cdf {
  std::string b = std::string("CDF\x01", 4);
  Cdf& u32(std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<char>((v >> s) & 0xff));
    return *this;
  }
  Cdf& name(const std::string& n) {
    u32(static_cast<std::uint32_t>(n.size()));
    b += n;
    while (b.size() % 4) b.push_back('\0');
    return *this;
  }
  Cdf& raw(std::size_t n, char c = '\0') { return b.append(n, c), *this; }
};

std::string write_file(const std::string& name, const std::string& bytes) {
  const std::string path = test::temp_dir() + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// The message of the Error check_exodus_file throws ("" when it accepts the file).
std::string refusal(const std::string& path) {
  try {
    io::check_exodus_file(path);
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(m.compare(0, path.size(), path), 0) << m;
    return m;
  }
  return "";
}

// numrecs 0, one dimension n = len, one global attribute, one int variable v(n) at `begin`.
Cdf one_var(std::uint32_t len, std::uint32_t attr_count, std::uint32_t begin) {
  Cdf c;
  c.u32(0).u32(0x0A).u32(1).name("n").u32(len);
  c.u32(0x0C).u32(1).name("title").u32(2).u32(attr_count).raw(4, 'x');
  c.u32(0x0B).u32(1).name("v").u32(1).u32(0).u32(0).u32(0).u32(4).u32(4 * len).u32(begin);
  return c;
}

TEST(NetcdfHeader, AcceptsAWellFormedCraftedFile) {
  Cdf c = one_var(3, 4, 0);
  const std::uint32_t begin = static_cast<std::uint32_t>(c.b.size());
  c = one_var(3, 4, begin);
  c.raw(12);
  NetcdfHeader h;
  io::read_netcdf_header(write_file("ok.exo", c.b), &h);
  EXPECT_EQ(h.version, 1);
  ASSERT_EQ(h.dims.size(), 1u);
  EXPECT_EQ(h.dims[0].length, 3u);
  ASSERT_EQ(h.vars.size(), 1u);
  EXPECT_EQ(h.vars[0].begin, begin);
  EXPECT_EQ(h.vars[0].bytes, 12u);
  EXPECT_EQ(h.header_bytes, begin);
}

TEST(NetcdfHeader, RefusesATruncatedHeader) {
  Cdf c = one_var(3, 4, 0);
  const std::string cut = c.b.substr(0, c.b.size() - 2);  // half the last field, begin
  const std::string m = refusal(write_file("cut.exo", cut));
  EXPECT_NE(m.find("the header is cut short"), std::string::npos) << m;
  EXPECT_NE(refusal(write_file("magic.exo", "CD")).find("cut short"), std::string::npos);
  EXPECT_NE(refusal(write_file("empty.exo", "")).find("cut short"), std::string::npos);
}

TEST(NetcdfHeader, RefusesDataPastTheEndOfTheFile) {
  Cdf c = one_var(3, 4, 0);
  c = one_var(3, 4, static_cast<std::uint32_t>(c.b.size()));
  c.raw(11);  // one byte short of 3 ints
  EXPECT_NE(refusal(write_file("short.exo", c.b)).find("variable 'v': data at bytes"),
            std::string::npos);
}

TEST(NetcdfHeader, RefusesAHugeDimension) {
  Cdf c = one_var(0x7fffffff, 4, 0);
  c = one_var(0x7fffffff, 4, static_cast<std::uint32_t>(c.b.size()));
  c.raw(64);
  const std::string m = refusal(write_file("huge_dim.exo", c.b));
  EXPECT_NE(m.find("variable 'v' is larger than the"), std::string::npos) << m;
}

TEST(NetcdfHeader, RefusesAHugeAttribute) {
  const std::string m = refusal(write_file("huge_attr.exo", one_var(3, 0x7ffffff0, 200).b));
  EXPECT_NE(m.find("attribute 'title' declares 2147483632 values"), std::string::npos) << m;
}

TEST(NetcdfHeader, RefusesAbsurdCounts) {
  Cdf dims;
  dims.u32(0).u32(0x0A).u32(100000000).raw(64);
  std::string m = refusal(write_file("dims.exo", dims.b));
  EXPECT_NE(m.find("100000000 dimensions declared"), std::string::npos) << m;
  Cdf name;
  name.u32(0).u32(0x0A).u32(1).u32(1000).raw(2000, 'a');
  m = refusal(write_file("name.exo", name.b));
  EXPECT_NE(m.find("name of 1000 bytes"), std::string::npos) << m;
  Cdf streaming;
  streaming.u32(0xffffffff).raw(24);
  m = refusal(write_file("streaming.exo", streaming.b));
  EXPECT_NE(m.find("STREAMING"), std::string::npos) << m;
}

TEST(NetcdfHeader, RefusesABadRecordDimensionAndType) {
  // Two record dimensions.
  Cdf two;
  two.u32(0).u32(0x0A).u32(2).name("a").u32(0).name("b").u32(0).raw(32);
  EXPECT_NE(refusal(write_file("two.exo", two.b)).find("a second record dimension 'b'"),
            std::string::npos);
  // v(n, t) with t the record dimension second.
  Cdf late;
  late.u32(0).u32(0x0A).u32(2).name("n").u32(2).name("t").u32(0).u32(0).u32(0);
  late.u32(0x0B).u32(1).name("v").u32(2).u32(0).u32(1).u32(0).u32(0).u32(4).u32(8).u32(200);
  late.raw(64);
  EXPECT_NE(refusal(write_file("late.exo", late.b)).find("the record dimension is not its first"),
            std::string::npos);
  Cdf type;
  type.u32(0).u32(0).u32(0).u32(0x0C).u32(1).name("x").u32(7).u32(1).raw(32);
  EXPECT_NE(refusal(write_file("type.exo", type.b)).find("bad type 7"), std::string::npos);
}

// netCDF-4 files (what meshio writes) go to libhdf5 unchecked (netcdf_header.h says why).
TEST(NetcdfHeader, PassesNetcdf4ToLibhdf5) {
  EXPECT_EQ(refusal(write_file("h.exo", std::string("\x89HDF\r\n\x1a\n", 8) + "xxxx")), "");
}

#ifdef TMOP_TEST_WITH_EXODUS

Mesh two_blocks() { return test::make_mesh({CellType::kTet4, CellType::kHex8}); }

TEST(NetcdfHeader, AcceptsWhatTmopWrites) {
  const std::string path = test::temp_dir() + "/m.exo";
  ASSERT_TRUE(write_mesh(path, two_blocks()).ok());
  EXPECT_EQ(refusal(path), "");
  NetcdfHeader h;
  io::read_netcdf_header(path, &h);
  bool coordx = false;
  for (const io::NetcdfVar& v : h.vars)
    if (v.name == "coordx")
      coordx = v.bytes == 8u * two_blocks().num_vertices() && v.begin + v.bytes <= h.file_bytes;
  EXPECT_TRUE(coordx);
}

// A valid Exodus file whose connect1 is declared over other dimensions: libexodusii would read
// it into a buffer sized from num_el_in_blk1 x num_nod_per_el1.
TEST(NetcdfHeader, RefusesAnExodusVariableOverOtherDimensions) {
  const std::string path = test::temp_dir() + "/m.exo";
  ASSERT_TRUE(write_mesh(path, two_blocks()).ok());
  std::ifstream f(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  // Rename num_nod_per_el1 to a dimension name of the same length that connect1 does not expect.
  const std::size_t at = bytes.find("num_nod_per_el1");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'x';
  const std::string bad = write_file("bad.exo", bytes);
  const std::string m = refusal(bad);
  EXPECT_NE(m.find("variable 'connect1' is not defined over (num_el_in_blk1, num_nod_per_el1)"),
            std::string::npos)
      << m;
  Mesh back;
  const Status s = read_mesh(bad, &back);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), m);
}

// ex_open reads "version" into one float: a crafted array of 100 would overrun it.
TEST(NetcdfHeader, RefusesAnExodusScalarAttributeOfManyValues) {
  Cdf c;
  c.u32(0).u32(0).u32(0).u32(0x0C).u32(1).name("version").u32(5).u32(100).raw(400);
  c.u32(0).u32(0);
  const std::string m = refusal(write_file("version.exo", c.b));
  EXPECT_NE(m.find("Exodus II attribute 'version' is not one number"), std::string::npos) << m;
}

// Found with valgrind on fuzz inputs: without connect1's elem_type (or without connect1),
// ex_get_block strcpy's an uninitialised buffer into the caller's type.
TEST(NetcdfHeader, RefusesAnExodusBlockWithoutElemTypeOrConnectivity) {
  const std::string path = test::temp_dir() + "/m.exo";
  ASSERT_TRUE(write_mesh(path, two_blocks()).ok());
  std::ifstream f(path, std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  std::string bytes = good;
  std::size_t at = bytes.find("elem_type");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'x';
  std::string m = refusal(write_file("untyped.exo", bytes));
  EXPECT_NE(m.find("variable 'connect1' has no elem_type attribute"), std::string::npos) << m;
  bytes = good;
  at = bytes.find("connect2");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'x';
  m = refusal(write_file("unconnected.exo", bytes));
  EXPECT_NE(m.find("element block 2 has no connect2"), std::string::npos) << m;
}

// A null block (eb_status 0, no num_el_in_blk1 / connect1; python3-netcdf4 from sq_a.exo) reads;
// an active block without them is refused (regressions/exo/active_block_without_dims.exo).
TEST(NetcdfHeader, NullBlocksReadActiveBlocksNeedTheirConnectivity) {
  const std::string dir = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/";
  Mesh mesh;
  const Status ok = read_mesh(dir + "corpus/exo/sq_null_block.exo", &mesh);
  ASSERT_TRUE(ok.ok()) << ok.message();
  EXPECT_EQ(mesh.num_cells(), 14);
  const std::string m = refusal(dir + "regressions/exo/active_block_without_dims.exo");
  EXPECT_NE(m.find("element block 1 has no num_el_in_blk1"), std::string::npos) << m;
}

TEST(NetcdfHeader, ReadMeshRefusesACutExodusFile) {
  const std::string path = test::temp_dir() + "/m.exo";
  ASSERT_TRUE(write_mesh(path, two_blocks()).ok());
  std::ifstream f(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const std::string cut = write_file("cut.exo", bytes.substr(0, bytes.size() - 9));
  Mesh back;
  const Status s = read_mesh(cut, &back);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("cut.exo: netCDF header, byte "), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("outside the data part"), std::string::npos) << s.message();
}

// Fuzz findings: a variable name and an element type with control bytes went into the message.
TEST(NetcdfHeader, MessagesQuoteFileBytesPrintable) {
  const std::string dir = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/regressions/exo/";
  for (const char* name : {"control_char_var_name.exo", "control_char_elem_type.exo"}) {
    Mesh mesh;
    const Status s = read_mesh(dir + name, &mesh);
    ASSERT_FALSE(s.ok()) << name;
    for (unsigned char c : s.message()) EXPECT_TRUE(c >= 0x20 && c != 0x7f) << s.message();
  }
}

#endif  // TMOP_TEST_WITH_EXODUS

}  // namespace
}  // namespace tmop
