// tests/fuzz/fuzz_read.cc
// libFuzzer target for every mesh-reader family (docs/fuzzing.md). The family is the extension
// the input is read as: TMOP_FUZZ_FAMILY=msh|vtk|vtu|mesh|off|obj|ply|stl|su2|ugrid|b8.ugrid|
// lb8.ugrid|r8.ugrid|lr8.ugrid|cgns|exo|nodes|report. The bytes are written to a temporary file
// with that extension (the readers take paths) and read with read_mesh (read_node_list for
// "nodes"; for "report" tmop_optimize's --from_report reader, apply_report_flags, over the flags
// defined below).
// Checks (abort() on failure, so libFuzzer records the input):
//   - anything thrown out of the reader (read_mesh returns a Status for tmop::Error and
//     bad_alloc; everything else escapes and is reported here);
//   - an error message is one printable line shorter than 1000 bytes;
//   - a mesh read is written back in the same format (when the writer takes it) and read again:
//     the same vertices, cells (type, node order, coordinates: exact, or float32 where the format
//     stores float32), regions and names where the format holds them (same_mesh.h);
//   - a report's output, report and from_report flags are never applied.
#include <gflags/gflags.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "tests/fuzz/child_report.h"
#include "tests/fuzz/same_mesh.h"
#include "tmop/io/isolated_read.h"
#include "tmop/io/mesh_io.h"
#include "tmop/io/node_list.h"
#include "tools/optimize/report_flags.h"

// The "report" family's flags: names and types of tmop_optimize's (apply_report_flags takes the
// flags of this file, kFlagFile).
DEFINE_string(input, "", "fuzz: as tmop_optimize");
DEFINE_string(output, "", "fuzz: never set from a report");
DEFINE_string(report, "", "fuzz: never set from a report");
DEFINE_string(from_report, "", "fuzz: never set from a report");
DEFINE_string(metric, "", "fuzz: as tmop_optimize");
DEFINE_string(boundary, "fixed", "fuzz: as tmop_optimize");
DEFINE_int32(max_iterations, 200, "fuzz: as tmop_optimize");
DEFINE_int32(threads, 0, "fuzz: as tmop_optimize");
DEFINE_double(power, 0, "fuzz: as tmop_optimize");
DEFINE_double(max_seconds, 1e9, "fuzz: as tmop_optimize");
DEFINE_bool(binary, false, "fuzz: as tmop_optimize");
DEFINE_bool(verbose, false, "fuzz: as tmop_optimize");

namespace {

std::string g_family;
std::string g_dir;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "tmop_fuzz_read (%s): %s\n", g_family.c_str(), what.c_str());
  std::abort();
}

void check_message(const std::string& message) {
  if (message.empty()) fail("empty error message");
  if (message.size() >= 1000) fail("error message of " + std::to_string(message.size()) + " bytes");
  for (unsigned char c : message)
    if (c < 0x20 || c == 0x7f) fail("control character " + std::to_string(c) + " in: " + message);
}

void write_bytes(const std::string& path, const uint8_t* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) fail("cannot create " + path);
  if (size && std::fwrite(data, 1, size, f) != size) fail("cannot write " + path);
  std::fclose(f);
}

void round_trip(const tmop::Mesh& mesh, bool binary) {
  const std::string out = g_dir + "/out." + g_family;
  tmop::WriteOptions options;
  options.binary = binary;
  const tmop::Status w = tmop::write_mesh(out, mesh, options);
  if (!w.ok()) {
    check_message(w.message());  // a mesh the format cannot hold: refused, that is fine
    return;
  }
  tmop::Mesh again;
  const tmop::Status r = tmop::read_mesh(out, &again);
  std::remove(out.c_str());
  if (!r.ok())
    fail(std::string("round trip (") + (binary ? "binary" : "ascii") +
         "): written file does not read back: " + r.message());
  if (again.num_cells() != mesh.num_cells() || again.num_vertices() != mesh.num_vertices())
    fail(std::string("round trip (") + (binary ? "binary" : "ascii") +
         "): " + std::to_string(mesh.num_cells()) + " cells, " +
         std::to_string(mesh.num_vertices()) + " nodes -> " + std::to_string(again.num_cells()) +
         " cells, " + std::to_string(again.num_vertices()) + " nodes");
  const std::string d = tmop_fuzz::mesh_difference(mesh, again, tmop_fuzz::holds(g_family, binary));
  if (!d.empty()) fail(std::string("round trip (") + (binary ? "binary" : "ascii") + "): " + d);
}

void run_report(const std::string& in) {
  gflags::FlagSaver saver;  // every input starts from the defaults
  const tmop::Status s = tmop_tools::apply_report_flags(in, "fuzz_read.cc");
  if (!s.ok()) return check_message(s.message());
  if (!FLAGS_output.empty() || !FLAGS_report.empty() || !FLAGS_from_report.empty())
    fail("a report set --output, --report or --from_report");
}

void run_one(const uint8_t* data, size_t size) {
  const std::string in = g_dir + "/in." + g_family;
  write_bytes(in, data, size);
  // TMOP_FUZZ_KEEP=DIR keeps every input as DIR/N.FAMILY: damage done inside an uninstrumented
  // library (libnetcdf, libhdf5) may show only inputs later, so the culprit is among these.
  static const char* keep = std::getenv("TMOP_FUZZ_KEEP");
  static long count = 0;
  if (keep && *keep)
    write_bytes(std::string(keep) + "/" + std::to_string(count++) + "." + g_family, data, size);
  if (g_family == "nodes") {
    std::vector<char> flags;
    const tmop::Status s = tmop::read_node_list(in, 64, &flags);
    if (!s.ok()) check_message(s.message());
    if (s.ok() && flags.size() != 64) fail("node list: " + std::to_string(flags.size()) + " flags");
    return;
  }
  if (g_family == "report") return run_report(in);
  // CGNS and netCDF-4 Exodus inputs go to libhdf5, which crashes on some damaged ones: they are
  // read in a child process (isolated_read.h), whose crash is an error unless ASan blames tmop.
  tmop::Mesh mesh;
  const tmop::Status s = tmop::read_mesh(in, &mesh);
  if (!s.ok()) {
    check_message(s.message());
    const std::string& m = s.message();
    if (m.find(": the HDF5 library ") != std::string::npos ||
        m.find(": the reading process ") != std::string::npos) {
      const std::string blame = tmop_fuzz::child_crash_in_tmop();
      if (!blame.empty()) fail("a memory error in tmop's code in the reading process: " + blame);
    }
    return;
  }
  // The same format back, ASCII and binary for the writers that take WriteOptions::binary (the
  // others write the same file twice: .ugrid picks its encoding from the name; .mesh .obj .su2
  // are ASCII, .exo .cgns have one encoding).
  round_trip(mesh, false);
  for (const char* f : {"msh", "vtk", "vtu", "off", "ply", "stl"})
    if (g_family == f) round_trip(mesh, true);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  const char* family = std::getenv("TMOP_FUZZ_FAMILY");
  if (!family || !*family) {
    std::fprintf(stderr, "tmop_fuzz_read: set TMOP_FUZZ_FAMILY (msh, vtk, vtu, mesh, ...)\n");
    std::exit(2);
  }
  g_family = family;
  // TMPDIR (ctest sets /dev/shm when it is there: every input is written and read back, and a
  // disk-backed /tmp makes those waits dominate the run on a busy machine).
  const char* tmp = std::getenv("TMPDIR");
  std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/tmop_fuzz_XXXXXX";
  if (!mkdtemp(&templ[0])) fail("cannot create a temporary directory in " + templ);
  g_dir = templ;
  // The tools' setting (TMOP_FUZZ_ISOLATED=0: direct reads, to see a libhdf5 crash itself).
  const char* isolated = std::getenv("TMOP_FUZZ_ISOLATED");
  tmop::set_isolated_hdf5_reads(!isolated || std::strcmp(isolated, "0") != 0);
  tmop_fuzz::install_child_hook(g_dir);
  // libhdf5 loops forever on some damaged inputs (regressions/exo/hdf5_hang.exo): the child's
  // CPU limit, 2 s for these small inputs, stops it well inside libFuzzer's -timeout.
  tmop::io::set_isolated_read_cpu_limit(2.0, 1.0);
  std::atexit([] {
    std::remove((g_dir + "/in." + g_family).c_str());
    std::remove((g_dir + "/child_report").c_str());
    rmdir(g_dir.c_str());
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    run_one(data, size);
  } catch (const std::exception& e) {
    fail(std::string("exception escaped the reader: ") + e.what());
  } catch (...) {
    fail("non-std exception escaped the reader");
  }
  return 0;
}
