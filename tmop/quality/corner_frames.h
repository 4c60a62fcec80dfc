// tmop/quality/corner_frames.h
// Corner frames of the linear cell types: at a corner c, the edge vectors E = [x_e1 - x_c, ...]
// (d of them, d = cell dimension) to neighbouring corners, ordered so that det E > 0 on the ideal
// element (ideal_element.h). They give the corner measures of linear cells without shape
// functions:
//   - on tri3/tet4 (affine) and at the corners of quad4/hex8/wedge6, T = E E_ideal^-1 equals
//     A W^-1 of the Jacobian A there (E and A differ by a fixed matrix that the ideal element
//     shares), so det T and the condition number of T are the Jacobian measures;
//   - det E / prod |e_k| is the corner's raw scaled Jacobian.
// Pyramid5: 4 base-corner frames (two base edges and the edge to the apex) and 4 apex frames
// (apex to three consecutive base corners): the pyramid's Jacobian is singular at the apex, so the
// apex is measured by the corners of the tets it shares with the base.
#ifndef TMOP_QUALITY_CORNER_FRAMES_H_
#define TMOP_QUALITY_CORNER_FRAMES_H_

#include "tmop/element/cell_type.h"

namespace tmop {

struct CornerFrame {
  int corner;               // local corner index
  int ends[3];              // edge k runs from `corner` to corner ends[k] (d entries)
  double ideal_inverse[9];  // E_ideal^-1, row-major d x d
  double ideal_det;         // det E_ideal > 0
  double ideal_scaled;      // det E_ideal / prod |e_ideal_k|, the ideal raw scaled Jacobian
};

struct CornerFrames {
  int dim = 0;    // 2 or 3
  int count = 0;  // tri 3, quad 4, tet 4, hex 8, wedge 6, pyramid 8
  CornerFrame frame[8];
};

// Frames of cell_info(type).linear; count == 0 for vertex and line types. Thread-safe; the
// reference stays valid for the program's life.
const CornerFrames& corner_frames(CellType type);

}  // namespace tmop

#endif  // TMOP_QUALITY_CORNER_FRAMES_H_
