// tmop/quality/quality_json.h
// quality_json: the QualityReport as one JSON object with stable keys (docs/quality.md lists
// every key). Numbers are printed with %.17g, so a report read back gives the exact doubles and
// two runs on the same mesh give identical text. Measures that do not apply to the mesh (no cell
// has them, e.g. dihedral angles of a 2D mesh) are null; NaN and infinite values are null.
#ifndef TMOP_QUALITY_QUALITY_JSON_H_
#define TMOP_QUALITY_QUALITY_JSON_H_

#include <string>

#include "tmop/quality/quality_report.h"

namespace tmop {

// Pretty-printed (2-space indent, one key per line except number arrays), ends with a newline.
std::string quality_json(const QualityReport& report);

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_JSON_H_
