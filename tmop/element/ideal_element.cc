#include "tmop/element/ideal_element.h"

#include <cstdio>
#include <cstdlib>

namespace tmop {
namespace {

// Literal (correctly rounded) values keep the tables constant-initialised.
constexpr double kHalfSqrt3 = 0.8660254037844386;     // sqrt(3) / 2
constexpr double kSqrt3Over6 = 0.28867513459481287;   // sqrt(3) / 6
constexpr double kSqrtTwoThirds = 0.816496580927726;  // sqrt(2 / 3)
constexpr double kInvSqrt2 = 0.7071067811865475;      // 1 / sqrt(2)

constexpr double kTri[3][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, kHalfSqrt3, 0}};
constexpr double kQuad[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
constexpr double kTet[4][3] = {
    {0, 0, 0}, {1, 0, 0}, {0.5, kHalfSqrt3, 0}, {0.5, kSqrt3Over6, kSqrtTwoThirds}};
constexpr double kHex[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
constexpr double kWedge[6][3] = {{0, 0, 0}, {1, 0, 0}, {0.5, kHalfSqrt3, 0},
                                 {0, 0, 1}, {1, 0, 1}, {0.5, kHalfSqrt3, 1}};
constexpr double kPyramid[5][3] = {
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, kInvSqrt2}};

// Reference simplices are the unit right simplices, so W's columns are the ideal edges from
// corner 0; reference quad / hex are [-1,1]^d onto the unit square / cube: W = I / 2; the wedge
// is triangle x [-1,1] (third column: half the unit height); the pyramid's base is [-1,1]^2 at
// zeta = 0 with the apex at zeta = 1.
constexpr double kTriW[4] = {1, 0.5, 0, kHalfSqrt3};
constexpr double kQuadW[4] = {0.5, 0, 0, 0.5};
constexpr double kTetW[9] = {1, 0.5, 0.5, 0, kHalfSqrt3, kSqrt3Over6, 0, 0, kSqrtTwoThirds};
constexpr double kHexW[9] = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};
constexpr double kWedgeW[9] = {1, 0.5, 0, 0, kHalfSqrt3, 0, 0, 0, 0.5};
constexpr double kPyramidW[9] = {0.5, 0, 0, 0, 0.5, 0, 0, 0, kInvSqrt2};

[[noreturn]] void fail(CellType type) {
  std::fprintf(stderr, "tmop: no ideal element for cell type %s\n", cell_name(type));
  std::abort();
}

}  // namespace

const double* ideal_corner(CellType type, int corner) {
  switch (cell_info(type).linear) {
    case CellType::kTri3:
      return kTri[corner];
    case CellType::kQuad4:
      return kQuad[corner];
    case CellType::kTet4:
      return kTet[corner];
    case CellType::kHex8:
      return kHex[corner];
    case CellType::kWedge6:
      return kWedge[corner];
    case CellType::kPyramid5:
      return kPyramid[corner];
    default:
      fail(type);
  }
}

const double* ideal_jacobian(CellType type) {
  switch (cell_info(type).linear) {
    case CellType::kTri3:
      return kTriW;
    case CellType::kQuad4:
      return kQuadW;
    case CellType::kTet4:
      return kTetW;
    case CellType::kHex8:
      return kHexW;
    case CellType::kWedge6:
      return kWedgeW;
    case CellType::kPyramid5:
      return kPyramidW;
    default:
      fail(type);
  }
}

void ideal_jacobian(CellType type, double* W) {
  const double* w = ideal_jacobian(type);
  const int d = cell_dim(type);
  for (int i = 0; i < d * d; ++i) W[i] = w[i];
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
  const double* W = ideal_jacobian(type);
  const double det = cell_dim(type) == 2
                         ? W[0] * W[3] - W[1] * W[2]
                         : W[0] * (W[4] * W[8] - W[5] * W[7]) - W[1] * (W[3] * W[8] - W[5] * W[6]) +
                               W[2] * (W[3] * W[7] - W[4] * W[6]);
  return det * reference_volume(type);
}

}  // namespace tmop
