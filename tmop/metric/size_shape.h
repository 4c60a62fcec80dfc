// tmop/metric/size_shape.h
// Size+shape metrics: invariant to rotations of T (left and right), zero exactly on T = R.
//
//   size_shape_barrier_{2d,3d}  mu_7 / mu_321   |T - T^-t|^2
//       r = vec(T - T^-t), exact. With T = U S V^t, |T - T^-t|^2 = sum_i (s_i - 1/s_i)^2, zero
//       iff every singular value is 1 and infinite as tau -> 0+. dr/dT: d(T^-t) = -T^-t dT^t T^-t,
//       so d r_ij / d T_kl = delta_ik delta_jl + (T^-1)_jk (T^-1)_li.
//   size_shape_{2d,3d}  (no alias)  |T^t T - I|^2 + (tau - 1)^2
//       r = [C_ii - 1 (i = 1..d), sqrt2 C_ij (i < j), tau - 1] with C = T^t T, exact (C is
//       symmetric, so the off-diagonal pair is counted once with weight 2). Not a barrier; zero
//       iff T^t T = I and det T = 1, i.e. T is a proper rotation (the (tau - 1)^2 term excludes
//       reflections). dC_ij/dT_kl = delta_lj T_ki + delta_li T_kj; d tau / dT = cof(T).
#ifndef TMOP_METRIC_SIZE_SHAPE_H_
#define TMOP_METRIC_SIZE_SHAPE_H_

#include <memory>

#include "tmop/metric/metric.h"

namespace tmop {

// dim is 2 or 3; nullptr otherwise.
std::unique_ptr<Metric> make_size_shape_metric(bool barrier, int dim);

}  // namespace tmop

#endif  // TMOP_METRIC_SIZE_SHAPE_H_
