// tmop/quality/quality_options.h
// Options of compute_quality (quality_report.h) and cell_quality (cell_quality.h).
#ifndef TMOP_QUALITY_QUALITY_OPTIONS_H_
#define TMOP_QUALITY_QUALITY_OPTIONS_H_

#include "tmop/element/sample_points.h"

namespace tmop {

struct QualityOptions {
  // Where the Jacobian of quadratic cells (tri6, quad9, tet10, hex27) is evaluated for min_det,
  // condition_number and the mean ratio of tri6/tet10. The corners are always added. Default: the
  // default rule of element/sample_points.h (corners + mid-edge nodes (+ face/centre nodes)).
  // Linear cells are measured at their corners (corner_frames.h) whatever the rule: their
  // Jacobian is constant (simplices) or extreme at the corners (quad4).
  SampleRule sample_rule = SampleRule::kDefault;

  // tri6 / tet10: also decide the sign of det J over the whole cell by its Bernstein coefficients
  // (element/bezier.h), subdividing up to bezier_subdivision levels where the plain bound is
  // inconclusive (jacobian_certificate.h). A cell that cannot be proven valid is reported
  // inverted even when no sample point shows det J <= 0. Default on; turn off to report
  // sample-point inversion only.
  bool bezier_certificate = true;

  // Subdivision levels of the certificate (0 = the plain bound of the whole cell). Only cells
  // whose bound is inconclusive pay for it: at most 4^k (tri6) / 8^k (tet10) sub-cells. Default 3.
  int bezier_subdivision = 3;

  // Also certify the types whose certificate does not decide `inverted` (quad9, hex8, wedge6),
  // filling cell_quality.h's `certified` for them (else NaN). Off by default: 27 coefficients per
  // hex8 cost ~3 us, 5x the rest of its measures (1M hexes: ~4 s instead of ~0.7 s on 2 cores).
  bool certify_all_types = false;

  // Angles and dihedral angles (atan2 per corner / edge: the most expensive measures). Off leaves
  // them NaN; count_inverted and worst_quality turn them off.
  bool angles = true;

  // Meshes written in the opposite orientation convention (some generators and formats; decided
  // by the boundary's orientation, mesh/orientation.h) are measured in their own convention, so
  // that they are not reported as all inverted; QualityReport::opposite_convention says so. Off:
  // measure every cell as stored.
  bool detect_convention = true;

  // Worker threads of compute_quality; 0 = std::thread::hardware_concurrency(). The results,
  // including every sum, are identical for every thread count.
  int threads = 0;
};

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_OPTIONS_H_
