// tests/metric/metric_registry_test.cc
// make_metric() / metric_names(): every listed name builds a metric of the right dimension,
// names and aliases resolve to the same metric, unknown names give nullptr.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "tests/metric/metric_test_util.h"
#include "tmop/metric/metric.h"

namespace tmop {
namespace {

using metric_test::canonical_names;

TEST(MetricRegistry, EveryListedNameBuildsAMetricOfThatDimension) {
  for (int d = 2; d <= 3; ++d) {
    for (const std::string& name : metric_names(d)) {
      std::unique_ptr<Metric> m = make_metric(name, d);
      ASSERT_NE(m, nullptr) << name;
      EXPECT_EQ(m->dim(), d) << name;
      EXPECT_GE(m->num_residuals(), 1) << name;
      EXPECT_LE(m->num_residuals(), kMaxMetricResiduals) << name;
      EXPECT_FALSE(std::string(metric_class_name(m->metric_class())).empty());
    }
  }
}

TEST(MetricRegistry, CanonicalNamesAndAliasesAreUniquePerDimension) {
  for (int d = 2; d <= 3; ++d) {
    std::set<std::string> names, aliases;
    for (const std::string& name : canonical_names(d)) {
      EXPECT_TRUE(names.insert(name).second) << name;
      std::unique_ptr<Metric> m = make_metric(name, d);
      if (!m->alias().empty()) {
        EXPECT_TRUE(aliases.insert(m->alias()).second) << m->alias();
        std::unique_ptr<Metric> by_alias = make_metric(m->alias(), d);
        ASSERT_NE(by_alias, nullptr);
        EXPECT_EQ(by_alias->name(), name);
      }
      // The canonical name ends with the dimension.
      EXPECT_EQ(name.substr(name.size() - 3), d == 2 ? "_2d" : "_3d") << name;
      std::unique_ptr<Metric> by_base = make_metric(name.substr(0, name.size() - 3), d);
      ASSERT_NE(by_base, nullptr) << name;
      EXPECT_EQ(by_base->name(), name);
    }
    EXPECT_GE(names.size(), 10u);
  }
}

TEST(MetricRegistry, KnownAliases) {
  const std::pair<const char*, const char*> k2d[] = {{"mu_2", "shape_barrier_2d"},
                                                     {"mu_4", "shape_2d"},
                                                     {"mu_7", "size_shape_barrier_2d"},
                                                     {"mu_14", "size_shape_orientation_2d"},
                                                     {"mu_55", "size_2d"},
                                                     {"mu_56", "size_barrier_2d"},
                                                     {"mu_77", "size_barrier_quadratic_2d"}};
  for (const auto& [alias, name] : k2d) {
    std::unique_ptr<Metric> m = make_metric(alias, 2);
    ASSERT_NE(m, nullptr) << alias;
    EXPECT_EQ(m->name(), name);
  }
  const std::pair<const char*, const char*> k3d[] = {{"mu_301", "condition_barrier_3d"},
                                                     {"mu_302", "condition_squared_barrier_3d"},
                                                     {"mu_303", "shape_barrier_3d"},
                                                     {"mu_304", "shape_cubic_barrier_3d"},
                                                     {"mu_315", "size_3d"},
                                                     {"mu_316", "size_barrier_3d"},
                                                     {"mu_318", "size_barrier_quadratic_3d"},
                                                     {"mu_321", "size_shape_barrier_3d"},
                                                     {"mu_360", "shape_3d"}};
  for (const auto& [alias, name] : k3d) {
    std::unique_ptr<Metric> m = make_metric(alias, 3);
    ASSERT_NE(m, nullptr) << alias;
    EXPECT_EQ(m->name(), name);
  }
}

TEST(MetricRegistry, UnknownNamesAndDimensionsGiveNull) {
  EXPECT_EQ(make_metric("no_such_metric", 2), nullptr);
  EXPECT_EQ(make_metric("shape_3d", 2), nullptr);
  EXPECT_EQ(make_metric("mu_303", 2), nullptr);
  EXPECT_EQ(make_metric("size", 4), nullptr);
  EXPECT_TRUE(metric_names(1).empty());
}

// "W1*NAME1+W2*NAME2": a weighted sum of two registry metrics, value and residuals consistent,
// barrier when either part is; malformed texts give null.
TEST(MetricRegistry, WeightedCombinationsOfTwo) {
  std::unique_ptr<Metric> m = make_metric("0.7*shape_barrier+0.3*size_barrier", 3);
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->name(), "0.7*shape_barrier_3d+0.3*size_barrier_3d");
  EXPECT_EQ(m->alias(), "0.7*mu_303+0.3*mu_316");
  EXPECT_TRUE(m->barrier());
  EXPECT_EQ(m->metric_class(), MetricClass::kShapeSize);
  const std::unique_ptr<Metric> a = make_metric("shape_barrier", 3), b = make_metric("mu_316", 3);
  const double T[9] = {1.2, 0.1, -0.2, 0.05, 0.9, 0.1, 0.0, -0.15, 1.1};
  EXPECT_NEAR(m->value(T), 0.7 * a->value(T) + 0.3 * b->value(T), 1e-14);
  std::vector<double> r(m->num_residuals());
  ASSERT_TRUE(m->residuals(T, r.data(), nullptr));
  double rr = 0;
  for (double x : r) rr += x * x;
  EXPECT_NEAR(rr, m->value(T) - m->min_value(), 1e-12);
  // Default weight 1, aliases, an exponent's '+', a non-barrier sum.
  std::unique_ptr<Metric> n = make_metric("shape+1e+0*mu_14", 2);
  ASSERT_NE(n, nullptr);
  EXPECT_EQ(n->name(), "1*shape_2d+1*size_shape_orientation_2d");
  EXPECT_FALSE(n->barrier());
  for (const char* bad :
       {"0.5*shape_barrier", "shape+size+size_shape", "-1*shape+size", "x*shape+size", "shape+",
        "+shape", "0*shape+0*size", "shape_3d+size", "nan*shape+size", "shape**size+size"})
    EXPECT_EQ(make_metric(bad, 2), nullptr) << bad;
  EXPECT_EQ(make_metric("untangle+untangle", 3), nullptr);  // more than kMaxMetricResiduals
}

TEST(MetricRegistry, DimensionFreeNamesPickTheDimension) {
  EXPECT_EQ(make_metric("shape_barrier", 2)->name(), "shape_barrier_2d");
  EXPECT_EQ(make_metric("shape_barrier", 3)->name(), "shape_barrier_3d");
  EXPECT_EQ(make_metric("untangle", 3)->name(), "untangle_3d");
  EXPECT_EQ(make_metric("size_shape_barrier", 3)->alias(), "mu_321");
}

}  // namespace
}  // namespace tmop
