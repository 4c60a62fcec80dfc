// tmop/metric/metric.cc
// The metric registry: make_metric() and metric_names() over every concrete metric, by
// descriptive name ("shape_barrier_3d"), dimension-free name ("shape_barrier", resolved with the
// dimension argument) or literature alias ("mu_303").
#include "tmop/metric/metric.h"

#include <functional>

#include "tmop/metric/shape_2d.h"
#include "tmop/metric/shape_3d.h"
#include "tmop/metric/size.h"
#include "tmop/metric/size_shape.h"
#include "tmop/metric/size_shape_orientation.h"
#include "tmop/metric/untangle.h"

namespace tmop {

const char* metric_class_name(MetricClass c) {
  switch (c) {
    case MetricClass::kShape:
      return "shape";
    case MetricClass::kSize:
      return "size";
    case MetricClass::kShapeSize:
      return "shape+size";
    case MetricClass::kShapeSizeOrientation:
      return "shape+size+orientation";
    case MetricClass::kUntangle:
      return "untangle";
  }
  return "unknown";
}

namespace {

struct Entry {
  const char* base;  // dimension-free name; the canonical name is base + "_2d" / "_3d"
  int dim;
  std::function<std::unique_ptr<Metric>()> make;
};

const std::vector<Entry>& registry() {
  static const std::vector<Entry>* entries = [] {
    auto* e = new std::vector<Entry>;
    for (int d = 2; d <= 3; ++d) {
      if (d == 2) {
        e->push_back({"shape", 2, [] { return make_shape_2d_metric(false); }});
        e->push_back({"shape_barrier", 2, [] { return make_shape_2d_metric(true); }});
      } else {
        e->push_back({"shape", 3, [] { return make_shape_3d_metric(Shape3dForm::kNonBarrier); }});
        e->push_back(
            {"shape_barrier", 3, [] { return make_shape_3d_metric(Shape3dForm::kBarrier); }});
        e->push_back({"shape_cubic_barrier", 3,
                      [] { return make_shape_3d_metric(Shape3dForm::kCubicBarrier); }});
        e->push_back({"condition_barrier", 3,
                      [] { return make_shape_3d_metric(Shape3dForm::kConditionBarrier); }});
        e->push_back({"condition_squared_barrier", 3,
                      [] { return make_shape_3d_metric(Shape3dForm::kConditionSquaredBarrier); }});
      }
      e->push_back({"size", d, [d] { return make_size_metric(SizeForm::kQuadratic, d); }});
      e->push_back({"size_barrier", d, [d] { return make_size_metric(SizeForm::kBarrier, d); }});
      e->push_back({"size_barrier_quadratic", d,
                    [d] { return make_size_metric(SizeForm::kBarrierQuadratic, d); }});
      e->push_back({"size_shape", d, [d] { return make_size_shape_metric(false, d); }});
      e->push_back({"size_shape_barrier", d, [d] { return make_size_shape_metric(true, d); }});
      e->push_back({"size_shape_orientation", d,
                    [d] { return make_size_shape_orientation_metric(false, d); }});
      e->push_back({"size_shape_orientation_barrier", d,
                    [d] { return make_size_shape_orientation_metric(true, d); }});
      e->push_back({"untangle", d, [d] { return std::make_unique<UntangleMetric>(d); }});
    }
    return e;
  }();
  return *entries;
}

}  // namespace

std::unique_ptr<Metric> make_metric(const std::string& name, int dim) {
  for (const Entry& entry : registry()) {
    if (entry.dim != dim) continue;
    const std::string base = entry.base;
    if (name == base || name == base + (dim == 2 ? "_2d" : "_3d")) return entry.make();
  }
  // Aliases: build each metric of this dimension once and compare (rare path).
  if (name.rfind("mu_", 0) == 0) {
    for (const Entry& entry : registry()) {
      if (entry.dim != dim) continue;
      std::unique_ptr<Metric> m = entry.make();
      if (m->alias() == name) return m;
    }
  }
  return nullptr;
}

std::vector<std::string> metric_names(int dim) {
  std::vector<std::string> names;
  for (const Entry& entry : registry()) {
    if (entry.dim != dim) continue;
    std::unique_ptr<Metric> m = entry.make();
    names.push_back(m->name());
    names.push_back(entry.base);
    if (!m->alias().empty()) names.push_back(m->alias());
  }
  return names;
}

}  // namespace tmop
