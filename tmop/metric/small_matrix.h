// tmop/metric/small_matrix.h
// Closed-form kernels on row-major D x D matrices (D = 2 or 3) for the per-sample-point metric
// code: determinant, cofactor matrix, Frobenius norm, the second derivative of the determinant,
// the rotation factor of the polar decomposition and its derivative. Plain arrays, no
// allocation, inline.
//
// cof(T) is the matrix of cofactors, cof(T) = det(T) T^-T = d det(T) / dT; it exists for every
// T, so metrics use it instead of the inverse until they know det T != 0.
//
// Kept inside metric/ because the metrics are its only hot users; core/ may later adopt it.
#ifndef TMOP_METRIC_SMALL_MATRIX_H_
#define TMOP_METRIC_SMALL_MATRIX_H_

#include <cmath>
#include <cstdint>
#include <cstring>

namespace tmop {
namespace small_matrix {

// x^(1/3) for finite x > 0 (normal numbers), within 3 ulps of glibc's std::cbrt (itself not
// correctly rounded) and ~2x faster; glibc's cbrt took a quarter of the 3D shape metric's time.
// An exponent-dividing bit guess (6 % error), two Halley steps (error e -> ~e^3: 2e-4, 1e-11)
// and a Newton step.
inline double cbrt_positive(double x) {
  std::uint64_t i;
  std::memcpy(&i, &x, sizeof i);
  i = i / 3 + 0x2a9f7893782da1ceULL;  // (bias - bias / 3) in the exponent field, tuned
  double y;
  std::memcpy(&y, &i, sizeof y);
  for (int k = 0; k < 2; ++k) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  }
  return y - (y * y * y - x) / (3.0 * y * y);
}

// x^(-1/3) for finite x > 0 without a division: an exponent-dividing bit guess (3.7 % error),
// two steps y (1 + d/3 + 2 d^2/9), d = 1 - x y^3 (error e -> ~e^3: 1e-4, 1e-11), a Newton step;
// within 1 ulp. Subnormal and huge x (the guess is wrong there) fall back to std::cbrt.
inline double inv_cbrt_positive(double x) {
  if (!(x > 1e-300 && x < 1e300)) return 1.0 / std::cbrt(x);
  std::uint64_t i;
  std::memcpy(&i, &x, sizeof i);
  i = 0x553ee00000000000ULL - i / 3;
  double y;
  std::memcpy(&y, &i, sizeof y);
  for (int k = 0; k < 2; ++k) {
    const double d = 1.0 - x * (y * y * y);
    y *= 1.0 + d * (1.0 / 3.0 + d * (2.0 / 9.0));
  }
  return y + y * (1.0 - x * (y * y * y)) * (1.0 / 3.0);
}

template <int D>
inline double det(const double* T);

template <>
inline double det<2>(const double* T) {
  return T[0] * T[3] - T[1] * T[2];
}

template <>
inline double det<3>(const double* T) {
  return T[0] * (T[4] * T[8] - T[5] * T[7]) - T[1] * (T[3] * T[8] - T[5] * T[6]) +
         T[2] * (T[3] * T[7] - T[4] * T[6]);
}

// C = cof(T) = d det(T) / dT (row-major, may not alias T).
template <int D>
inline void cofactor(const double* T, double* C);

template <>
inline void cofactor<2>(const double* T, double* C) {
  C[0] = T[3];
  C[1] = -T[2];
  C[2] = -T[1];
  C[3] = T[0];
}

template <>
inline void cofactor<3>(const double* T, double* C) {
  C[0] = T[4] * T[8] - T[5] * T[7];
  C[1] = T[5] * T[6] - T[3] * T[8];
  C[2] = T[3] * T[7] - T[4] * T[6];
  C[3] = T[2] * T[7] - T[1] * T[8];
  C[4] = T[0] * T[8] - T[2] * T[6];
  C[5] = T[1] * T[6] - T[0] * T[7];
  C[6] = T[1] * T[5] - T[2] * T[4];
  C[7] = T[2] * T[3] - T[0] * T[5];
  C[8] = T[0] * T[4] - T[1] * T[3];
}

// det(T) from a row of T and the matching row of cof(T) (Laplace expansion): saves the
// separate determinant when the cofactors are needed anyway.
template <int D>
inline double det_from_cofactor(const double* T, const double* C) {
  double s = 0.0;
  for (int j = 0; j < D; ++j) s += T[j] * C[j];
  return s;
}

template <int D>
inline double frobenius2(const double* T) {
  double s = 0.0;
  for (int i = 0; i < D * D; ++i) s += T[i] * T[i];
  return s;
}

// H = d cof(T)_ij / dT_kl for 3x3 T, stored as a 9 x 9 row-major matrix (row 3i+j, column 3k+l).
// cof_ij = T_ab T_ce - T_ae T_cb with a = i+1, c = i+2, b = j+1, e = j+2 (mod 3), so each row has
// four non-zeros; H is filled completely (zeros included).
inline void cofactor_derivative_3(const double* T, double* H) {
  for (int n = 0; n < 81; ++n) H[n] = 0.0;
  for (int i = 0; i < 3; ++i) {
    const int a = (i + 1) % 3, c = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int b = (j + 1) % 3, e = (j + 2) % 3;
      double* row = H + 9 * (3 * i + j);
      row[3 * a + b] = T[3 * c + e];
      row[3 * c + e] = T[3 * a + b];
      row[3 * a + e] = -T[3 * c + b];
      row[3 * c + b] = -T[3 * a + e];
    }
  }
}

// R = the rotation factor of the polar decomposition S = R P (P symmetric positive definite) of
// a 3x3 S with det S > 0, fastest when det S is close to 1 (pass T det(T)^(-1/3); the metrics
// have it anyway). Newton iteration X <- (g X + X^-T / g) / 2 (Higham 1986): unscaled (g = 1)
// while the update is below 1 in norm, with the Frobenius-norm scaling g = sqrt(|X^-1| / |X|)
// above, which keeps ill-conditioned S (condition 1e6) to about 7 iterations; 4-6 iterations for
// the elements seen in meshes; no SVD. Stops when the update is below 1e-8 (quadratic
// convergence leaves an error ~1e-16). Returns false when det S <= 0 or S is not finite.
inline bool polar_rotation_unit_det_3(const double* S, double* R) {
  double X[9], C[9];
  for (int n = 0; n < 9; ++n) X[n] = S[n];
  double delta2 = 0.0;
  for (int iter = 0; iter < 100; ++iter) {
    cofactor<3>(X, C);
    const double tau = det_from_cofactor<3>(X, C);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    // X^-T = C / tau, so |X^-1| / |X| = sqrt(|C|^2 / |X|^2) / tau.
    const double g =
        delta2 > 1.0 ? std::sqrt(std::sqrt(frobenius2<3>(C) / frobenius2<3>(X)) / tau) : 1.0;
    const double a = 0.5 * g, b = 0.5 / (g * tau);
    delta2 = 0.0;
    for (int n = 0; n < 9; ++n) {
      const double x = a * X[n] + b * C[n];
      delta2 += (x - X[n]) * (x - X[n]);
      X[n] = x;
    }
    if (delta2 < 1e-16) break;
  }
  for (int n = 0; n < 9; ++n) R[n] = X[n];
  return true;
}

// The polar rotation of any 3x3 T with det T > 0 (normalises the determinant first).
inline bool polar_rotation_3(const double* T, double* R) {
  const double tau = det<3>(T);
  if (!(tau > 0.0) || !std::isfinite(tau)) return false;
  const double a = 1.0 / std::cbrt(tau);
  double S[9];
  for (int n = 0; n < 9; ++n) S[n] = a * T[n];
  return polar_rotation_unit_det_3(S, R);
}

// L = dR/dS for the polar decomposition S = R P (3x3, det S > 0), as a 9 x 9 row-major matrix
// acting on vec(dS). Derivation: dS = dR P + R dP with dR = R W, W skew; the skew part of
// R^t dS is W P + P W = [ (tr(P) I - P) w ]x for W = [w]x. So w = K m with
// K = (tr(P) I - P)^-1 (positive definite: its eigenvalues are sums of two eigenvalues of P) and
// m = axial(R^t dS - dS^t R) = A vec(dS); dR = R [w]x = A^t w. Hence L = A^t K A (symmetric,
// rank 3), with A_{l,(k,l+1)} = R_{k,l+2}, A_{l,(k,l+2)} = -R_{k,l+1} (indices mod 3).
// R must be the rotation factor of S (polar_rotation_3).
inline void polar_rotation_derivative_3(const double* S, const double* R, double* L) {
  // P = R^t S (symmetric up to round-off; symmetrised).
  double P[9];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k) s += R[3 * k + i] * S[3 * k + j];
      P[3 * i + j] = s;
    }
  }
  const double tr = P[0] + P[4] + P[8];
  double Q[9], K[9];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) Q[3 * i + j] = -0.5 * (P[3 * i + j] + P[3 * j + i]);
    Q[4 * i] += tr;
  }
  cofactor<3>(Q, K);  // Q symmetric: Q^-1 = cof(Q) / det(Q)
  const double inv_det = 1.0 / det_from_cofactor<3>(Q, K);
  for (int n = 0; n < 9; ++n) K[n] *= inv_det;
  double A[27];
  for (int n = 0; n < 27; ++n) A[n] = 0.0;
  for (int l = 0; l < 3; ++l) {
    const int l1 = (l + 1) % 3, l2 = (l + 2) % 3;
    for (int k = 0; k < 3; ++k) {
      A[9 * l + 3 * k + l1] = R[3 * k + l2];
      A[9 * l + 3 * k + l2] = -R[3 * k + l1];
    }
  }
  double KA[27];
  for (int i = 0; i < 3; ++i) {
    for (int n = 0; n < 9; ++n) {
      KA[9 * i + n] = K[3 * i] * A[n] + K[3 * i + 1] * A[9 + n] + K[3 * i + 2] * A[18 + n];
    }
  }
  for (int p = 0; p < 9; ++p) {
    for (int q = p; q < 9; ++q) {
      const double v = A[p] * KA[q] + A[9 + p] * KA[9 + q] + A[18 + p] * KA[18 + q];
      L[9 * p + q] = v;
      L[9 * q + p] = v;
    }
  }
}

}  // namespace small_matrix
}  // namespace tmop

#endif  // TMOP_METRIC_SMALL_MATRIX_H_
