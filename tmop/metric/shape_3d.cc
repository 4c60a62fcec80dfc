// tmop/metric/shape_3d.cc
// 3D shape metrics: polar residual form for the barrier ones, cofactor form for mu_360
// (see shape_3d.h for the derivations).
#include "tmop/metric/shape_3d.h"

#include <cmath>
#include <limits>

#include "tmop/metric/metric_base.h"
#include "tmop/metric/small_matrix.h"

namespace tmop {
namespace {

constexpr double kSqrt3 = 1.73205080756887729353;
constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt6 = 0.40824829046386301637;

double nan_or_inf(double tau) {
  return std::isnan(tau) ? tau : std::numeric_limits<double>::infinity();
}

// F(X) = vec(cof X - n X) / (2 sqrt(n)), n = |X| / sqrt(3): the cofactor form of mu_360
// (shape_3d.h), and dF/dX when J is not null.
bool conformal_residual(const double* X, double* F, double* J) {
  const double f2 = small_matrix::frobenius2<3>(X);
  if (!std::isfinite(f2)) return false;
  const double n = std::sqrt(f2 / 3.0);
  if (!(n > 1e-150)) {  // X = 0 (a minimiser): F -> 0 and dF/dX -> 0 like |X|^(3/2), |X|^(1/2)
    for (int m = 0; m < 9; ++m) F[m] = 0.0;
    if (J != nullptr) {
      for (int m = 0; m < 81; ++m) J[m] = 0.0;
    }
    return true;
  }
  double C[9];
  small_matrix::cofactor<3>(X, C);
  const double sn = std::sqrt(n);
  const double u = 0.5 / sn;  // F = u cof - v X
  const double v = 0.5 * sn;
  for (int m = 0; m < 9; ++m) F[m] = u * C[m] - v * X[m];
  if (J != nullptr) {
    // dF = u dcof - v I - cof (x) X / (12 n^(5/2)) - X (x) X / (12 n^(3/2)).
    small_matrix::cofactor_derivative_3(X, J);
    const double p = 1.0 / (12.0 * n * n * sn);
    const double q = n * p;
    for (int i = 0; i < 9; ++i) {
      double* row = J + 9 * i;
      const double ai = -(p * C[i] + q * X[i]);
      for (int m = 0; m < 9; ++m) row[m] = u * row[m] + ai * X[m];
      row[i] -= v;
    }
  }
  return true;
}

// The deviatoric residuals of mu_303 (Mu303 = true) and mu_304 in one regime, for every T with
// tau > 0. For these two metrics mu = rho |w|^2 never cancels: with s = |w|^2 = |D|^2 and
// e = det D, rho carries f / 6 - e / s, and e / s <= f / 9 because M = D + (f / 3) I >= 0, so
// f / 6 - e / s >= f / 18 (mu_301 and mu_302 carry f - 9 e / s, which does cancel on needles:
// they keep the two-regime path below). Straight-line code: one division-free cube root, three
// independent divisions and one square root for mu_303.
//   r = alpha w, alpha = sqrt(rho); dr/dT = dw/dT (alpha T) + w u^t, u = (alpha / 2) d ln rho / dT
//   d ln rho / dT = ca T - cb d(e/s)/dT - cc K,  d(e/s)/dT = (2 / s) T (dev cof D - 2 (e/s) D),
// so u = T Y - (alpha / 2) cc K with Y symmetric (alpha / 2) (ca I - (2 cb / s) (dev cof D -
// 2 (e/s) D)).
template <bool Mu303>
bool deviatoric_303_304(const double* T, double* r, double* dr_dT) {
  double K[9];
  small_matrix::cofactor<3>(T, K);
  const double tau = small_matrix::det_from_cofactor<3>(T, K);
  if (!(tau > 0.0) || !std::isfinite(tau)) return false;
  // M = T^t T (upper triangle), f = tr M, D = M - (f / 3) I.
  double M00 = 0, M01 = 0, M02 = 0, M11 = 0, M12 = 0, M22 = 0;
  for (int a = 0; a < 3; ++a) {
    const double t0 = T[3 * a], t1 = T[3 * a + 1], t2 = T[3 * a + 2];
    M00 += t0 * t0;
    M01 += t0 * t1;
    M02 += t0 * t2;
    M11 += t1 * t1;
    M12 += t1 * t2;
    M22 += t2 * t2;
  }
  const double f = M00 + M11 + M22, m3 = f / 3.0;
  const double D00 = M00 - m3, D11 = M11 - m3, D22 = M22 - m3;
  const double w[5] = {kInvSqrt2 * (M00 - M11), kInvSqrt6 * (M00 + M11 - 2.0 * M22), kSqrt2 * M01,
                       kSqrt2 * M02, kSqrt2 * M12};
  const double s = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] + w[3] * w[3] + w[4] * w[4];
  // cof D (symmetric) and det D by its first row.
  const double c00 = D11 * D22 - M12 * M12, c11 = D00 * D22 - M02 * M02,
               c22 = D00 * D11 - M01 * M01;
  const double c01 = M12 * M02 - M01 * D22, c02 = M01 * M12 - D11 * M02,
               c12 = M01 * M02 - D00 * M12;
  const double e = D00 * c00 + M01 * c01 + M02 * c02;
  // Below s = 1e-30 f^2 (|D| ~ 1e-15 f: rounding noise of M) dropping e / s changes rho by a
  // few ulps and w u^t by ~1e-15 of alpha dw/dT.
  const bool deviates = s > 1e-30 * f * f;
  const double is = deviates ? 1.0 / s : 0.0;
  const double dl = e * is, num = f / 6.0 - dl;
  double rho, ca, cc, it;
  if constexpr (Mu303) {
    const double z = small_matrix::inv_cbrt_positive(tau);  // tau^(-1/3)
    const double q2 = tau * z, P = f * f + 3.0 * f * q2 + 9.0 * q2 * q2, iP = 1.0 / P;
    it = z * z * z;
    rho = 9.0 * num * (z * z) * iP;
    ca = -2.0 * (2.0 * f + 3.0 * q2) * iP;
    cc = (2.0 / 3.0) * it * (1.0 + (3.0 * f + 18.0 * q2) * q2 * iP);
  } else {
    const double sf = std::sqrt(f), iQ = 1.0 / (f * sf + 3.0 * kSqrt3 * tau);
    it = 1.0 / tau;
    rho = 3.0 * kSqrt3 * num * it * iQ;
    ca = -3.0 * sf * iQ;
    cc = it + 3.0 * kSqrt3 * iQ;
  }
  if (!(rho > 0.0) || !std::isfinite(rho) || !std::isfinite(s)) return false;
  const double alpha = std::sqrt(rho);
  for (int j = 0; j < 5; ++j) r[j] = alpha * w[j];
  if (dr_dT == nullptr) return true;
  const double inum = 1.0 / num, h = 0.5 * alpha;
  // Y = h (ca + inum / 3) I - h inum (2 / s) X, X = dev cof D - 2 (e/s) D.
  const double g = -2.0 * h * inum * is, t3 = (c00 + c11 + c22) / 3.0, dl2 = 2.0 * dl;
  const double yd = h * (ca + inum / 3.0);
  const double Y00 = yd + g * (c00 - t3 - dl2 * D00), Y11 = yd + g * (c11 - t3 - dl2 * D11),
               Y22 = yd + g * (c22 - t3 - dl2 * D22);
  const double Y01 = g * (c01 - dl2 * M01), Y02 = g * (c02 - dl2 * M02),
               Y12 = g * (c12 - dl2 * M12);
  const double hc = h * cc, as2 = alpha * kSqrt2, as6 = alpha * 2.0 * kInvSqrt6;
  for (int a = 0; a < 3; ++a) {
    const int i0 = 3 * a, i1 = i0 + 1, i2 = i0 + 2;
    const double t0 = T[i0], t1 = T[i1], t2 = T[i2];
    const double u0 = t0 * Y00 + t1 * Y01 + t2 * Y02 - hc * K[i0];
    const double u1 = t0 * Y01 + t1 * Y11 + t2 * Y12 - hc * K[i1];
    const double u2 = t0 * Y02 + t1 * Y12 + t2 * Y22 - hc * K[i2];
    const double p0 = as2 * t0, p1 = as2 * t1, p2 = as2 * t2;
    const double v0 = as6 * t0, v1 = as6 * t1, v2 = as6 * t2;
    double* d0 = dr_dT;       // w0 = (M00 - M11) / sqrt2
    double* d1 = dr_dT + 9;   // w1 = (M00 + M11 - 2 M22) / sqrt6
    double* d2 = dr_dT + 18;  // w2 = sqrt2 M01
    double* d3 = dr_dT + 27;  // w3 = sqrt2 M02
    double* d4 = dr_dT + 36;  // w4 = sqrt2 M12
    d0[i0] = p0 + w[0] * u0, d0[i1] = -p1 + w[0] * u1, d0[i2] = w[0] * u2;
    d1[i0] = v0 + w[1] * u0, d1[i1] = v1 + w[1] * u1, d1[i2] = -2.0 * v2 + w[1] * u2;
    d2[i0] = p1 + w[2] * u0, d2[i1] = p0 + w[2] * u1, d2[i2] = w[2] * u2;
    d3[i0] = p2 + w[3] * u0, d3[i1] = w[3] * u1, d3[i2] = p0 + w[3] * u2;
    d4[i0] = w[4] * u0, d4[i1] = p2 + w[4] * u1, d4[i2] = p1 + w[4] * u2;
  }
  return true;
}

class BarrierShapeMetric final : public FixedMetric {
 public:
  BarrierShapeMetric(Shape3dForm form, const char* name, const char* alias, double c2,
                     Shape3dResidual residual)
      : FixedMetric(name, alias, 3, MetricClass::kShape, true,
                    residual == Shape3dResidual::kDeviatoric ? 5 : 9,
                    residual == Shape3dResidual::kDeviatoric),
        form_(form),
        c_(std::sqrt(c2)),
        residual_(residual) {}

  double value(const double* T) const override {
    Invariants in;
    if (!in.compute(T, form_ == Shape3dForm::kBarrier)) return nan_or_inf(in.tau);
    return mu(in);
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    // The deviatoric form computes cof T and checks tau > 0 itself (Invariants::compute).
    if (residual_ == Shape3dResidual::kDeviatoric) return deviatoric_residuals(T, r, dr_dT);
    double C[9];
    small_matrix::cofactor<3>(T, C);
    const double tau = small_matrix::det_from_cofactor<3>(T, C);
    if (!(tau > 0.0) || !std::isfinite(tau)) return false;
    const double a = 1.0 / std::cbrt(tau);
    double S[9], R[9];
    for (int n = 0; n < 9; ++n) S[n] = a * T[n];
    if (residual_ == Shape3dResidual::kCofactor) return cofactor_residuals(a, tau, S, C, r, dr_dT);
    if (!small_matrix::polar_rotation_unit_det_3(S, R)) return false;
    const double ca = c_ * a;
    for (int n = 0; n < 9; ++n) {
      r[n] = c_ * (S[n] - R[n]);
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      // dS/dT = a (I - vec(T) vec(T^-t)^t / 3), T^-t = C / tau. With R held fixed dr/dT = c dS/dT;
      // the exact Jacobian is c (I - L) dS/dT with L = dR/dS.
      const double b = 1.0 / (3.0 * tau);
      if (residual_ == Shape3dResidual::kPolarRotationFixed) {
        for (int n = 0; n < 9; ++n) {
          double* row = dr_dT + 9 * n;
          const double bt = -ca * b * T[n];
          for (int m = 0; m < 9; ++m) row[m] = bt * C[m];
          row[n] += ca;
        }
        return true;
      }
      double L[81];
      small_matrix::polar_rotation_derivative_3(S, R, L);
      // (I - L)(I - t g^t / 3) = I - L - t g^t / 3, since L t = 0: A t = axial(R^t T - T^t R)
      // vanishes because R^t T = P / a is symmetric.
      const double cb = -ca * b;
      for (int n = 0; n < 9; ++n) {
        double* row = dr_dT + 9 * n;
        const double* l = L + 9 * n;
        const double bt = cb * T[n];
        for (int m = 0; m < 9; ++m) row[m] = bt * C[m] - ca * l[m];
        row[n] += ca;
      }
    }
    return true;
  }

 private:
  // What the formulas need, for tau > 0: K = cof T, f = |T|^2, fk = |K|^2, M = T^t T (upper
  // triangle), D = dev M = M - (f / 3) I, w = the coordinates of D in the orthonormal basis
  // (e11 - e22) / sqrt2, (e11 + e22 - 2 e33) / sqrt6, (e12 + e21) / sqrt2, (e13 + e31) / sqrt2,
  // (e23 + e32) / sqrt2 of the traceless symmetric matrices (|w| = |D|), and det D.
  struct Invariants {
    double K[9], tau, f, fk, M[3][3], D[3][3], w[5], w2, det_D;
    double q2 = 0;  // tau^(2/3), mu_303 only
    bool compute(const double* T, bool need_q2) {
      small_matrix::cofactor<3>(T, K);
      tau = small_matrix::det_from_cofactor<3>(T, K);
      if (!(tau > 0.0) || !std::isfinite(tau)) return false;
      if (need_q2) q2 = small_matrix::cbrt_positive(tau * tau);
      f = small_matrix::frobenius2<3>(T);
      fk = small_matrix::frobenius2<3>(K);
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) {
          M[i][j] = T[i] * T[j] + T[3 + i] * T[3 + j] + T[6 + i] * T[6 + j];
          M[j][i] = M[i][j];
        }
      w[0] = kInvSqrt2 * (M[0][0] - M[1][1]);
      w[1] = kInvSqrt6 * (M[0][0] + M[1][1] - 2.0 * M[2][2]);
      w[2] = kSqrt2 * M[0][1];
      w[3] = kSqrt2 * M[0][2];
      w[4] = kSqrt2 * M[1][2];
      w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2] + w[3] * w[3] + w[4] * w[4];
      const double m = f / 3.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) D[i][j] = M[i][j] - (i == j ? m : 0.0);
      det_D = D[0][0] * (D[1][1] * D[2][2] - D[1][2] * D[1][2]) -
              D[0][1] * (D[0][1] * D[2][2] - D[1][2] * D[0][2]) +
              D[0][2] * (D[0][1] * D[1][2] - D[1][1] * D[0][2]);
      return std::isfinite(f) && std::isfinite(fk) && std::isfinite(w2);
    }
  };

  // The published formula as written: accurate to a few ulps of 1 + mu, so relatively accurate
  // wherever mu is not small.
  double published_mu(const Invariants& in) const {
    switch (form_) {
      case Shape3dForm::kBarrier:
        return in.f / (3.0 * in.q2) - 1.0;
      case Shape3dForm::kCubicBarrier:
        return in.f * std::sqrt(in.f) / (3.0 * kSqrt3 * in.tau) - 1.0;
      case Shape3dForm::kConditionBarrier:
        return std::sqrt(in.f * in.fk) / (3.0 * in.tau) - 1.0;
      case Shape3dForm::kConditionSquaredBarrier:
        return in.f * in.fk / (9.0 * in.tau * in.tau) - 1.0;
      default:
        return std::numeric_limits<double>::quiet_NaN();
    }
  }

  // Near the minimiser (published mu < kNear) the formulas cancel; there mu = rho |w|^2 with
  // rho computed without cancellation. With m = f / 3 and the eigenvalues m + d_i of M
  // (sum d_i = 0): det M = m^3 - m |D|^2 / 2 + det D, hence
  //   f^3 - 27 tau^2 = 27 |D|^2 (f / 6 - delta),   f fk - 9 tau^2 = |D|^2 (f - 9 delta),
  // delta = det D / |D|^2 = O(|D|), and a^3 - b^3 = (a - b)(a^2 + ab + b^2) gives
  //   mu_303 = 9 (f/6 - delta) / (q^2 P) |D|^2,  q^2 = tau^(2/3), P = f^2 + 3 f q^2 + 9 q^4,
  //   mu_304 = 3 sqrt3 (f/6 - delta) / (tau Q) |D|^2,  Q = f^(3/2) + 3 sqrt3 tau,
  //   mu_301 = (f - 9 delta) / (3 tau (g + 3 tau)) |D|^2,  g = sqrt(f fk),
  //   mu_302 = (f - 9 delta) / (9 tau^2) |D|^2.
  // (Far from the minimiser f - 9 delta cancels instead, on needles: hence two regimes.)
  static constexpr double kNear = 0.25;
  double delta(const Invariants& in) const { return in.w2 > 0.0 ? in.det_D / in.w2 : 0.0; }
  double rho(const Invariants& in) const {
    const double dl = delta(in);
    switch (form_) {
      case Shape3dForm::kBarrier: {
        const double q2 = in.q2;
        return 9.0 * (in.f / 6.0 - dl) / (q2 * (in.f * in.f + 3.0 * in.f * q2 + 9.0 * q2 * q2));
      }
      case Shape3dForm::kCubicBarrier:
        return 3.0 * kSqrt3 * (in.f / 6.0 - dl) /
               (in.tau * (in.f * std::sqrt(in.f) + 3.0 * kSqrt3 * in.tau));
      case Shape3dForm::kConditionBarrier:
        return (in.f - 9.0 * dl) / (3.0 * in.tau * (std::sqrt(in.f * in.fk) + 3.0 * in.tau));
      case Shape3dForm::kConditionSquaredBarrier:
        return (in.f - 9.0 * dl) / (9.0 * in.tau * in.tau);
      default:
        return std::numeric_limits<double>::quiet_NaN();
    }
  }
  double mu(const Invariants& in) const {
    const double p = published_mu(in);
    return p < kNear ? rho(in) * in.w2 : p;
  }

  // d fk / dT = 2 T (f I - M), row-major.
  static void dfk_dT(const double* T, const Invariants& in, double* dfk) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double tm = 0.0;
        for (int c = 0; c < 3; ++c) tm += T[3 * a + c] * in.M[c][b];
        dfk[3 * a + b] = 2.0 * (in.f * T[3 * a + b] - tm);
      }
  }

  // dmu/dT of the published formula (far regime).
  void mu_gradient(const double* T, const Invariants& in, double* grad) const {
    const double* K = in.K;
    const double tau = in.tau, f = in.f, fk = in.fk;
    switch (form_) {
      case Shape3dForm::kBarrier: {
        const double a = 2.0 / (3.0 * in.q2), b = f / (3.0 * tau);
        for (int n = 0; n < 9; ++n) grad[n] = a * (T[n] - b * K[n]);
        return;
      }
      case Shape3dForm::kCubicBarrier: {
        const double a = std::sqrt(f) / (kSqrt3 * tau), b = f / (3.0 * tau);
        for (int n = 0; n < 9; ++n) grad[n] = a * (T[n] - b * K[n]);
        return;
      }
      case Shape3dForm::kConditionBarrier:
      case Shape3dForm::kConditionSquaredBarrier: {
        double dfk[9];
        dfk_dT(T, in, dfk);
        if (form_ == Shape3dForm::kConditionBarrier) {
          const double g = std::sqrt(f * fk);
          const double a = 1.0 / (6.0 * g * tau), b = g / (3.0 * tau * tau);
          for (int n = 0; n < 9; ++n) grad[n] = a * (2.0 * fk * T[n] + f * dfk[n]) - b * K[n];
          return;
        }
        const double it2 = 1.0 / (9.0 * tau * tau);
        const double b = 2.0 * f * fk * it2 / tau;
        for (int n = 0; n < 9; ++n) grad[n] = it2 * (2.0 * fk * T[n] + f * dfk[n]) - b * K[n];
        return;
      }
      default:
        for (int n = 0; n < 9; ++n) grad[n] = std::numeric_limits<double>::quiet_NaN();
    }
  }

  // d rho / dT (near regime). d delta = (d det D - delta d|w|^2) / |w|^2 with
  // d det D / dT = 2 T dev(cof D) and d|w|^2 = d|D|^2 = 4 T D.
  void rho_gradient(const double* T, const Invariants& in, double rho_value, double* grad) const {
    const double* K = in.K;
    const double tau = in.tau, f = in.f;
    const double dl = delta(in);
    double ddl[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    if (in.w2 > 0.0) {
      const double(&D)[3][3] = in.D;
      double cD[3][3] = {
          {D[1][1] * D[2][2] - D[1][2] * D[1][2], D[1][2] * D[0][2] - D[0][1] * D[2][2],
           D[0][1] * D[1][2] - D[1][1] * D[0][2]},
          {0, D[0][0] * D[2][2] - D[0][2] * D[0][2], D[0][1] * D[0][2] - D[0][0] * D[1][2]},
          {0, 0, D[0][0] * D[1][1] - D[0][1] * D[0][1]}};
      cD[1][0] = cD[0][1];
      cD[2][0] = cD[0][2];
      cD[2][1] = cD[1][2];
      // sum_j w_j dw_j = d|D|^2 / 2 = 2 T D, so d delta = (2 / |w|^2) T (dev cof D - 2 delta D).
      const double t3 = (cD[0][0] + cD[1][1] + cD[2][2]) / 3.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) cD[i][j] -= 2.0 * dl * D[i][j] + (i == j ? t3 : 0.0);
      const double iw2 = 2.0 / in.w2;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          ddl[3 * a + b] =
              iw2 * (T[3 * a] * cD[0][b] + T[3 * a + 1] * cD[1][b] + T[3 * a + 2] * cD[2][b]);
    }
    // grad = rho (a T - b d delta - c K) (+ the d fk term of mu_301), from d ln rho.
    const double it = 1.0 / tau;
    double ca = 0, cb = 0, cc = 0;
    switch (form_) {
      case Shape3dForm::kBarrier: {
        // ln rho = ln(f/6 - delta) - ln q^2 - ln P + const, dq^2 = (2/3) q^2 K / tau.
        const double q2 = in.q2;
        const double iP = 1.0 / (f * f + 3.0 * f * q2 + 9.0 * q2 * q2), inum = 1.0 / (f / 6.0 - dl);
        ca = inum / 3.0 - 2.0 * (2.0 * f + 3.0 * q2) * iP;
        cb = inum;
        cc = (2.0 / 3.0) * it * (1.0 + (3.0 * f + 18.0 * q2) * q2 * iP);
        break;
      }
      case Shape3dForm::kCubicBarrier: {  // ln rho = ln(f/6 - delta) - ln tau - ln Q + const
        const double sf = std::sqrt(f);
        const double iQ = 1.0 / (f * sf + 3.0 * kSqrt3 * tau), inum = 1.0 / (f / 6.0 - dl);
        ca = inum / 3.0 - 3.0 * sf * iQ;
        cb = inum;
        cc = it + 3.0 * kSqrt3 * iQ;
        break;
      }
      case Shape3dForm::kConditionBarrier: {
        // ln rho = ln(f - 9 delta) - ln tau - ln(g + 3 tau), dg = (fk df + f dfk) / (2 g).
        double dfk[9];
        dfk_dT(T, in, dfk);
        const double g = std::sqrt(f * in.fk);
        const double iden = 1.0 / (g + 3.0 * tau), inum = 1.0 / (f - 9.0 * dl);
        const double a = 2.0 * inum - in.fk * iden / g, b = 9.0 * inum, c = it + 3.0 * iden;
        const double e = 0.5 * f * iden / g;
        for (int n = 0; n < 9; ++n)
          grad[n] = rho_value * (a * T[n] - b * ddl[n] - c * K[n] - e * dfk[n]);
        return;
      }
      case Shape3dForm::kConditionSquaredBarrier: {  // rho = (f - 9 delta) / (9 tau^2)
        const double it2 = it * it / 9.0;
        for (int n = 0; n < 9; ++n)
          grad[n] = (2.0 * T[n] - 9.0 * ddl[n]) * it2 - 2.0 * rho_value * K[n] * it;
        return;
      }
      default:
        for (int n = 0; n < 9; ++n) grad[n] = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    for (int n = 0; n < 9; ++n) grad[n] = rho_value * (ca * T[n] - cb * ddl[n] - cc * K[n]);
  }

  // r = sqrt(mu) w / |w| = alpha w (shape_3d.h). Far from the minimiser alpha = sqrt(mu / |w|^2)
  // with the published mu and dr/dT = alpha (I - n n^t) dw/dT + n (dmu/dT)^t / (2 sqrt(mu)),
  // n = w / |w|; near it alpha = sqrt(rho) and dr/dT = alpha dw/dT + w (d rho/dT)^t / (2 alpha),
  // with no division by |w| (at w = 0 exactly, r = 0 and dr/dT = alpha dw/dT).
  bool deviatoric_residuals(const double* T, double* r, double* dr_dT) const {
    if (form_ == Shape3dForm::kBarrier) return deviatoric_303_304<true>(T, r, dr_dT);
    if (form_ == Shape3dForm::kCubicBarrier) return deviatoric_303_304<false>(T, r, dr_dT);
    Invariants in;
    if (!in.compute(T, form_ == Shape3dForm::kBarrier)) return false;
    const double p = published_mu(in);
    if (!std::isfinite(p)) return false;
    const bool near = p < kNear;
    const double rho_value = near ? rho(in) : 0.0;
    if (near && !(rho_value > 0.0)) return false;  // cannot happen for tau > 0 (rho >= f/54...)
    const double alpha = near ? std::sqrt(rho_value) : std::sqrt(p / in.w2);
    const double* w = in.w;
    for (int j = 0; j < 5; ++j) r[j] = alpha * w[j];
    if (dr_dT == nullptr) return true;
    // dw/dT, row-major per residual: row a of T carries (T_a0, T_a1, T_a2).
    double* dw = dr_dT;  // filled with dw first, scaled below
    for (int a = 0; a < 3; ++a) {
      const double t0 = T[3 * a], t1 = T[3 * a + 1], t2 = T[3 * a + 2];
      const int i0 = 3 * a, i1 = 3 * a + 1, i2 = 3 * a + 2;
      // d(M11 - M22)/sqrt2 = sqrt2 (T_a0, -T_a1, 0).
      dw[i0] = kSqrt2 * t0;
      dw[i1] = -kSqrt2 * t1;
      dw[i2] = 0.0;
      // d(M11 + M22 - 2 M33)/sqrt6 = (2 T_a0, 2 T_a1, -4 T_a2) / sqrt6.
      dw[9 + i0] = 2.0 * kInvSqrt6 * t0;
      dw[9 + i1] = 2.0 * kInvSqrt6 * t1;
      dw[9 + i2] = -4.0 * kInvSqrt6 * t2;
      // d(sqrt2 M12) = sqrt2 (T_a1, T_a0, 0); M13: (T_a2, 0, T_a0); M23: (0, T_a2, T_a1).
      dw[18 + i0] = kSqrt2 * t1;
      dw[18 + i1] = kSqrt2 * t0;
      dw[18 + i2] = 0.0;
      dw[27 + i0] = kSqrt2 * t2;
      dw[27 + i1] = 0.0;
      dw[27 + i2] = kSqrt2 * t0;
      dw[36 + i0] = 0.0;
      dw[36 + i1] = kSqrt2 * t2;
      dw[36 + i2] = kSqrt2 * t1;
    }
    double u[9];  // dr = alpha dw + w u^t
    if (near) {
      double grad[9];
      rho_gradient(T, in, rho_value, grad);
      const double h = 0.5 / alpha;
      for (int m = 0; m < 9; ++m) u[m] = h * grad[m];
    } else {
      // u = (dmu/dT / (2 s) - alpha n^t dw) / |w| = dmu/dT / (2 s |w|) - alpha w^t dw / |w|^2.
      double grad[9];
      mu_gradient(T, in, grad);
      const double s = std::sqrt(p);
      const double iws = 0.5 / (s * std::sqrt(in.w2)), aiw2 = alpha / in.w2;
      for (int m = 0; m < 9; ++m) {
        double wdw = 0.0;
        for (int j = 0; j < 5; ++j) wdw += w[j] * dw[9 * j + m];
        u[m] = iws * grad[m] - aiw2 * wdw;
      }
    }
    for (int j = 0; j < 5; ++j)
      for (int m = 0; m < 9; ++m) dr_dT[9 * j + m] = alpha * dw[9 * j + m] + w[j] * u[m];
    return true;
  }

  // r = c F(S); dr/dT = c dF/dS a (I - vec(T) g^t / 3) with g = T^-t = C / tau. F is homogeneous
  // of degree 3/2, so (dF/dS) vec(S) = (3/2) F and dr/dT = c (a dF/dS - F g^t / 2).
  bool cofactor_residuals(double a, double tau, const double* S, const double* C, double* r,
                          double* dr_dT) const {
    double F[9];
    if (!conformal_residual(S, F, dr_dT)) return false;
    for (int n = 0; n < 9; ++n) {
      r[n] = c_ * F[n];
      if (!std::isfinite(r[n])) return false;
    }
    if (dr_dT != nullptr) {
      const double ca = c_ * a, h = -0.5 * c_ / tau;
      for (int i = 0; i < 9; ++i) {
        double* row = dr_dT + 9 * i;
        const double hf = h * F[i];
        for (int m = 0; m < 9; ++m) row[m] = ca * row[m] + hf * C[m];
      }
    }
    return true;
  }

  Shape3dForm form_;
  double c_;
  Shape3dResidual residual_;
};

class ConformalShapeMetric final : public FixedMetric {
 public:
  ConformalShapeMetric()
      : FixedMetric("shape_3d", "mu_360", 3, MetricClass::kShape, false, 9, false) {}

  double value(const double* T) const override {
    const double f2 = small_matrix::frobenius2<3>(T);
    return f2 * std::sqrt(f2) / (3.0 * kSqrt3) - small_matrix::det<3>(T);
  }

  bool residuals(const double* T, double* r, double* dr_dT) const override {
    return conformal_residual(T, r, dr_dT);
  }
};

}  // namespace

std::unique_ptr<Metric> make_shape_3d_metric(Shape3dForm form, Shape3dResidual residual) {
  switch (form) {
    case Shape3dForm::kNonBarrier:
      return std::make_unique<ConformalShapeMetric>();
    case Shape3dForm::kBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "shape_barrier_3d", "mu_303", 2.0 / 3.0,
                                                  residual);
    case Shape3dForm::kCubicBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "shape_cubic_barrier_3d", "mu_304", 1.0,
                                                  residual);
    case Shape3dForm::kConditionBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "condition_barrier_3d", "mu_301", 2.0 / 3.0,
                                                  residual);
    case Shape3dForm::kConditionSquaredBarrier:
      return std::make_unique<BarrierShapeMetric>(form, "condition_squared_barrier_3d", "mu_302",
                                                  4.0 / 3.0, residual);
  }
  return nullptr;
}

}  // namespace tmop
