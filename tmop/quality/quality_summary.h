// tmop/quality/quality_summary.h
// quality_summary: the QualityReport for humans: a header with counts (elements by type,
// inverted, certified, slivers, unique-edge lengths) and an aligned table with min / mean / max /
// ideal of every measure that applies. Numbers with 6 significant digits; the JSON report
// (quality_json.h) is the exact, machine-readable form.
#ifndef TMOP_QUALITY_QUALITY_SUMMARY_H_
#define TMOP_QUALITY_QUALITY_SUMMARY_H_

#include <string>

#include "tmop/quality/quality_report.h"

namespace tmop {

// Several lines, each ending with a newline.
std::string quality_summary(const QualityReport& report);

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_SUMMARY_H_
