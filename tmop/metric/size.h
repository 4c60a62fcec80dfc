// tmop/metric/size.h
// Size metrics: functions of tau = det T only, minimal (zero) exactly on det T = 1, invariant to
// any volume-preserving change of T. One residual r(tau) with |r|^2 = mu exactly, and
// dr/dT = r'(tau) cof(T) since d tau / dT = cof(T) = tau T^-T.
//
//   form             mu(tau)                       r(tau)                  barrier  aliases
//   kQuadratic       (tau - 1)^2                   tau - 1                 no       mu_55, mu_315
//   kBarrier         (tau + 1/tau)/2 - 1           (tau - 1)/sqrt(2 tau)   yes      mu_56, mu_316
//                    = (tau - 1)^2 / (2 tau)
//   kBarrierQuadratic (tau - 1/tau)^2 / 2          (tau - 1/tau)/sqrt(2)   yes      mu_77, mu_318
//
// The barrier forms are symmetric under tau -> 1/tau (growing and shrinking cost the same) and
// tend to +infinity as tau -> 0+; kBarrierQuadratic grows faster on both sides.
#ifndef TMOP_METRIC_SIZE_H_
#define TMOP_METRIC_SIZE_H_

#include <memory>

#include "tmop/metric/metric.h"

namespace tmop {

enum class SizeForm { kQuadratic, kBarrier, kBarrierQuadratic };

// Names: size_{2d,3d}, size_barrier_{2d,3d}, size_barrier_quadratic_{2d,3d}. dim is 2 or 3.
std::unique_ptr<Metric> make_size_metric(SizeForm form, int dim);

}  // namespace tmop

#endif  // TMOP_METRIC_SIZE_H_
