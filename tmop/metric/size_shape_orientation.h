// tmop/metric/size_shape_orientation.h
// Size+shape+orientation metrics: zero exactly at T = I (the element equals its target,
// orientation included). No invariance.
//
//   size_shape_orientation_{2d,3d}          mu_14 (2D)   |T - I|^2
//       r = vec(T - I), dr/dT = identity; exact, not a barrier.
//   size_shape_orientation_barrier_{2d,3d}  (no alias)   |T - I|^2 / (2 tau)
//       r = vec(T - I) / sqrt(2 tau), exact, barrier (+infinity as tau -> 0+, unless T = I).
//       dr/dT = s I - r / (2 tau) cof(T)^t with s = (2 tau)^(-1/2). This is half of MFEM's
//       mu_98 = |T - I|^2 / tau; the factor 1/2 matches the normalisation of mu_2.
#ifndef TMOP_METRIC_SIZE_SHAPE_ORIENTATION_H_
#define TMOP_METRIC_SIZE_SHAPE_ORIENTATION_H_

#include <memory>

#include "tmop/metric/metric.h"

namespace tmop {

// dim is 2 or 3; nullptr otherwise.
std::unique_ptr<Metric> make_size_shape_orientation_metric(bool barrier, int dim);

}  // namespace tmop

#endif  // TMOP_METRIC_SIZE_SHAPE_ORIENTATION_H_
