// The isolated read of HDF5-based files (io/isolated_read.h, io/mesh_pipe.h): the same mesh as a
// direct read field by field, a child that crashes or is interrupted becomes one line, a damaged
// stream is an error, and the switch is off under MPI.
#include "tmop/io/isolated_read.h"

#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"
#include "tmop/io/mesh_pipe.h"

namespace tmop {
namespace {

// Every field of Mesh, compared exactly (the stream must not change a bit).
std::string exact_difference(const Mesh& a, const Mesh& b) {
  if (a.space_dim != b.space_dim) return "space_dim";
  if (std::memcmp(&a.plane_z, &b.plane_z, sizeof(double)) != 0) return "plane_z";
  if (a.coords.size() != b.coords.size() ||
      (!a.coords.empty() &&
       std::memcmp(a.coords.data(), b.coords.data(), a.coords.size() * sizeof(double)) != 0))
    return "coords";
  if (a.cell_types != b.cell_types) return "cell_types";
  if (a.cell_offsets != b.cell_offsets) return "cell_offsets";
  if (a.cell_nodes != b.cell_nodes) return "cell_nodes";
  if (a.cell_region != b.cell_region) return "cell_region";
  if (a.cell_entity != b.cell_entity) return "cell_entity";
  for (int k = 0; k < 2; ++k) {
    const auto& x = k ? a.cell_data : a.point_data;
    const auto& y = k ? b.cell_data : b.point_data;
    if (x.size() != y.size()) return "data array count";
    for (std::size_t i = 0; i < x.size(); ++i)
      if (x[i].name != y[i].name || x[i].components != y[i].components ||
          x[i].values != y[i].values)
        return "data array " + x[i].name;
  }
  if (a.physical_names.size() != b.physical_names.size()) return "physical name count";
  for (std::size_t i = 0; i < a.physical_names.size(); ++i) {
    const PhysicalName &p = a.physical_names[i], &q = b.physical_names[i];
    if (p.dim != q.dim || p.tag != q.tag || p.name != q.name) return "physical name " + p.name;
  }
  if (a.periodic.size() != b.periodic.size()) return "periodic count";
  for (std::size_t i = 0; i < a.periodic.size(); ++i) {
    const PeriodicLink &p = a.periodic[i], &q = b.periodic[i];
    if (p.dim != q.dim || p.tag != q.tag || p.master_tag != q.master_tag || p.affine != q.affine ||
        p.nodes != q.nodes)
      return "periodic link " + std::to_string(i);
  }
  return "";
}

// A mesh with every field set: 2D at z = 5, names with odd bytes, data arrays, periodic links.
Mesh full_mesh() {
  Mesh m =
      test::make_mesh({CellType::kTri3, CellType::kQuad4, CellType::kTri6, CellType::kLine3}, 2);
  m.plane_z = 5.25;
  m.cell_entity.assign(m.num_cells(), 7);
  m.point_data.push_back({"p", 2, std::vector<double>(2 * m.num_vertices(), -0.0)});
  m.cell_data.push_back({"", 1, std::vector<double>(m.num_cells(), 1e-310)});
  m.set_physical_name(2, 1, "fluid");
  m.set_physical_name(1, 4, std::string("in\0let\n", 7));
  PeriodicLink l;
  l.dim = 1;
  l.tag = 3;
  l.master_tag = 2;
  l.affine.assign(16, 0.5);
  l.nodes = {{0, 1}, {2, 3}};
  m.periodic = {l, PeriodicLink()};
  return m;
}

// mesh through a pipe (a thread sends, as the child does), received into *back.
char through_pipe(const Mesh& mesh, Mesh* back, std::string* message) {
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  bool sent = false;
  std::thread sender([&] {
    sent = io::send_mesh(fds[1], mesh);
    ::close(fds[1]);
  });
  char kind = 0;
  try {
    kind = io::receive_mesh(fds[0], back, message);
  } catch (const Error& e) {
    *message = e.what();
  }
  ::close(fds[0]);
  sender.join();
  EXPECT_TRUE(sent);
  return kind;
}

TEST(MeshPipe, CarriesEveryFieldOfTheMesh) {
  const Mesh m = full_mesh();
  Mesh back;
  std::string message;
  ASSERT_EQ(through_pipe(m, &back, &message), 'M') << message;
  EXPECT_EQ(exact_difference(m, back), "");
  EXPECT_NE(exact_difference(m, Mesh()), "");  // the comparison can fail
}

TEST(MeshPipe, StreamsALargeMesh) {
  Mesh m;
  m.coords.resize(3 * 400000);
  for (std::size_t i = 0; i < m.coords.size(); ++i) m.coords[i] = 1.0 / (1.0 + i);
  for (int c = 0; c + 3 < 400000; c += 4) {
    const std::int32_t n[4] = {c, c + 1, c + 2, c + 3};
    m.add_cell(CellType::kTet4, n, c % 5, 1);
  }
  Mesh back;
  std::string message;
  ASSERT_EQ(through_pipe(m, &back, &message), 'M') << message;
  EXPECT_EQ(exact_difference(m, back), "");
}

// The stream cut anywhere, or with any byte changed, is an Error or a consistent mesh.
TEST(MeshPipe, DamagedStreamsAreErrors) {
  const std::string dir = test::temp_dir();
  const std::string file = dir + "/stream";
  {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ASSERT_TRUE(io::send_mesh(fd, full_mesh()));
    ::close(fd);
  }
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string good = ss.str();
  ASSERT_LT(good.size() + 1, 65536u);  // fits in a pipe: written whole, then read
  auto receive = [&](const std::string& bytes, std::string* error) {
    int fds[2];
    EXPECT_EQ(::pipe(fds), 0);
    EXPECT_EQ(::write(fds[1], bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    ::close(fds[1]);
    Mesh m;
    std::string message;
    char kind = 0;
    try {
      kind = io::receive_mesh(fds[0], &m, &message);
    } catch (const Error& e) {
      *error = e.what();
    }
    ::close(fds[0]);
    return kind;
  };
  int errors = 0;
  for (std::size_t cut = 0; cut < good.size(); ++cut) {
    std::string error;
    EXPECT_EQ(receive(good.substr(0, cut), &error), 0) << cut;
    EXPECT_EQ(error.rfind("damaged data: ", 0), 0u) << error;
    errors += !error.empty();
  }
  EXPECT_EQ(errors, static_cast<int>(good.size()));
  std::string error;
  EXPECT_EQ(receive(good + "x", &error), 0);
  EXPECT_EQ(error, "damaged data: bytes after the end marker");
  std::mt19937 rng(3);
  for (int k = 0; k < 4000; ++k) {
    std::string bad = good;
    bad[rng() % bad.size()] ^= static_cast<char>(1 + rng() % 255);
    std::string e;
    receive(bad, &e);  // any outcome but a crash (ASan builds check the memory)
  }
}

// The files of the repository (fuzz seeds) and meshes with names and quadratic cells written by
// tmop, read directly and isolated: the same Mesh exactly. The netCDF-4 seed takes the isolated
// path for Exodus; classic Exodus files are read directly either way.
std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d))
      if (e->d_name[0] != '.') out.push_back(dir + "/" + e->d_name);
    ::closedir(d);
  }
  return out;
}

std::string compare_reads(const std::string& path) {
  Mesh direct, isolated;
  set_isolated_hdf5_reads(false);
  const Status a = read_mesh(path, &direct);
  set_isolated_hdf5_reads(true);
  const Status b = read_mesh(path, &isolated);
  set_isolated_hdf5_reads(false);
  if (a.ok() != b.ok() || a.message() != b.message())
    return path + ": '" + a.message() + "' vs '" + b.message() + "'";
  const std::string d = exact_difference(direct, isolated);
  return d.empty() ? "" : path + ": " + d;
}

#if defined(TMOP_TEST_WITH_CGNS) && defined(TMOP_TEST_WITH_EXODUS)

Mesh named_quadratic_mesh() {
  Mesh m = test::make_mesh({CellType::kTri3, CellType::kQuad4, CellType::kTri6, CellType::kQuad8,
                            CellType::kTet10, CellType::kHex20, CellType::kWedge15});
  for (int c = 0; c < m.num_cells(); ++c) m.cell_entity[c] = 0;
  m.set_physical_name(2, m.cell_region[0], "wall");
  m.set_physical_name(3, m.cell_region[4], "fluid");
  return m;
}

TEST(IsolatedRead, EqualsTheDirectReadFieldByField) {
  std::vector<std::string> files =
      files_in(std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/cgns");
  for (const std::string& f : files_in(std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/exo"))
    files.push_back(f);
  const std::string dir = test::temp_dir();
  for (const char* name : {"/named.cgns", "/named.exo"}) {
    ASSERT_TRUE(write_mesh(dir + name, named_quadratic_mesh()).ok()) << name;
    files.push_back(dir + name);
  }
  files.push_back(std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/regressions/exo/no_elem_type.exo");
  int hdf5 = 0;
  for (const std::string& f : files) {
    EXPECT_EQ(compare_reads(f), "");
    hdf5 += io::has_hdf5_signature(f);
  }
  EXPECT_GE(hdf5, 5);  // the CGNS files and the netCDF-4 Exodus seed
  Mesh m;
  ASSERT_TRUE(read_mesh(dir + "/named.exo", &m).ok());
  EXPECT_EQ(m.physical_names.size(), 2u);  // names and quadratic types are in the comparison
}

// A child that dies is one line naming the file; the hook shows which files take the child.
void segv_hook(int) { ::raise(SIGSEGV); }
void abort_hook(int) { std::abort(); }
void exit_hook(int) { ::_exit(1); }
void interrupt_hook(int) { ::raise(SIGINT); }
void garbage_hook(int fd) {
  (void)!::write(fd, "TMOPPIP1M", 9);
  ::_exit(0);
}

std::string isolated_error(const std::string& path, void (*hook)(int)) {
  set_isolated_hdf5_reads(true);
  io::set_isolated_read_child_hook(hook);
  Mesh m;
  const Status s = read_mesh(path, &m);
  io::set_isolated_read_child_hook(nullptr);
  set_isolated_hdf5_reads(false);
  if (!s.ok() && m.num_vertices() != 0) return "mesh not cleared";
  return s.ok() ? "ok" : s.message();
}

TEST(IsolatedRead, ACrashingChildIsOneLine) {
  const std::string cgns = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/cgns/sq_a.cgns";
  EXPECT_EQ(isolated_error(cgns, segv_hook),
            cgns +
                ": the HDF5 library crashed reading this file (SIGSEGV, signal 11); the file "
                "is damaged or not a valid CGNS file");
  EXPECT_EQ(isolated_error(cgns, abort_hook),
            cgns +
                ": the HDF5 library crashed reading this file (SIGABRT, signal 6); the file "
                "is damaged or not a valid CGNS file");
  EXPECT_EQ(isolated_error(cgns, exit_hook),
            cgns +
                ": the HDF5 library failed reading this file (the reading process exited with "
                "status 1); the file is damaged or not a valid CGNS file");
  EXPECT_EQ(isolated_error(cgns, interrupt_hook), cgns + ": reading was interrupted (SIGINT)");
  EXPECT_EQ(isolated_error(cgns, garbage_hook),
            cgns + ": the reading process sent damaged data: truncated");
  const std::string nc4 = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/exo/sq_netcdf4.exo";
  EXPECT_NE(isolated_error(nc4, segv_hook).find("not a valid netCDF-4 (HDF5) Exodus II file"),
            std::string::npos);
  // Classic netCDF never reaches libhdf5: read in the process, the hook never runs.
  const std::string classic = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/exo/sq_a.exo";
  EXPECT_EQ(isolated_error(classic, segv_hook), "ok");
  // Isolation off: the hook does not run either (a direct read).
  io::set_isolated_read_child_hook(segv_hook);
  Mesh m;
  EXPECT_TRUE(read_mesh(cgns, &m).ok());
  io::set_isolated_read_child_hook(nullptr);
}

// The libhdf5 invalid free found by fuzzing (docs/fuzzing.md): one line, no crash.
TEST(IsolatedRead, TheLibhdf5FindingIsOneLine) {
  const std::string f =
      std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/regressions/exo/hdf5_invalid_free.exo";
  const std::string e = isolated_error(f, nullptr);
  EXPECT_EQ(e.rfind(f + ": ", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_NE(e, "ok");
}

// libhdf5 loops forever on this damaged netCDF-4 file (found by fuzzing, 2026-12-05): the
// child's CPU-time limit ends the read with one line; a child spinning in a hook likewise.
void spin_hook(int) {
  for (volatile unsigned long i = 0;; i = i + 1) {
  }
}

TEST(IsolatedRead, AReadThatNeverEndsIsStoppedByItsCpuLimit) {
  io::set_isolated_read_cpu_limit(1.0, 0.0);
  const std::string f = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/regressions/exo/hdf5_hang.exo";
  EXPECT_EQ(isolated_error(f, nullptr),
            f + ": the HDF5 library did not finish reading this file in 1 s of CPU time (the "
                "reading process was stopped); the file is damaged or not a valid netCDF-4 "
                "(HDF5) Exodus II file");
  const std::string cgns = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/cgns/sq_a.cgns";
  EXPECT_EQ(isolated_error(cgns, spin_hook),
            cgns +
                ": the HDF5 library did not finish reading this file in 1 s of CPU time (the "
                "reading process was stopped); the file is damaged or not a valid CGNS file");
  io::set_isolated_read_cpu_limit(20.0, 1.0);
  // The defaults leave a valid file alone.
  EXPECT_EQ(isolated_error(cgns, nullptr), "ok");
}

#endif

TEST(IsolatedRead, OffUnderMpi) {
  set_isolated_hdf5_reads(true);
  EXPECT_TRUE(isolated_hdf5_reads());
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    ::setenv(v, "2", 1);
    EXPECT_FALSE(isolated_hdf5_reads()) << v;
    ::unsetenv(v);
  }
  EXPECT_TRUE(isolated_hdf5_reads());
  set_isolated_hdf5_reads(false);
  EXPECT_FALSE(isolated_hdf5_reads());
}

}  // namespace
}  // namespace tmop
