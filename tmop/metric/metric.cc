// tmop/metric/metric.cc
// The metric registry: make_metric() and metric_names() over every concrete metric, by
// descriptive name ("shape_barrier_3d"), dimension-free name ("shape_barrier", resolved with the
// dimension argument) or literature alias ("mu_303"), and weighted combinations of two of them
// ("0.7*shape_barrier+0.3*size_barrier").
#include "tmop/metric/metric.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>

#include "tmop/metric/shape_2d.h"
#include "tmop/metric/shape_3d.h"
#include "tmop/metric/size.h"
#include "tmop/metric/size_shape.h"
#include "tmop/metric/size_shape_orientation.h"
#include "tmop/metric/untangle.h"
#include "tmop/metric/weighted_sum.h"

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

namespace {

// "W*NAME": the weight (default 1) and the name of one term of a weighted combination.
bool parse_term(const std::string& text, double* weight, std::string* name) {
  *weight = 1;
  *name = text;
  const std::size_t star = text.find('*');
  if (star == std::string::npos) return !text.empty();
  const std::string w = text.substr(0, star);
  char* end = nullptr;
  errno = 0;
  *weight = std::strtod(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size() || errno != 0 || !std::isfinite(*weight) ||
      *weight < 0)
    return false;
  *name = text.substr(star + 1);
  return !name->empty() && name->find('*') == std::string::npos;
}

// "W1*NAME1+W2*NAME2" (weights >= 0, default 1): a WeightedSumMetric of two registry metrics.
// A '+' right after an exponent's 'e' belongs to the number (1e+3).
std::unique_ptr<Metric> make_weighted_sum(const std::string& text, int dim) {
  std::size_t plus = std::string::npos;
  for (std::size_t i = 1; i < text.size(); ++i)
    if (text[i] == '+' &&
        !((text[i - 1] == 'e' || text[i - 1] == 'E') && i >= 2 &&
          (std::isdigit(static_cast<unsigned char>(text[i - 2])) || text[i - 2] == '.'))) {
      if (plus != std::string::npos) return nullptr;  // two terms only
      plus = i;
    }
  if (plus == std::string::npos) return nullptr;
  double wa = 0, wb = 0;
  std::string a, b;
  if (!parse_term(text.substr(0, plus), &wa, &a) || !parse_term(text.substr(plus + 1), &wb, &b))
    return nullptr;
  std::shared_ptr<const Metric> ma(make_metric(a, dim).release());
  std::shared_ptr<const Metric> mb(make_metric(b, dim).release());
  if (!ma || !mb || ma->num_residuals() + mb->num_residuals() > kMaxMetricResiduals ||
      !(wa + wb > 0))
    return nullptr;
  return std::make_unique<WeightedSumMetric>(ma, wa, mb, wb);
}

}  // namespace

std::unique_ptr<Metric> make_metric(const std::string& name, int dim) {
  if (name.find_first_of("*+") != std::string::npos) return make_weighted_sum(name, dim);
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
