// tools/optimize/run_report.h
// tmop_optimize's run report (--report=FILE.json) and its rerun (--from_report=FILE.json):
//
//   run_report: {"input", "output", "status", "tmop": {"version", "commit"},
//     "input_file": {"path", "bytes", "fnv1a64"} (the input mesh), "input_files": [{"flag",
//     "path", "bytes", "fnv1a64"}: every file the run reads, in this order: input, reference,
//     moved, fixed_nodes (not field:NAME), geometry (a surface file), from_report; bytes and
//     fnv1a64 null for a file that cannot be read], "settings": (recipe_settings_json: the options
//     as the recipe used them, defaults resolved), "flags": {every tmop_optimize flag: its value
//     as text, defaults included}, "run": (recipe_json), "quality_before", "quality_after"}.
//   apply_report_flags (--from_report): report_flags.h.
//   fnv1a64_file: the 64-bit FNV-1a hash of a file's bytes and its size.
#ifndef TMOP_TOOLS_OPTIMIZE_RUN_REPORT_H_
#define TMOP_TOOLS_OPTIMIZE_RUN_REPORT_H_

#include <cstdint>
#include <string>

#include "tmop/core/status.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/recipe_result.h"
#include "tools/optimize/report_flags.h"

namespace tmop_tools {

struct ReportInputs {
  std::string input, output, status, settings_json;
  bool written = false;
};

std::string run_report(const ReportInputs& in, const tmop::RecipeResult& result,
                       const tmop::QualityReport& before, const tmop::QualityReport& after);

tmop::Status fnv1a64_file(const std::string& path, std::uint64_t* hash, std::uint64_t* bytes);

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_OPTIMIZE_RUN_REPORT_H_
