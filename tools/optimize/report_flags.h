// tools/optimize/report_flags.h
// tmop_optimize --from_report=FILE.json: the flags of a run report (run_report.h) read back.
//
//   apply_report_flags(path, flag_file): sets every flag of the report's "flags" object that the
//     command line did not give, except output, report and from_report (a rerun writes where it
//     is told). The flags are those defined in a source file whose name contains flag_file
//     (tools/optimize/flags.cc; tests/fuzz passes its own). "flags" is a flat object of JSON
//     strings
//     ({"name": "value", ...}, the escapes run_report writes: \" \\ \/ \n \t \r \b \f \uXXXX
//     below 0x80). Failure, one line: "FILE: cannot open ...", "FILE: not a tmop_optimize report
//     (no \"flags\" object)", "FILE: byte N: ...", "FILE: flag --x: bad value 'y'" (y quoted
//     printable, at most 40 bytes).
//   tool_flags(flag_file): the flags defined in that file (not glog's or gflags').
#ifndef TMOP_TOOLS_OPTIMIZE_REPORT_FLAGS_H_
#define TMOP_TOOLS_OPTIMIZE_REPORT_FLAGS_H_

#include <gflags/gflags.h>

#include <string>
#include <vector>

#include "tmop/core/status.h"

namespace tmop_tools {

tmop::Status apply_report_flags(const std::string& path,
                                const std::string& flag_file = "tools/optimize/flags.cc");

std::vector<gflags::CommandLineFlagInfo> tool_flags(
    const std::string& flag_file = "tools/optimize/flags.cc");

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_OPTIMIZE_REPORT_FLAGS_H_
