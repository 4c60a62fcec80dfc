// Inputs that are not what their name says (issue 19): directories, devices, FIFOs and huge
// files are refused before they are read, from their first bytes; reader messages quote file
// text in a bounded printable form; cell errors point at the cell's own line.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

std::string read_error(const std::string& path) {
  Mesh mesh;
  const Status s = read_mesh(path, &mesh);
  EXPECT_FALSE(s.ok()) << path << " was accepted";
  EXPECT_EQ(mesh.num_vertices(), 0);
  return s.message();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool printable_line(const std::string& m) {
  for (char c : m)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) return false;
  return true;
}

TEST(HostileInput, ADirectoryIsNotARegularFile) {
  const std::string dir = test::temp_dir();
  for (const char* name : {"/x.msh", "/x.vtk", "/x.vtu", "/x.stl", "/x.obj"}) {
    ASSERT_EQ(mkdir((dir + name).c_str(), 0755), 0);
    EXPECT_EQ(read_error(dir + name), dir + name + ": not a regular file (a directory)");
  }
  // Not "unknown mesh file extension '.'".
  EXPECT_EQ(read_error(dir + "/."), dir + "/.: not a regular file (a directory)");
  EXPECT_EQ(read_error(dir), dir + ": not a regular file (a directory)");
}

TEST(HostileInput, DevicesAndFifosAreRefusedWithoutReading) {
  const std::string dir = test::temp_dir();
  ASSERT_EQ(symlink("/dev/zero", (dir + "/z.msh").c_str()), 0);
  ASSERT_EQ(symlink("/dev/urandom", (dir + "/u.vtk").c_str()), 0);
  ASSERT_EQ(mkfifo((dir + "/f.msh").c_str(), 0644), 0);  // opening it would block forever
  EXPECT_EQ(read_error(dir + "/z.msh"), dir + "/z.msh: not a regular file (a character device)");
  EXPECT_EQ(read_error(dir + "/u.vtk"), dir + "/u.vtk: not a regular file (a character device)");
  EXPECT_EQ(read_error(dir + "/f.msh"), dir + "/f.msh: not a regular file (a FIFO)");
}

// A 3 GB file of NUL bytes (sparse: no disk space, created at once) is judged by its first bytes:
// the reader never holds the 3 GB.
TEST(HostileInput, AHugeFileOfTheWrongKindIsRejectedFromItsFirstBytes) {
  const std::string dir = test::temp_dir();
  const std::string big = dir + "/big.bin";
  const int fd = ::open(big.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::ftruncate(fd, 3LL << 30), 0) << "no sparse files here";
  ::close(fd);
  struct Case {
    const char* ext;
    const char* message;
  };
  const Case cases[] = {
      {"msh", ":1: not a Gmsh file: expected $MeshFormat"},
      {"vtk", ":1: not a VTK legacy file"},
      {"vtu", ":1: not a VTK XML file"},
      {"stl", ":byte 80: binary STL declares 0 triangles, the file size 3221225472 does not match"},
      {"ply", ":1: not a PLY file"},
      {"mesh", ":1: binary data (a NUL byte) where a text file was expected"},
      {"obj", ":1: binary data (a NUL byte) where a text file was expected"},
      {"off", ":1: binary data (a NUL byte) where a text file was expected"},
  };
  for (const Case& c : cases) {
    const std::string path = dir + "/big." + c.ext;
    ASSERT_EQ(symlink(big.c_str(), path.c_str()), 0);
    const std::string m = read_error(path);
    EXPECT_EQ(m.rfind(path + c.message, 0), 0u) << m;
  }
  // Peak memory of this process stays far below the file size.
  struct rusage ru;
  ASSERT_EQ(getrusage(RUSAGE_SELF, &ru), 0);
  EXPECT_LT(ru.ru_maxrss, 512L * 1024) << "KB";
}

// The first-bytes check lets valid files through, also those whose first 64 KiB are only a
// start: a binary STL that happens to begin with "solid", leading whitespace, a short file.
TEST(HostileInput, TheFirstBytesCheckAcceptsValidFiles) {
  const std::string dir = test::temp_dir();
  Mesh m = test::make_mesh({CellType::kTri3});
  for (const char* name : {"/a.msh", "/a.vtk", "/a.vtu", "/a.stl", "/a.ply", "/a.obj", "/a.off"}) {
    ASSERT_TRUE(write_mesh(dir + name, m).ok()) << name;
    Mesh back;
    EXPECT_TRUE(read_mesh(dir + name, &back).ok()) << name;
  }
  WriteOptions bin;
  bin.binary = true;
  ASSERT_TRUE(write_mesh(dir + "/b.stl", m, bin).ok());
  std::string bytes;
  {
    std::ifstream f(dir + "/b.stl", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(f), {});
  }
  bytes.replace(0, 5, "solid");  // a binary STL header may start with "solid"
  write_text(dir + "/c.stl", bytes);
  Mesh back;
  EXPECT_TRUE(read_mesh(dir + "/c.stl", &back).ok());
  write_text(dir + "/ws.msh", std::string(70000, ' ') + "junk");
  EXPECT_NE(read_error(dir + "/ws.msh").find("not a Gmsh file"), std::string::npos);
}

// UBSan found vtu.cc casting a cell type of 1.37e11 to int before its range check.
TEST(HostileInput, VtuCellTypeOutsideIntIsAnError) {
  const std::string dir = test::temp_dir();
  for (const char* type : {"137000000000", "-5e300", "4294967301", "5.5"}) {
    write_text(dir + "/t.vtu",
               std::string("<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid>"
                           "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\"><Points>"
                           "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
                           "0 0 0 1 0 0 0 1 0</DataArray></Points><Cells>"
                           "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2"
                           "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" "
                           "format=\"ascii\">3</DataArray><DataArray type=\"Float64\" "
                           "Name=\"types\" format=\"ascii\">") +
                   type + "</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>\n");
    const std::string m = read_error(dir + "/t.vtu");
    EXPECT_NE(m.find("unsupported VTK cell type"), std::string::npos) << m;
  }
}

// Attribute text reached messages raw: newlines, terminal escapes, 10 MB.
TEST(HostileInput, VtuMessagesQuoteAttributesPrintablyAndBriefly) {
  const std::string dir = test::temp_dir();
  const std::string evil = "\x1b]0;owned\x07\x1b[2J\nline two" + std::string(10 << 20, 'A');
  const std::string head =
      "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"3\" "
      "NumberOfCells=\"1\"><Points>";
  const std::string cases[] = {
      head + "<DataArray type=\"" + evil + "\" NumberOfComponents=\"3\">",
      head + "<DataArray type=\"Float64\" Name=\"" + evil + "\" format=\"" + evil + "\">",
      head + "<DataArray type=\"Float64\" NumberOfComponents=\"" + evil + "\">",
      "<VTKFile type=\"UnstructuredGrid\" compressor=\"" + evil + "\">",
  };
  for (const std::string& text : cases) {
    write_text(dir + "/e.vtu", text + "</DataArray></Points></Piece></UnstructuredGrid></VTKFile>");
    const std::string m = read_error(dir + "/e.vtu");
    EXPECT_TRUE(printable_line(m)) << m.substr(0, 200);
    EXPECT_LT(m.size(), 400u) << m.substr(0, 200);
  }
}

// Names decoded from %XX and unknown section names reach messages only in printable form.
TEST(HostileInput, LegacyMessagesQuoteFileTextPrintably) {
  const std::string dir = test::temp_dir();
  write_text(dir + "/n.vtk",
             "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n"
             "0 0 0\n1 0 0\n0 1 0\nCELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n5\nPOINT_DATA 3\n"
             "FIELD FieldData 1\n%1B]0;x%07%0A 1 2 double\n1 2\n");
  std::string m = read_error(dir + "/n.vtk");
  EXPECT_TRUE(printable_line(m)) << m;
  EXPECT_NE(m.find("field array '?]0;x?"
                   "?' has 2"),
            std::string::npos)
      << m;
  write_text(dir + "/s.msh",
             "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$\x1b[2J" + std::string(1 << 20, 'x') + "\n");
  m = read_error(dir + "/s.msh");
  EXPECT_TRUE(printable_line(m)) << m.substr(0, 100);
  EXPECT_LT(m.size(), 300u);
  write_text(dir + "/v.msh", "$MeshFormat\n\x1b[2J9.9 0 8\n$EndMeshFormat\n");
  m = read_error(dir + "/v.msh");
  EXPECT_TRUE(printable_line(m)) << m;
}

// The bad cell is reported at its own line (was: the CELL_TYPES / CELLS keyword's line).
TEST(HostileInput, VtkCellErrorsPointAtTheCell) {
  const std::string dir = test::temp_dir();
  const std::string points =
      "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 3 double\n"
      "0 0 0\n1 0 0\n0 1 0\n";
  write_text(dir + "/a.vtk", points +
                                 "CELLS 3 12\n3 0 1 2\n3 0 1 2\n3 0 1 2\nCELL_TYPES 3\n5\n5\n"
                                 "42\n");
  // The refusal names the VTK type and lists what tmop reads instead.
  EXPECT_EQ(read_error(dir + "/a.vtk"), dir +
                                            "/a.vtk:16: cell 2: unsupported VTK cell type 42 "
                                            "(VTK_POLYHEDRON; tmop reads " +
                                            supported_cell_types() + ")");
  // 2^32 + 5 is not a triangle (a cast to int made it one).
  write_text(dir + "/b.vtk", points + "CELLS 1 4\n3 0 1 2\nCELL_TYPES 1\n4294967301\n");
  EXPECT_EQ(read_error(dir + "/b.vtk"),
            dir + "/b.vtk:12: cell 0: unsupported VTK cell type 4294967301 (tmop reads " +
                supported_cell_types() + ")");
  write_text(dir + "/c.vtk",
             points + "CELLS 3 12\n3 0 1 2\n3 0 1 2\n3 0 1 7\nCELL_TYPES 3\n5\n5\n5\n");
  EXPECT_EQ(read_error(dir + "/c.vtk"),
            dir + "/c.vtk:12: cell 2 refers to point 7, out of range 0..2");
  write_text(dir + "/d.vtk", points + "CELLS 2 9\n3 0 1 2\n\n4 0 1 2 0\nCELL_TYPES 2\n5\n5\n");
  EXPECT_NE(read_error(dir + "/d.vtk").find("/d.vtk:12: cell 1 (tri3) has 4 nodes"),
            std::string::npos);
}

}  // namespace
}  // namespace tmop
