// tmop/quality/quality_svg.h
// Pictures of quality reports as standalone SVG 1.1 documents (for docs and reviews).
//
// quality_svg(mesh, report):
//   - planar 2D meshes: every element filled by its quality, the per-cell value worst_quality.h
//     uses (mean ratio for simplices, scaled Jacobian otherwise), on a colour bar from 0 (dark
//     blue) to 1 (yellow); inverted elements magenta whatever their value. Quadratic cells are
//     drawn as the polygon through their corner and mid-edge nodes.
//   - surface meshes (2D cells in 3D): the same map in an orthographic view from direction
//     (1, -1.3, 0.9), cells painted back to front.
//   - volume meshes: panels with histograms (fraction of elements per fixed
//     bin of quality_report.h: mean ratio, scaled Jacobian, min and max (dihedral) angles) and a
//     scatter plot of max vs min dihedral angle per tet (2D elements: interior angles), with the
//     sliver corner (min < 10, max > 150 degrees) shaded. At most 20000 points are drawn per
//     scatter (every k-th element, deterministic).
// quality_svg_compare(before, after): the same histogram and scatter panels with both reports
//   overlaid (bars side by side per bin, both point clouds), for before/after figures.
#ifndef TMOP_QUALITY_QUALITY_SVG_H_
#define TMOP_QUALITY_QUALITY_SVG_H_

#include <string>

#include "tmop/mesh/mesh.h"
#include "tmop/quality/quality_report.h"

namespace tmop {

// report must come from compute_quality(mesh).
std::string quality_svg(const Mesh& mesh, const QualityReport& report);

// The two reports may come from different meshes (histograms are normalised per report).
std::string quality_svg_compare(const QualityReport& before, const QualityReport& after,
                                const std::string& before_label = "before",
                                const std::string& after_label = "after");

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_SVG_H_
