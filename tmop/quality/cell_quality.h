// tmop/quality/cell_quality.h
// The quality measures of one cell (docs/quality.md defines each one; "1 = ideal" always means
// the ideal element of ideal_element.h). Measures that do not apply to the cell's type are NaN.
//
//   inverted          det(A) <= 0 at a corner or sample point; tri6/tet10 also when det(A) > 0
//   cannot
//                     be proven on the whole cell (QualityOptions::bezier_certificate)
//   certified         1 when det(A) > 0 is proven on the whole cell, else 0: tri3, tet4, quad4 by
//                     their corners (det A is constant or affine there); tri6, tet10 by Bernstein
//                     coefficients with subdivision (jacobian_certificate.h); quad9, hex8, wedge6
//                     by the plain Bernstein bound with QualityOptions::certify_all_types; NaN
//                     otherwise (pyramid5 and hex27 have no certificate here)
//   min_det           min det(T), T = A W^-1, W the Jacobian of the ideal element with unit edges:
//                     the local volume (area) relative to that element, length^d, signed
//   mean_ratio        simplices: d det(T)^(2/d) / |T|_F^2 with sign(det T), in [-1, 1]; tri3 / tet4
//                     by the edge formulas 4 sqrt3 A / sum l^2 and 12 (3V)^(2/3) / sum l^2;
//                     tri6 / tet10: the minimum of the pointwise value over the sample points
//   scaled_jacobian   min over corner frames (corner_frames.h) of det(E) / prod |e_k|, divided by
//                     the same quantity of the ideal element so that the ideal scores 1; in
//                     in [-1, 1] (pyramid, wedge: <= 1 in random sampling, not proven);
//                     quadratic cells: of their corners (the straight-sided cell)
//   condition_number  max over corners / sample points of |T|_F |T^-1|_F / d, in [1, inf);
//                     +inf when det T <= 0 somewhere
//   min/max_angle_deg 2D cells: interior angles of the corner polygon, degrees; a corner turning
//                     against the cell's own normal is reflex (> 180), so a dart quad shows it
//   min/max_dihedral  tet4 / tet10 (of the corner tet): interior dihedral angles, degrees (0, 180)
//   min/max_edge      shortest / longest corner-to-corner edge, length units
//
// 2D cells in 3D space are measured in their own plane: coordinates are projected onto the frame
// (t1, t2, n) with n = `up` when given (planar meshes: +z) or else the cell's Newell normal; so
// a linear surface triangle is never inverted against its own normal, while a folded quad or a
// tri6 whose interior folds back is.
#ifndef TMOP_QUALITY_CELL_QUALITY_H_
#define TMOP_QUALITY_CELL_QUALITY_H_

#include <limits>

#include "tmop/element/cell_type.h"
#include "tmop/quality/quality_options.h"

namespace tmop {

struct CellQuality {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  bool inverted = false;
  double certified = kNaN;
  double min_det = kNaN;
  double mean_ratio = kNaN;
  double scaled_jacobian = kNaN;
  double condition_number = kNaN;
  double min_angle_deg = kNaN;
  double max_angle_deg = kNaN;
  double min_dihedral_deg = kNaN;
  double max_dihedral_deg = kNaN;
  double min_edge_length = kNaN;
  double max_edge_length = kNaN;
};

// nodes: cell_num_nodes(type) x 3 doubles, row-major, Gmsh node order (z = 0 for planar meshes).
// up: for 2D cells, the unit normal that defines positive orientation (nullptr: the cell's own
// Newell normal); ignored for 3D cells. Cells of dimension < 2 give all-NaN, not inverted.
// Allocation-free and thread-safe.
CellQuality cell_quality(CellType type, const double* nodes, const double* up,
                         const QualityOptions& options = {});

// A 2D cell (nodes: cell_num_nodes(type) x 3) in the frame of its plane, exactly as cell_quality
// measures it (`up` as there): 2 coordinates per node into p, positively oriented when the cell
// turns counterclockwise about the normal. For certificates and measures of surface cells.
void cell_plane_coordinates(CellType type, const double* nodes, const double* up, double* p);

}  // namespace tmop

#endif  // TMOP_QUALITY_CELL_QUALITY_H_
