#include "tmop/element/bezier.h"

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "tmop/element/shape.h"

namespace tmop {
namespace {

// The polynomial space of det J: a simplex part (dimension sdim, total degree sdeg) times a tensor
// part (tdim axes on [-1, 1], degree tdeg each). Why these degrees: each column of J loses one
// degree along its own direction, and det J multiplies one entry of each column.
struct Space {
  int sdim = 0, sdeg = 0, tdim = 0, tdeg = 0;
};

bool SpaceOf(CellType type, Space* s) {
  switch (type) {
    case CellType::kTri3:
      *s = {2, 0, 0, 0};
      return true;
    case CellType::kTri6:  // J entries degree 1, product of two
      *s = {2, 2, 0, 0};
      return true;
    case CellType::kTet4:
      *s = {3, 0, 0, 0};
      return true;
    case CellType::kTet10:  // J entries degree 1, product of three
      *s = {3, 3, 0, 0};
      return true;
    case CellType::kQuad4:  // x_xi in Q(0,1), y_eta in Q(1,0)
      *s = {0, 0, 2, 1};
      return true;
    case CellType::kQuad9:  // x_xi in Q(1,2), y_eta in Q(2,1)
      *s = {0, 0, 2, 3};
      return true;
    case CellType::kHex8:  // x_xi in Q(0,1,1), ... product in Q(2,2,2)
      *s = {0, 0, 3, 2};
      return true;
    case CellType::kWedge6:  // x_xi, x_eta: P0 x Q1; x_zeta: P1 x Q0
      *s = {2, 1, 1, 2};
      return true;
    default:
      return false;
  }
}

double Factorial(int n) { return n <= 1 ? 1.0 : n * Factorial(n - 1); }

// Lattice of the space in the documented order: multi-indices (simplex a[0..2], tensor m[0..2]).
struct Lattice {
  int count = 0;
  std::array<std::array<int, 6>, kMaxBezierCoefficients> index{};  // i j k | m0 m1 m2
};

Lattice MakeLattice(const Space& s) {
  Lattice l;
  const int tn = s.tdim == 0 ? 1 : static_cast<int>(std::pow(s.tdeg + 1, s.tdim));
  for (int t = 0; t < tn; ++t) {
    int m[3] = {0, 0, 0}, rest = t;
    for (int a = 0; a < s.tdim; ++a) {
      m[a] = rest % (s.tdeg + 1);
      rest /= s.tdeg + 1;
    }
    const int p = s.sdeg;
    const int kmax = s.sdim == 3 ? p : 0, jmax = s.sdim >= 2 ? p : 0;
    for (int k = 0; k <= kmax; ++k)
      for (int j = 0; j <= jmax - k; ++j)
        for (int i = 0; i <= p - j - k; ++i) l.index[l.count++] = {i, j, k, m[0], m[1], m[2]};
  }
  return l;
}

void LatticePoint(const Space& s, const std::array<int, 6>& a, double* xi) {
  xi[0] = xi[1] = xi[2] = 0;
  for (int d = 0; d < s.sdim; ++d)
    xi[d] = s.sdeg == 0 ? 1.0 / (s.sdim + 1) : static_cast<double>(a[d]) / s.sdeg;
  for (int d = 0; d < s.tdim; ++d) xi[s.sdim + d] = -1 + 2.0 * a[3 + d] / s.tdeg;
}

// Bernstein basis function with multi-index a at xi (only used to build the collocation matrix).
double Bernstein(const Space& s, const std::array<int, 6>& a, const double* xi) {
  double v = 1;
  if (s.sdim > 0) {
    double lambda0 = 1;
    int a0 = s.sdeg;
    v = Factorial(s.sdeg);
    for (int d = 0; d < s.sdim; ++d) {
      lambda0 -= xi[d];
      a0 -= a[d];
      v *= std::pow(xi[d], a[d]) / Factorial(a[d]);
    }
    v *= std::pow(lambda0, a0) / Factorial(a0);
  }
  for (int d = 0; d < s.tdim; ++d) {
    const double t = xi[s.sdim + d];
    const int m = a[3 + d], p = s.tdeg;
    v *= Factorial(p) / (Factorial(m) * Factorial(p - m)) * std::pow(0.5 * (1 - t), p - m) *
         std::pow(0.5 * (1 + t), m);
  }
  return v;
}

struct TypeData {
  bool supported = false;
  Space space;
  Lattice lattice;
  std::array<std::array<double, 3>, kMaxBezierCoefficients> points{};
  Eigen::MatrixXd values_to_coefficients;  // inverse of the collocation matrix B(point_r)_c
};

struct Table {
  std::array<TypeData, kNumCellTypes> types;
  Table() {
    for (int t = 0; t < kNumCellTypes; ++t) {
      TypeData& d = types[t];
      d.supported = SpaceOf(static_cast<CellType>(t), &d.space);
      if (!d.supported) continue;
      d.lattice = MakeLattice(d.space);
      const int n = d.lattice.count;
      Eigen::MatrixXd B(n, n);
      for (int r = 0; r < n; ++r) {
        LatticePoint(d.space, d.lattice.index[r], d.points[r].data());
        for (int c = 0; c < n; ++c)
          B(r, c) = Bernstein(d.space, d.lattice.index[c], d.points[r].data());
      }
      d.values_to_coefficients = B.fullPivLu().inverse();
    }
  }
};

const Table& GetTable() {
  static const Table table;
  return table;
}

double Det(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

}  // namespace

int jacobian_bezier_count(CellType type) {
  const TypeData& d = GetTable().types[static_cast<int>(type)];
  return d.supported ? d.lattice.count : 0;
}

int jacobian_bezier_coefficients(CellType type, const double* node_coords, double* out) {
  const TypeData& d = GetTable().types[static_cast<int>(type)];
  if (!d.supported) return 0;
  const int n = d.lattice.count, dim = cell_dim(type);
  double values[kMaxBezierCoefficients];
  for (int r = 0; r < n; ++r) {
    double A[9];
    cell_jacobian(type, node_coords, dim, d.points[r].data(), A);
    values[r] = Det(A, dim);
  }
  const Eigen::MatrixXd& M = d.values_to_coefficients;
  for (int c = 0; c < n; ++c) {
    double sum = 0;
    for (int r = 0; r < n; ++r) sum += M(c, r) * values[r];
    out[c] = sum;
  }
  return n;
}

void jacobian_bezier_point(CellType type, int k, double* xi) {
  const TypeData& d = GetTable().types[static_cast<int>(type)];
  for (int j = 0; j < 3; ++j) xi[j] = d.points[k][j];
}

}  // namespace tmop
