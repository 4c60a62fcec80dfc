// tests/fuzz/child_report.cc
// The fuzz target's hook in the isolated read's child and the triage of its crashes
// (child_report.h).
#include "tests/fuzz/child_report.h"

#include <fcntl.h>
#include <sanitizer/asan_interface.h>
#include <sanitizer/common_interface_defs.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tmop/io/isolated_read.h"

namespace tmop_fuzz {
namespace {

std::string g_report;  // DIR/child_report
int g_stderr = -1;     // the fuzzer's stderr, for the child

void no_death_callback() {}

extern "C" void report_to_file(const char* text) {
  const int fd = ::open(g_report.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return;
  for (std::size_t n = std::strlen(text); n > 0;) {
    const ssize_t w = ::write(fd, text, n);
    if (w <= 0) break;
    text += w;
    n -= static_cast<std::size_t>(w);
  }
  ::close(fd);
}

void child_hook(int) {
  __sanitizer_set_death_callback(no_death_callback);
  __asan_set_error_report_callback(report_to_file);
  if (g_stderr >= 0) ::dup2(g_stderr, 2);
}

// A stack frame of the sanitizer runtime or of the memory functions it intercepts: the frame
// after it is the one to blame.
bool runtime_frame(const std::string& line) {
  if (line.find("compiler-rt/") != std::string::npos) return true;
  for (const char* f : {" in free", " in malloc", " in calloc", " in realloc", " in __interceptor_",
                        " in operator delete", " in operator new", " in memcpy", " in memmove",
                        " in memset", " in strcpy", " in strlen", " in __asan", " in __sanitizer"})
    if (line.find(f) != std::string::npos) return true;
  return false;
}

}  // namespace

void install_child_hook(const std::string& dir) {
  g_report = dir + "/child_report";
  g_stderr = ::fcntl(2, F_DUPFD_CLOEXEC, 10);
  tmop::io::set_isolated_read_child_hook(child_hook);
}

std::string child_crash_in_tmop() {
  std::ifstream in(g_report);
  if (!in) return "";
  std::string line;
  std::string blame;
  while (std::getline(in, line)) {
    const std::size_t hash = line.find('#');
    if (hash == std::string::npos || line.find(" in ") == std::string::npos) continue;
    if (runtime_frame(line)) continue;
    blame = line;
    break;
  }
  in.close();
  std::remove(g_report.c_str());
  for (const char* lib : {"libhdf5", "libnetcdf", "libcgns", "libexoII"})
    if (blame.find(lib) != std::string::npos) return "";
  return blame.empty() ? "an ASan report without a stack frame" : blame;
}

}  // namespace tmop_fuzz
