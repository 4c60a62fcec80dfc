// tmop_micro_bench: throughput of the per-sample-point kernels (docs/benchmarks.md).
//
//   metric/<d>d/<name>           Metric::residuals with dr/dT, for every name in metric_names(d)
//   metric_value_only/<d>d/<name> Metric::residuals without dr/dT (Ceres's residual-only path)
//   cost/<type>                  SamplePointCost::Evaluate (residuals + every Jacobian block) at
//                                the type's default sample points, default shape metric
//   shape_gradients/<type>       shape_gradients at the type's default sample points
//
// items_per_second counts sample points (one T each). Inputs are fixed pseudo-random matrices /
// node positions near the ideal element (det > 0, so barrier metrics are defined), cycled through
// a batch of 1024 so that the branch predictor cannot learn one input.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "tmop/element/ideal_element.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/metric/metric.h"
#include "tmop/optimize/sample_point_cost.h"
#include "tmop/recipes/improve_shape.h"

namespace {

constexpr int kBatch = 1024;

// Deterministic values in [-1, 1) (splitmix64).
struct Rng {
  std::uint64_t s = 12345;
  double uniform() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (z >> 11) * (2.0 / 9007199254740992.0) - 1;
  }
};

double det(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

// kBatch matrices I + 0.3 * noise with det T >= 0.2.
std::vector<double> make_T_batch(int d) {
  Rng rng;
  std::vector<double> Ts;
  while (static_cast<int>(Ts.size()) < kBatch * d * d) {
    double T[9];
    for (int k = 0; k < d * d; ++k) T[k] = (k % (d + 1) == 0 ? 1.0 : 0.0) + 0.3 * rng.uniform();
    if (det(T, d) < 0.2) continue;
    Ts.insert(Ts.end(), T, T + d * d);
  }
  return Ts;
}

void BM_metric(benchmark::State& state, std::shared_ptr<tmop::Metric> metric, bool derivatives) {
  const int d = metric->dim();
  const std::vector<double> Ts = make_T_batch(d);
  double r[tmop::kMaxMetricResiduals], dr[tmop::kMaxMetricResiduals * 9];
  int k = 0;
  for (auto _ : state) {
    const bool ok = metric->residuals(Ts.data() + k * d * d, r, derivatives ? dr : nullptr);
    benchmark::DoNotOptimize(ok);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(dr);
    benchmark::ClobberMemory();
    k = (k + 1) & (kBatch - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// The element's nodes: the ideal element (W applied to the reference nodes) plus noise of 5 % of
// its size; a batch of such elements, and G_i = W^-T grad N_i at each default sample point.
struct ElementFixture {
  tmop::CellType type;
  int n = 0, d = 0, points = 0;
  std::vector<double> coords;  // kBatch * n * d
  std::vector<double> G;       // points * n * d
  std::vector<double> weights;

  explicit ElementFixture(tmop::CellType t) : type(t) {
    n = tmop::cell_num_nodes(t);
    d = tmop::cell_dim(t);
    double W[9], Winv[9];
    tmop::ideal_jacobian(t, W);
    const double w = det(W, d);
    if (d == 2) {
      Winv[0] = W[3] / w, Winv[1] = -W[1] / w, Winv[2] = -W[2] / w, Winv[3] = W[0] / w;
    } else {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
          Winv[i * 3 + j] = (W[i1 * 3 + j1] * W[i2 * 3 + j2] - W[i1 * 3 + j2] * W[i2 * 3 + j1]) / w;
        }
    }
    // Reference node r maps to W (r - r_0); the reference scale differs per type, so the noise
    // is relative to the first edge.
    Rng rng;
    std::vector<double> ideal(n * d);
    for (int i = 0; i < n; ++i)
      for (int a = 0; a < d; ++a) {
        double v = 0;
        for (int b = 0; b < d; ++b) v += W[a * d + b] * tmop::reference_node(t, i)[b];
        ideal[i * d + a] = v;
      }
    double h = 0;
    for (int a = 0; a < d; ++a) h += std::pow(ideal[d + a] - ideal[a], 2);
    h = std::sqrt(h);
    for (int e = 0; e < kBatch; ++e)
      for (int k = 0; k < n * d; ++k) coords.push_back(ideal[k] + 0.05 * h * rng.uniform());
    double grad[tmop::kMaxCellNodes * 3];
    for (const tmop::SamplePoint& sp : tmop::sample_points(t, tmop::SampleRule::kDefault)) {
      tmop::shape_gradients(t, sp.xi, grad);
      for (int i = 0; i < n; ++i)
        for (int b = 0; b < d; ++b) {
          double v = 0;
          for (int c = 0; c < d; ++c) v += Winv[c * d + b] * grad[i * d + c];
          G.push_back(v);
        }
      weights.push_back(std::sqrt(sp.weight));
      ++points;
    }
  }
};

void BM_cost(benchmark::State& state, tmop::CellType type) {
  ElementFixture f(type);
  std::string error;
  const auto metric = tmop::recipe_metric("", f.d, 1.0, &error);
  std::deque<tmop::SamplePointCost> costs;
  for (int p = 0; p < f.points; ++p) {
    tmop::SamplePointTerm term;
    term.metric = metric.get();
    term.G = f.G.data() + p * f.n * f.d;
    term.sqrt_weight = f.weights[p];
    costs.emplace_back(f.n, f.d, 1, &term);
  }
  const int m = metric->num_residuals();
  std::vector<double> residuals(m), jac(f.n * m * f.d);
  std::vector<double*> jacobians(f.n);
  for (int i = 0; i < f.n; ++i) jacobians[i] = jac.data() + i * m * f.d;
  std::vector<const double*> x(f.n);
  int e = 0, p = 0;
  bool all_ok = true;
  for (auto _ : state) {
    for (int i = 0; i < f.n; ++i) x[i] = f.coords.data() + (e * f.n + i) * f.d;
    all_ok &= costs[p].Evaluate(x.data(), residuals.data(), jacobians.data());
    benchmark::DoNotOptimize(residuals.data());
    benchmark::DoNotOptimize(jac.data());
    benchmark::ClobberMemory();
    if (++p == f.points) {
      p = 0;
      e = (e + 1) & (kBatch - 1);
    }
  }
  if (!all_ok) state.SkipWithError("Evaluate returned false");
  state.SetItemsProcessed(state.iterations());
  state.counters["residuals"] = m;
  state.counters["points_per_element"] = f.points;
}

void BM_shape_gradients(benchmark::State& state, tmop::CellType type) {
  const auto& points = tmop::sample_points(type, tmop::SampleRule::kDefault);
  double grad[tmop::kMaxCellNodes * 3];
  std::size_t p = 0;
  for (auto _ : state) {
    tmop::shape_gradients(type, points[p].xi, grad);
    benchmark::DoNotOptimize(grad);
    benchmark::ClobberMemory();
    if (++p == points.size()) p = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  for (int d = 2; d <= 3; ++d)
    for (const std::string& name : tmop::metric_names(d)) {
      std::shared_ptr<tmop::Metric> metric(tmop::make_metric(name, d).release());
      if (!metric) continue;
      const std::string suffix = std::to_string(d) + "d/" + name;
      benchmark::RegisterBenchmark(("metric/" + suffix).c_str(), BM_metric, metric, true);
      benchmark::RegisterBenchmark(("metric_value_only/" + suffix).c_str(), BM_metric, metric,
                                   false);
    }
  using tmop::CellType;
  for (CellType t : {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8,
                     CellType::kTet10, CellType::kWedge6, CellType::kTri6, CellType::kHex27}) {
    const std::string name = tmop::cell_name(t);
    benchmark::RegisterBenchmark(("cost/" + name).c_str(), BM_cost, t);
    benchmark::RegisterBenchmark(("shape_gradients/" + name).c_str(), BM_shape_gradients, t);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
