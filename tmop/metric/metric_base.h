// tmop/metric/metric_base.h
// FixedMetric: the bookkeeping every concrete metric shares (name, alias, dimension, class,
// barrier flag, residual count), fixed at construction. Concrete metrics derive from it and
// implement value() and residuals() only.
#ifndef TMOP_METRIC_METRIC_BASE_H_
#define TMOP_METRIC_METRIC_BASE_H_

#include <string>
#include <utility>

#include "tmop/metric/metric.h"

namespace tmop {

class FixedMetric : public Metric {
 public:
  // exact: whether |r|^2 == value() - min_value() identically (see Metric::exact_residuals()).
  FixedMetric(std::string name, std::string alias, int dim, MetricClass metric_class, bool barrier,
              int num_residuals, bool exact = true)
      : name_(std::move(name)),
        alias_(std::move(alias)),
        dim_(dim),
        class_(metric_class),
        barrier_(barrier),
        num_residuals_(num_residuals),
        exact_residuals_(exact) {}

  std::string name() const final { return name_; }
  std::string alias() const final { return alias_; }
  int dim() const final { return dim_; }
  MetricClass metric_class() const final { return class_; }
  bool barrier() const final { return barrier_; }
  int num_residuals() const final { return num_residuals_; }
  bool exact_residuals() const final { return exact_residuals_; }

 private:
  std::string name_;
  std::string alias_;
  int dim_;
  MetricClass class_;
  bool barrier_;
  int num_residuals_;
  bool exact_residuals_;
};

}  // namespace tmop

#endif  // TMOP_METRIC_METRIC_BASE_H_
