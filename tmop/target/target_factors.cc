#include "tmop/target/target_factors.h"

#include <cmath>

#include "tmop/element/ideal_element.h"

namespace tmop {
namespace {

constexpr double kPi = 3.14159265358979323846;

double det(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

bool finite(const double* a, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(a[i])) return false;
  return true;
}

// Degrees to radians, exact at the right angle so that a 90 degree skew gives Q = I exactly.
void cos_sin(double degrees, double* c, double* s) {
  if (degrees == 90) {
    *c = 0;
    *s = 1;
    return;
  }
  const double r = degrees * kPi / 180;
  *c = std::cos(r);
  *s = std::sin(r);
}

}  // namespace

bool factor_jacobian(CellType type, const double* A, TargetFactors* f) {
  const int d = cell_dim(type);
  if (!finite(A, d * d)) return false;
  const double detA = det(A, d);
  if (!(detA > 0)) return false;
  // Modified Gram-Schmidt on the columns: A = R U with U upper triangular, positive diagonal
  // (det A > 0 keeps every diagonal entry positive and makes det R = +1).
  double e[3][3] = {}, U[3][3] = {}, length[3];
  for (int j = 0; j < d; ++j) {
    double v[3], l2 = 0;
    for (int i = 0; i < d; ++i) {
      v[i] = A[i * d + j];
      l2 += v[i] * v[i];
    }
    length[j] = std::sqrt(l2);
    // Two passes ("twice is enough"): R stays orthonormal to rounding even for a nearly
    // singular A, which one pass does not give.
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < j; ++k) {
        double r = 0;
        for (int i = 0; i < d; ++i) r += e[k][i] * v[i];
        U[k][j] += r;
        for (int i = 0; i < d; ++i) v[i] -= r * e[k][i];
      }
    double n = 0;
    for (int i = 0; i < d; ++i) n += v[i] * v[i];
    n = std::sqrt(n);
    if (!(n > 0)) return false;
    U[j][j] = n;
    for (int i = 0; i < d; ++i) e[j][i] = v[i] / n;
  }
  double product = 1;
  for (int j = 0; j < d; ++j) product *= length[j];
  const double l = std::pow(product, 1.0 / d);
  const double v = det(ideal_jacobian(type), d);
  *f = TargetFactors();  // identity outside the d x d blocks
  f->size = std::pow(detA / v, 1.0 / d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      f->orientation[i * 3 + j] = e[j][i];
      f->skew[i * 3 + j] = U[i][j] / length[j];
    }
  for (int j = 0; j < d; ++j) f->aspect[j] = length[j] / l;
  return true;
}

TargetFactors ideal_factors(CellType type) {
  TargetFactors f;
  factor_jacobian(type, ideal_jacobian(type), &f);  // det > 0 for every ideal element
  return f;
}

void compose_factors(CellType type, const TargetFactors& f, double* W) {
  const int d = cell_dim(type);
  double det_q = 1;
  for (int j = 0; j < d; ++j) det_q *= f.skew[j * 3 + j];
  const double s = f.size * std::pow(det(ideal_jacobian(type), d) / det_q, 1.0 / d);
  // W = s R (Q D): D scales Q's columns.
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      double w = 0;
      for (int k = 0; k < d; ++k) w += f.orientation[i * 3 + k] * f.skew[k * 3 + j];
      W[i * d + j] = s * w * f.aspect[j];
    }
}

bool orientation_from_axes(int d, const double* axes, double* R) {
  if (!finite(axes, d == 2 ? 2 : 6)) return false;
  if (d == 2) {
    const double n = std::hypot(axes[0], axes[1]);
    if (!(n > 0)) return false;
    const double c = axes[0] / n, s = axes[1] / n;
    const double r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    for (int i = 0; i < 9; ++i) R[i] = r[i];
    return true;
  }
  double e1[3], e2[3];
  const double n1 = std::sqrt(axes[0] * axes[0] + axes[1] * axes[1] + axes[2] * axes[2]);
  if (!(n1 > 0)) return false;
  for (int i = 0; i < 3; ++i) e1[i] = axes[i] / n1;
  const double* b = axes + 3;
  const double nb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  const double dot = e1[0] * b[0] + e1[1] * b[1] + e1[2] * b[2];
  for (int i = 0; i < 3; ++i) e2[i] = b[i] - dot * e1[i];
  const double n2 = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
  // Nearly parallel axes leave the second direction to rounding: refuse them.
  if (!(n2 > 1e-12 * nb)) return false;
  for (int i = 0; i < 3; ++i) e2[i] /= n2;
  const double e3[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
  for (int i = 0; i < 3; ++i) {
    R[i * 3 + 0] = e1[i];
    R[i * 3 + 1] = e2[i];
    R[i * 3 + 2] = e3[i];
  }
  return true;
}

bool skew_from_angles(int d, const double* degrees, double* Q) {
  const int n = d == 2 ? 1 : 3;
  for (int i = 0; i < n; ++i)
    if (!(degrees[i] > 0 && degrees[i] < 180)) return false;
  double c12, s12;
  cos_sin(degrees[0], &c12, &s12);
  if (d == 2) {
    const double q[9] = {1, c12, 0, 0, s12, 0, 0, 0, 1};
    for (int i = 0; i < 9; ++i) Q[i] = q[i];
    return true;
  }
  double c13, s13, c23, s23;
  cos_sin(degrees[1], &c13, &s13);
  cos_sin(degrees[2], &c23, &s23);
  // Columns q1 = e1, q2 = (c12, s12, 0), q3 = (c13, y, z) with q2 . q3 = c23 and |q3| = 1.
  const double y = (c23 - c12 * c13) / s12;
  const double z2 = 1 - c13 * c13 - y * y;
  // A (nearly) flat trihedron would make det Q vanish up to rounding: refuse it.
  if (!(z2 > 1e-12)) return false;
  const double q[9] = {1, c12, c13, 0, s12, y, 0, 0, std::sqrt(z2)};
  for (int i = 0; i < 9; ++i) Q[i] = q[i];
  return true;
}

bool aspect_from_lengths(int d, const double* lengths, double* aspect) {
  double product = 1;
  for (int j = 0; j < d; ++j) {
    if (!(lengths[j] > 0) || !std::isfinite(lengths[j])) return false;
    product *= lengths[j];
  }
  const double l = std::pow(product, 1.0 / d);
  if (!(l > 0) || !std::isfinite(l)) return false;
  for (int j = 0; j < d; ++j) aspect[j] = lengths[j] / l;
  return true;
}

}  // namespace tmop
