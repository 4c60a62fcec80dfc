#include "tmop/target/ideal_element.h"

#include <cassert>
#include <cmath>

namespace tmop {

void ideal_jacobian(CellType type, double* W) {
  const double s3 = std::sqrt(3.0);
  switch (cell_info(type).linear) {
    case CellType::kTri3: {  // columns: the two edges from node 0 of a unit equilateral triangle
      const double w[4] = {1, 0.5, 0, s3 / 2};
      for (int i = 0; i < 4; ++i) W[i] = w[i];
      return;
    }
    case CellType::kQuad4: {  // reference [-1,1]^2 -> unit square
      const double w[4] = {0.5, 0, 0, 0.5};
      for (int i = 0; i < 4; ++i) W[i] = w[i];
      return;
    }
    case CellType::kTet4: {  // regular tet with unit edges; columns are the edges from node 0
      const double w[9] = {1, 0.5, 0.5, 0, s3 / 2, s3 / 6, 0, 0, std::sqrt(2.0 / 3.0)};
      for (int i = 0; i < 9; ++i) W[i] = w[i];
      return;
    }
    case CellType::kHex8: {
      const double w[9] = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};
      for (int i = 0; i < 9; ++i) W[i] = w[i];
      return;
    }
    case CellType::kWedge6: {  // equilateral base (xi, eta), zeta in [-1,1] -> unit height
      const double w[9] = {1, 0.5, 0, 0, s3 / 2, 0, 0, 0, 0.5};
      for (int i = 0; i < 9; ++i) W[i] = w[i];
      return;
    }
    case CellType::kPyramid5: {  // base [-1,1]^2 -> unit square, apex height 1 -> 1/sqrt2
      const double w[9] = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 1.0 / std::sqrt(2.0)};
      for (int i = 0; i < 9; ++i) W[i] = w[i];
      return;
    }
    default:
      assert(false && "ideal_jacobian: no ideal element below dimension 2");
  }
}

double reference_volume(CellType type) {
  switch (cell_info(type).linear) {
    case CellType::kTri3:
      return 0.5;
    case CellType::kQuad4:
      return 4.0;
    case CellType::kTet4:
      return 1.0 / 6.0;
    case CellType::kHex8:
      return 8.0;
    case CellType::kWedge6:
      return 1.0;  // triangle 1/2 x height 2
    case CellType::kPyramid5:
      return 4.0 / 3.0;  // base 4 x height 1 / 3
    default:
      return 1.0;
  }
}

double ideal_volume(CellType type) {
  double W[9];
  ideal_jacobian(type, W);
  const double det = cell_dim(type) == 2
                         ? W[0] * W[3] - W[1] * W[2]
                         : W[0] * (W[4] * W[8] - W[5] * W[7]) - W[1] * (W[3] * W[8] - W[5] * W[6]) +
                               W[2] * (W[3] * W[7] - W[4] * W[6]);
  return det * reference_volume(type);
}

}  // namespace tmop
