#include "tmop/quality/ideal_element.h"

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

// Reference triangle / tet are the unit right simplices, so W's columns are the ideal edges from
// corner 0. Reference quad / hex are [-1,1]^d, mapped onto the unit square / cube: W = I / 2.
constexpr double kTriW[4] = {1, 0.5, 0, kHalfSqrt3};
constexpr double kQuadW[4] = {0.5, 0, 0, 0.5};
constexpr double kTetW[9] = {1, 0.5, 0.5, 0, kHalfSqrt3, kSqrt3Over6, 0, 0, kSqrtTwoThirds};
constexpr double kHexW[9] = {0.5, 0, 0, 0, 0.5, 0, 0, 0, 0.5};

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

const double* ideal_reference_jacobian(CellType type) {
  switch (cell_info(type).linear) {
    case CellType::kTri3:
      return kTriW;
    case CellType::kQuad4:
      return kQuadW;
    case CellType::kTet4:
      return kTetW;
    case CellType::kHex8:
      return kHexW;
    default:
      fail(type);
  }
}

}  // namespace tmop
