// tmop/quality/worst_quality.h
// worst_quality: one number for "how bad is the worst element": the minimum over elements of the
// mean ratio for simplices (tri3, tri6, tet4, tet10) and of the scaled Jacobian for the other
// types (cell_quality.h). 1 = every element ideal; <= 0 means an inverted (or degenerate) element.
// NaN for a mesh without 2D/3D elements. For progress lines: skips angles and statistics.
#ifndef TMOP_QUALITY_WORST_QUALITY_H_
#define TMOP_QUALITY_WORST_QUALITY_H_

#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

// threads: as QualityOptions::threads (0 = all cores).
double worst_quality(const Mesh& mesh, int threads = 0);

// The same measure per cell (num_cells() values; NaN for cells that are not elements).
std::vector<double> cell_headline_quality(const Mesh& mesh, int threads = 0);

}  // namespace tmop

#endif  // TMOP_QUALITY_WORST_QUALITY_H_
