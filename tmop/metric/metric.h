// tmop/metric/metric.h
// A local metric mu(T) >= 0 of the dimensionless matrix T = A W^-1 (d x d, d = 2 or 3), in the
// least-squares form Ceres needs: residuals r(T) with |r|^2 = mu(T) - mu_min, or a documented
// equivalent with the same minimisers and invariances (DESIGN.md section 6). T and the
// derivatives are row-major: T[3*i + j] is T_ij in 3D, T[2*i + j] in 2D.
//
// Metrics are immutable after construction and safe to share between threads.
#ifndef TMOP_METRIC_METRIC_H_
#define TMOP_METRIC_METRIC_H_

#include <memory>
#include <string>
#include <vector>

namespace tmop {

enum class MetricClass {
  kShape,                 // invariant to rotation and scaling of T: minimal on T = s R
  kSize,                  // depends on det T only: minimal on det T = 1
  kShapeSize,             // invariant to rotation: minimal on T = R
  kShapeSizeOrientation,  // minimal on T = I only
  kUntangle,              // regularised energies, finite for det T <= 0
};
const char* metric_class_name(MetricClass c);

constexpr int kMaxMetricResiduals = 12;

class Metric {
 public:
  virtual ~Metric() = default;

  // Descriptive name ("shape_barrier_3d") and literature alias ("mu_303"), stable in reports.
  virtual std::string name() const = 0;
  virtual std::string alias() const = 0;
  virtual int dim() const = 0;  // 2 or 3
  virtual MetricClass metric_class() const = 0;
  // Barrier metrics are infinite for det T <= 0; residuals() then returns false.
  virtual bool barrier() const = 0;
  // Residual count m (<= kMaxMetricResiduals).
  virtual int num_residuals() const = 0;

  // mu(T) exactly as published (for reports); +infinity where a barrier metric is undefined.
  virtual double value(const double* T) const = 0;
  // The minimum of value() (on the invariance set); |r|^2 = value - min_value for exact forms.
  virtual double min_value() const { return 0.0; }
  // True when |r|^2 == value() - min_value() holds identically (an exact sum of squares); false
  // for the documented equivalent forms (same minimisers and invariances, second-order agreement
  // at the minimum), e.g. the polar form of the 3D shape metrics.
  virtual bool exact_residuals() const { return true; }

  // r (m values) and, when dr_dT is not null, dr/dT as an m x (d*d) row-major matrix whose
  // column d*i + j is the derivative by T_ij. Returns false (outputs unspecified) when the metric
  // is undefined at T: barrier metrics for det T <= 0, any metric for non-finite T.
  virtual bool residuals(const double* T, double* r, double* dr_dT) const = 0;
};

// Builds a metric by name or alias for dimension d; nullptr when unknown (see metric_names()).
// A weighted combination of two metrics is written "W1*NAME1+W2*NAME2" (weights >= 0, not both
// 0, default 1; e.g. "0.7*shape_barrier+0.3*size_barrier", MFEM's mu_80 form): a
// WeightedSumMetric (weighted_sum.h), barrier when either part is; its name() is the same text
// with the canonical names.
std::unique_ptr<Metric> make_metric(const std::string& name, int dim);
// Every name make_metric() accepts for dimension d.
std::vector<std::string> metric_names(int dim);

}  // namespace tmop

#endif  // TMOP_METRIC_METRIC_H_
