// tmop/metric/shape_3d.h
// 3D shape metrics: invariant to rotations (left and right) and scaling of T, minimal exactly on
// T = s R (s > 0, R a rotation). value() reports the published formula; the residuals are an
// exact non-polynomial least-squares form (3D shape metrics have no polynomial sum of squares).
//
// Barrier metrics (tau = det T > 0 required), in terms of S = T tau^(-1/3) (det S = 1):
//   shape_barrier_3d              mu_303  |T|^2 / (3 tau^(2/3)) - 1         c^2 = 2/3
//   shape_cubic_barrier_3d        mu_304  |T|^3 / (3 sqrt(3) tau) - 1       c^2 = 1
//   condition_barrier_3d          mu_301  |T| |T^-1| / 3 - 1                c^2 = 2/3
//   condition_squared_barrier_3d  mu_302  |T|^2 |T^-1|^2 / 9 - 1            c^2 = 4/3
// (mu_304 is the mean-ratio-like "sliver" metric: (mean ratio)^(-3/2) - 1 for a tet.)
//
// Deviatoric residual form (Shape3dResidual::kDeviatoric, the default): 5 residuals, exact.
//   r = sqrt(mu) w / |w|,  w = the coordinates of D = dev(T^t T) = T^t T - (|T|^2 / 3) I in an
//   orthonormal basis of the 5-dimensional space of traceless symmetric matrices.
//   * Exact: |r|^2 = mu for every T with tau > 0, so Ceres minimises the published objective and
//     J^t r is its exact gradient (dmu/dT / 2); exact_residuals() is true.
//   * Same minimisers and invariances: w = 0 iff T^t T = s^2 I iff T = s R (tau > 0), where every
//     mu above vanishes; rotating T on the left leaves w unchanged, on the right rotates w
//     (an orthogonal map of the 5-space), and scaling T does not change w / |w|.
//   * Gauss-Newton model: near the minimiser mu = kappa |w|^2 / (tau^(2/3) |T|^2) + O(|w|^3),
//     kappa = 3 c^2 / 4, so J^t J equals half the Hessian of mu there. 5 is the rank of that
//     Hessian (9 entries of T minus 3 rotations and 1 scaling), the fewest residuals with an
//     exact local model; the polar form below needs 9 (the Jacobian of a tet is 5 x 12 instead
//     of 9 x 12: less memory and fewer flops in every CGNR product).
//   * mu is computed without cancellation near the minimiser: with m = |T|^2 / 3,
//     |T|^6 - 27 tau^2 = 27 (m |D|^2 / 2 - det D) and |T|^2 |cof T|^2 - 9 tau^2 =
//     |T|^2 |D|^2 - 9 det D, both evaluated from D itself (shape_3d.cc). For |T|^2 / (3 tau^(2/3))
//     - 1 and |T|^3 / (3 sqrt3 tau) - 1, rho = mu / |w|^2 has the numerator |T|^2 / 6 - det D /
//     |D|^2 >= |T|^2 / 18 (because D + m I = T^t T >= 0), which never cancels: their residuals use
//     one straight-line kernel for every T. The two condition-number forms switch to the
//     published mu far from the minimiser, where |T|^2 - 9 det D / |D|^2 would cancel on needles.
//   * dr/dT = (s / |w|) (I - n n^t) dw/dT + n (dmu/dT)^t / (2 s), s = sqrt(mu), n = w / |w|; at an
//     ideal T (w = 0) r = 0 and dr/dT is the limit sqrt(kappa) dw/dT / (tau^(1/3) |T|).
//
// Polar residual form: r = c vec(S - R), R the rotation of the polar decomposition S = R P.
//   * Same minimisers: |S - R|^2 = |P - I|^2 = sum_i (l_i - 1)^2 over the eigenvalues l_i of P,
//     zero iff P = I iff T = s R; each mu above is zero iff all l_i are equal (AM-GM / Cauchy-
//     Schwarz), i.e. on the same set.
//   * Same invariances: scaling T changes neither S nor R; rotating T rotates S - R.
//   * Second-order agreement: with l_i = 1 + d_i and prod l_i = 1, sum d_i = |d|^2/2 + O(d^3),
//     so |S|^2 = |S^-1|^2 = 3 + 2|d|^2 + O(d^3); hence mu_303 ~ mu_301 ~ (2/3)|d|^2,
//     mu_304 ~ |d|^2, mu_302 ~ (4/3)|d|^2 and c^2 |S - R|^2 matches mu to second order at the
//     minimiser (same Hessian, so the same local Gauss-Newton model).
//   * Jacobian: dr/dT = c (I - L) dS/dT with dS/dT = tau^(-1/3) (I - vec(T) vec(T^-t)^t / 3)
//     and L = dR/dS the exact derivative of the polar rotation (small_matrix.h), so J is the
//     exact Jacobian of r and J^t J is the exact Gauss-Newton model (at the minimiser it equals
//     the Hessian of |r|^2 / 2: no stiffness against rotating an element, which is free).
//     Because R minimises |S - Q|^2 over rotations Q, R^t (S - R) = P - I is symmetric while
//     dR = R W with W skew, so (c dR)^t r = 0: J^t r equals the gradient of |r|^2 / 2 computed
//     with R held fixed, c^2 (dS/dT)^t vec(S - R).
//   * Shape3dResidual::kPolarRotationFixed gives the cheaper rotation-fixed Jacobian c dS/dT
//     instead: the same gradient J^t r, but J^t J adds stiffness c^2 tau^(-2/3) |W T|^2 along
//     the rotations dT = W T of the element.
//   R comes from a scaled Newton polar iteration (small_matrix.h), no SVD.
//
// Cofactor residual form of the barrier metrics (Shape3dResidual::kCofactor): the mu_360 form
// below applied to S, r = c vec(cof S - n S) / (2 sqrt(n)), n = |S| / sqrt(3). Since det S = 1,
// mu_360(S) = mu_304(T), so |r|^2 agrees with mu_304 to second order for c = 1 (and with the
// others for the same c as the polar form); zero exactly on T = s R; barrier (|r|^2 grows like
// tau^(-1) as tau -> 0+, like mu_304); scale and rotation invariant. No iteration, exact
// Jacobian: about 1.6x the throughput of kPolar. Its growth with stretching (cubic in the largest
// singular value of S) follows mu_304 closely and is steeper than mu_303.
//
// Non-barrier metric, defined for every T (inverted ones included):
//   shape_3d  mu_360  |T|^3 / (3 sqrt(3)) - tau  ( = tau mu_304 for tau > 0 ),
//   zero iff T = s R with s >= 0 (AM-GM on the singular values; a reflection gives tau < 0).
//   Residual (cofactor form, exact Jacobian, no polar factor):
//     r = vec(cof T - n T) / (2 sqrt(n)),  n = |T| / sqrt(3),  cof T = tau T^-t.
//   cof T = n T implies T^t T = (tau / n) I, so r = 0 exactly on {s R, s >= 0}, like mu_360.
//   With T = s(I + E): cof T - n T = -2 s^2 dev(sym E) + O(E^2), so |r|^2 = s^3 |dev sym E|^2
//   = mu_360 + O(E^3): second-order agreement on the whole minimiser set; both are homogeneous
//   of degree 3 in T. r and dr/dT are set to 0 at T = 0 (a minimiser, where r is continuous).
#ifndef TMOP_METRIC_SHAPE_3D_H_
#define TMOP_METRIC_SHAPE_3D_H_

#include <memory>

#include "tmop/metric/metric.h"

namespace tmop {

enum class Shape3dForm {
  kNonBarrier,               // shape_3d, mu_360
  kBarrier,                  // shape_barrier_3d, mu_303
  kCubicBarrier,             // shape_cubic_barrier_3d, mu_304
  kConditionBarrier,         // condition_barrier_3d, mu_301
  kConditionSquaredBarrier,  // condition_squared_barrier_3d, mu_302
};

// Residual form of the barrier metrics (ignored by kNonBarrier, which always uses its cofactor
// form). The registry (make_metric) uses kPolar.
enum class Shape3dResidual {
  kPolar,               // c vec(S - R), exact Jacobian including dR/dS
  kPolarRotationFixed,  // c vec(S - R), Jacobian with R held fixed (cheaper, same J^t r)
  kCofactor,            // c vec(cof S - n S) / (2 sqrt n), n = |S| / sqrt3: no polar iteration
  kDeviatoric,          // 5 residuals: c (sqrt3 / 2) dev(T^t T) / (tau^(1/3) |T|), the default
};

std::unique_ptr<Metric> make_shape_3d_metric(
    Shape3dForm form, Shape3dResidual residual = Shape3dResidual::kDeviatoric);

}  // namespace tmop

#endif  // TMOP_METRIC_SHAPE_3D_H_
