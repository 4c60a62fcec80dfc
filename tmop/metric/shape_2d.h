// tmop/metric/shape_2d.h
// 2D shape metrics: invariant to rotations and scaling of T, zero exactly on T = s R (s > 0,
// R a rotation). With t = T (row-major t11 t12 t21 t22) and tau = det T,
//   |T|^2 - 2 tau = (t11 - t22)^2 + (t12 + t21)^2
// (expand: t11^2 + t22^2 + t12^2 + t21^2 - 2 t11 t22 + 2 t12 t21), a sum of squares of the two
// Cauchy-Riemann defects q = [t11 - t22, t12 + t21], which vanish exactly on conformal maps.
//
//   shape_2d          mu_4  |T|^2 - 2 tau          r = q                 exact, not a barrier
//   shape_barrier_2d  mu_2  |T|^2 / (2 tau) - 1    r = q / sqrt(2 tau)   exact, barrier
//
// Both are exact: |r|^2 = mu. shape_2d is minimal on s R with s >= 0 and positive for inverted
// T (|T|^2 >= 2|tau|), so it also works on tangled meshes; it is not scale invariant in value
// (degree 2) but its minimiser set is.
#ifndef TMOP_METRIC_SHAPE_2D_H_
#define TMOP_METRIC_SHAPE_2D_H_

#include <memory>

#include "tmop/metric/metric.h"

namespace tmop {

std::unique_ptr<Metric> make_shape_2d_metric(bool barrier);

}  // namespace tmop

#endif  // TMOP_METRIC_SHAPE_2D_H_
