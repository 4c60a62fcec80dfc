// tmop/target/ideal_element.h
// The ideal element of each type with unit edge length, as the Jacobian W of the affine map from
// the reference element (element/shape.h) to it: equilateral triangle, square, regular tet,
// cube, right prism with an equilateral base and unit height, pyramid with all eight edges of
// unit length. Quadratic types share their linear type's ideal. W is d x d row-major,
// d = cell_dim(type) (2 or 3).
#ifndef TMOP_TARGET_IDEAL_ELEMENT_H_
#define TMOP_TARGET_IDEAL_ELEMENT_H_

#include "tmop/element/cell_type.h"

namespace tmop {

// Writes W (d*d values). Types of dimension < 2 are a programmer error.
void ideal_jacobian(CellType type, double* W);

// Volume (area in 2D) of the unit-edge ideal element: used to turn a cell's volume into an
// "equivalent edge length" h = (volume / ideal_volume)^(1/d).
double ideal_volume(CellType type);

// det of the reference element's volume measure: |reference| such that
// volume = integral of det A over the reference = det(A) * reference_volume for affine cells.
double reference_volume(CellType type);

}  // namespace tmop

#endif  // TMOP_TARGET_IDEAL_ELEMENT_H_
