// tests/fuzz/child_report.h
// The fuzz target's side of the isolated read (tmop/io/isolated_read.h): HDF5-based inputs
// (.cgns, netCDF-4 .exo) are parsed in a forked child, whose crash read_mesh reports as an error.
// That is the product's answer to a libhdf5 crash, but a memory error in tmop's own reader code
// in the child (cgns.cc, exodus.cc) must stay a finding. So:
//   install_child_hook(dir): in every child, libFuzzer's death callback is replaced by a no-op (no
//     crash-* file, no final stats from the child), the child's stderr is restored (ASan's report
//     stays visible) and ASan's report text goes to DIR/child_report;
//   child_crash_in_tmop(): after a read whose message says the reading process crashed or
//     failed, "" when the report (if any) blames libhdf5 / libnetcdf / libcgns / libexoII (its
//     first frame past the sanitizer runtime and libc's memory functions is in one of them), else
//     the frame that blames tmop. A plain signal without a report (SIGABRT from glibc in libhdf5)
//     is accepted. The report file is removed either way.
#ifndef TMOP_TESTS_FUZZ_CHILD_REPORT_H_
#define TMOP_TESTS_FUZZ_CHILD_REPORT_H_

#include <string>

namespace tmop_fuzz {

void install_child_hook(const std::string& dir);
std::string child_crash_in_tmop();

}  // namespace tmop_fuzz

#endif  // TMOP_TESTS_FUZZ_CHILD_REPORT_H_
