#include "tmop/quality/guarantees.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <tuple>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/element_scan.h"
#include "tmop/quality/parallel_for.h"
#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int index(GuaranteeMeasure m) { return static_cast<int>(m); }

bool is_simplex(CellType linear) { return linear == CellType::kTri3 || linear == CellType::kTet4; }

double det(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

// min det J / max det J over the validity points of a quadratic cell. p: node coordinates,
// d per node (a 2D cell already in its plane).
double jacobian_ratio(CellType type, const double* p, int d) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  double A[9];
  for (const SamplePoint& s : sample_points(type, validity_rule(SampleRule::kDefault))) {
    cell_jacobian(type, p, d, s.xi, A);
    const double j = det(A, d);
    lo = std::min(lo, j);
    hi = std::max(hi, j);
  }
  if (!(hi > 0)) return lo < 0 ? -1 : 0;
  return lo / hi;
}

void measure_cell(CellType type, const double* nodes, const double* up, int space_dim,
                  const QualityOptions& options, std::array<double, kNumGuaranteeMeasures>* out,
                  std::uint8_t* sliver, std::uint8_t* inverted) {
  out->fill(kNaN);
  const CellInfo& info = cell_info(type);
  const CellQuality q = cell_quality(type, nodes, up, options);
  *inverted = q.inverted;
  const bool simplex = is_simplex(info.linear);
  if (simplex)
    (*out)[index(GuaranteeMeasure::kMeanRatio)] = q.mean_ratio;
  else
    (*out)[index(GuaranteeMeasure::kScaledJacobian)] = q.scaled_jacobian;
  if (info.linear == CellType::kTet4) {
    if (info.order == 2) {  // the corner tet of a tet10 (a linear tet is judged by its mean ratio)
      (*out)[index(GuaranteeMeasure::kMinDihedral)] = q.min_dihedral_deg;
      (*out)[index(GuaranteeMeasure::kMaxDihedral)] = -q.max_dihedral_deg;
    }
    *sliver =
        q.max_dihedral_deg > kSliverMaxDihedralDeg && q.min_dihedral_deg < kSliverMinDihedralDeg;
  }
  if (info.order < 2) return;
  if (simplex) {
    QualityOptions corner = options;
    corner.angles = false;
    (*out)[index(GuaranteeMeasure::kCornerMeanRatio)] =
        cell_quality(info.linear, nodes, up, corner).mean_ratio;
  }
  const int d = info.dim;
  double p[kMaxCellNodes * 3];
  if (d == 2 && !(space_dim == 2 || up != nullptr)) {
    cell_plane_coordinates(type, nodes, up, p);
  } else if (d == 2) {
    for (int i = 0; i < info.num_nodes; ++i) {
      p[2 * i] = nodes[3 * i];
      p[2 * i + 1] = nodes[3 * i + 1];
    }
  } else {
    std::copy(nodes, nodes + 3 * info.num_nodes, p);
  }
  (*out)[index(GuaranteeMeasure::kJacobianRatio)] = jacobian_ratio(type, p, d);
}

struct GroupKey {
  int type, region, measure;
  bool operator<(const GroupKey& o) const {
    return std::tie(type, region, measure) < std::tie(o.type, o.region, o.measure);
  }
};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

const char* guarantee_measure_key(GuaranteeMeasure m) {
  static const char* const keys[] = {"mean_ratio",     "scaled_jacobian", "corner_mean_ratio",
                                     "jacobian_ratio", "min_dihedral",    "max_dihedral"};
  return keys[index(m)];
}

const char* guarantee_measure_label(GuaranteeMeasure m) {
  static const char* const labels[] = {"mean ratio",  "scaled Jacobian",  "corner mean ratio",
                                       "det J ratio", "min dihedral deg", "max dihedral deg"};
  return labels[index(m)];
}

bool guarantee_measure_has_mean(GuaranteeMeasure m) { return index(m) < 4; }

namespace {

// Cell c's row of *v (an element of dimension d).
void measure_row(const Mesh& mesh, std::int64_t c, const double* up, const QualityOptions& options,
                 GuaranteeValues* v) {
  double nodes[kMaxCellNodes * 3] = {};
  const CellType type = mesh.cell_types[c];
  const int sd = mesh.space_dim;
  const std::int32_t* cell = mesh.cell(static_cast<int>(c));
  for (int i = 0; i < cell_num_nodes(type); ++i) {
    const double* x = mesh.vertex(cell[i]);
    for (int k = 0; k < 3; ++k) nodes[3 * i + k] = k < sd ? x[k] : 0.0;
  }
  measure_cell(type, nodes, up, sd, options, &v->cell[c], &v->sliver[c], &v->inverted[c]);
}

const double kZUp[3] = {0, 0, 1};

}  // namespace

GuaranteeValues guarantee_values(const Mesh& mesh, int threads) {
  GuaranteeValues v;
  const std::int64_t n = mesh.num_cells();
  std::array<double, kNumGuaranteeMeasures> none;
  none.fill(kNaN);
  v.cell.assign(n, none);
  v.sliver.assign(n, 0);
  v.inverted.assign(n, 0);
  const int d = mesh.dim();
  if (d < 2) return v;
  const double* up = is_planar_2d(mesh) ? kZUp : nullptr;
  QualityOptions options;
  options.threads = 1;
  parallel_chunks(n, kScanChunk, threads, [&](std::int64_t, std::int64_t begin, std::int64_t end) {
    for (std::int64_t c = begin; c < end; ++c)
      if (cell_dim(mesh.cell_types[c]) == d) measure_row(mesh, c, up, options, &v);
  });
  return v;
}

void measure_guarantee_cell(const Mesh& mesh, int c, bool planar, GuaranteeValues* values) {
  QualityOptions options;
  options.threads = 1;
  measure_row(mesh, c, planar ? kZUp : nullptr, options, values);
}

GuaranteeBaseline guarantee_baseline(const Mesh& input, int threads) {
  GuaranteeBaseline b;
  b.input = guarantee_values(input, threads);
  const std::int64_t n = input.num_cells();
  std::array<std::int32_t, kNumGuaranteeMeasures> no_group;
  no_group.fill(-1);
  b.cell_group.assign(n, no_group);
  b.cell_type.assign(input.cell_types.begin(), input.cell_types.end());
  std::map<GroupKey, int> worst_index, mean_index;
  for (std::int64_t c = 0; c < n; ++c) {
    // Cells inverted in the input are in no group: untangling may leave them at any valid
    // shape, and their measures (e.g. a hex27's corners) say nothing of their validity.
    if (b.input.inverted[c]) continue;
    const int type = static_cast<int>(input.cell_types[c]);
    const int region =
        c < static_cast<std::int64_t>(input.cell_region.size()) ? input.cell_region[c] : 0;
    for (int m = 0; m < kNumGuaranteeMeasures; ++m) {
      const double v = b.input.cell[c][m];
      if (std::isnan(v)) continue;
      auto add = [&](std::map<GroupKey, int>* index, std::vector<GuaranteeBaseline::Group>* groups,
                     int group_region) {
        const GroupKey key{type, group_region, m};
        auto it = index->find(key);
        if (it == index->end()) {
          it = index->emplace(key, static_cast<int>(groups->size())).first;
          groups->push_back({static_cast<CellType>(type), group_region,
                             static_cast<GuaranteeMeasure>(m),
                             std::numeric_limits<double>::infinity(), 0, -1, 0});
        }
        GuaranteeBaseline::Group& g = (*groups)[it->second];
        if (v < g.worst) {
          g.worst = v;
          g.worst_cell = static_cast<int>(c);
        }
        g.mean += v;  // a sum until the end
        ++g.count;
        return it->second;
      };
      b.cell_group[c][m] = add(&worst_index, &b.worst_groups, region);
      if (guarantee_measure_has_mean(static_cast<GuaranteeMeasure>(m)))
        add(&mean_index, &b.mean_groups, -1);
    }
  }
  for (auto* groups : {&b.worst_groups, &b.mean_groups})
    for (GuaranteeBaseline::Group& g : *groups) g.mean /= static_cast<double>(g.count);
  return b;
}

namespace {

// The result's worst and mean per group of the baseline.
struct GroupStats {
  std::vector<double> worst;
  std::vector<int> worst_cell;
  std::vector<double> mean;
};

GroupStats group_stats(const GuaranteeBaseline& b, const GuaranteeValues& r) {
  GroupStats s;
  s.worst.assign(b.worst_groups.size(), std::numeric_limits<double>::infinity());
  s.worst_cell.assign(b.worst_groups.size(), -1);
  std::vector<double> sum(b.mean_groups.size(), 0);
  std::map<GroupKey, int> mean_of;
  for (std::size_t i = 0; i < b.mean_groups.size(); ++i)
    mean_of[{static_cast<int>(b.mean_groups[i].type), -1, index(b.mean_groups[i].measure)}] =
        static_cast<int>(i);
  for (std::size_t c = 0; c < b.cell_group.size(); ++c)
    for (int m = 0; m < kNumGuaranteeMeasures; ++m) {
      const int g = b.cell_group[c][m];
      if (g < 0) continue;
      double v = r.cell[c][m];
      if (std::isnan(v)) v = -std::numeric_limits<double>::infinity();  // degenerate now
      if (v < s.worst[g]) {
        s.worst[g] = v;
        s.worst_cell[g] = static_cast<int>(c);
      }
      const GuaranteeBaseline::Group& wg = b.worst_groups[g];
      if (guarantee_measure_has_mean(wg.measure))
        sum[mean_of[{static_cast<int>(wg.type), -1, m}]] += v;
    }
  s.mean.resize(sum.size());
  for (std::size_t i = 0; i < sum.size(); ++i)
    s.mean[i] = sum[i] / static_cast<double>(b.mean_groups[i].count);
  return s;
}

}  // namespace

std::string GuaranteeViolation::message() const {
  std::string where = cell_name(type);
  if (kind == Kind::kWorst && region != 0) where += " in region " + std::to_string(region);
  const bool negated = measure == GuaranteeMeasure::kMaxDihedral;
  const double b = negated ? -before : before, a = negated ? -after : after;
  std::string s;
  switch (kind) {
    case Kind::kWorst:
      s = where + " worst " + guarantee_measure_label(measure) + " " + number(b) + " -> " +
          number(a);
      break;
    case Kind::kMean:
      s = where + " mean " + guarantee_measure_label(measure) + " " + number(b) + " -> " +
          number(a);
      break;
    case Kind::kSlivers:
      s = where + " slivers " + number(b) + " -> " + number(a);
      break;
    case Kind::kInverted:
      s = where + " inverted " + number(b) + " -> " + number(a);
      break;
  }
  if (cell >= 0) s += " (cell " + std::to_string(cell) + ")";
  return s;
}

std::vector<GuaranteeViolation> check_guarantees(const GuaranteeBaseline& b,
                                                 const GuaranteeValues& r,
                                                 const GuaranteeOptions& options) {
  std::vector<GuaranteeViolation> out;
  const GroupStats s = group_stats(b, r);
  const double t = options.tolerance;
  for (std::size_t g = 0; g < b.worst_groups.size(); ++g) {
    const GuaranteeBaseline::Group& bg = b.worst_groups[g];
    if (s.worst[g] < bg.worst - t)
      out.push_back({GuaranteeViolation::Kind::kWorst, bg.type, bg.region, bg.measure, bg.worst,
                     s.worst[g], s.worst_cell[g]});
  }
  if (options.means)
    for (std::size_t g = 0; g < b.mean_groups.size(); ++g) {
      const GuaranteeBaseline::Group& bg = b.mean_groups[g];
      if (s.mean[g] < bg.mean - t)
        out.push_back(
            {GuaranteeViolation::Kind::kMean, bg.type, 0, bg.measure, bg.mean, s.mean[g], -1});
    }
  // Per type: new slivers and new inversions, with the first such cell.
  struct Counts {
    std::int64_t before = 0, after = 0;
    int first_new = -1;
  };
  std::map<int, Counts> slivers, inverted;
  for (std::size_t c = 0; c < r.cell.size(); ++c) {
    const int type = static_cast<int>(b.cell_type[c]);
    auto count = [&](std::map<int, Counts>* m, bool was, bool is) {
      if (!was && !is) return;
      Counts& k = (*m)[type];
      k.before += was;
      k.after += is;
      if (is && !was && k.first_new < 0) k.first_new = static_cast<int>(c);
    };
    if (options.slivers) count(&slivers, b.input.sliver[c], r.sliver[c]);
    count(&inverted, b.input.inverted[c], r.inverted[c]);
  }
  for (auto* m : {&slivers, &inverted})
    for (const auto& [type, k] : *m)
      if (k.first_new >= 0)
        out.push_back({m == &slivers ? GuaranteeViolation::Kind::kSlivers
                                     : GuaranteeViolation::Kind::kInverted,
                       static_cast<CellType>(type), 0, GuaranteeMeasure::kMeanRatio,
                       static_cast<double>(k.before), static_cast<double>(k.after), k.first_new});
  if (options.tangled_inversions_only &&
      std::find(b.input.inverted.begin(), b.input.inverted.end(), 1) != b.input.inverted.end())
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const GuaranteeViolation& v) {
                               return v.kind != GuaranteeViolation::Kind::kInverted;
                             }),
              out.end());
  return out;
}

std::vector<int> guard_violators(const GuaranteeBaseline& b, const GuaranteeValues& r,
                                 const GuaranteeOptions& options) {
  const double t = options.tolerance;
  std::vector<char> bad(r.cell.size(), 0);
  for (std::size_t c = 0; c < r.cell.size(); ++c) {
    bad[c] = (r.inverted[c] && !b.input.inverted[c]) ||
             (options.slivers && r.sliver[c] && !b.input.sliver[c]);
    for (int m = 0; m < kNumGuaranteeMeasures && !bad[c]; ++m) {
      const int g = b.cell_group[c][m];
      if (g >= 0 && !(r.cell[c][m] >= b.worst_groups[g].worst - t)) bad[c] = 1;  // NaN too
    }
  }
  // A fallen mean: hold the cells that lost most until their losses cover mean_cover times the
  // deficit (holding a cell restores about its own loss; the margin covers what its neighbours
  // lose when their shared vertices go back).
  if (options.means) {
    const GroupStats s = group_stats(b, r);
    for (std::size_t g = 0; g < b.mean_groups.size(); ++g) {
      const GuaranteeBaseline::Group& mg = b.mean_groups[g];
      const double deficit = (mg.mean - s.mean[g]) * static_cast<double>(mg.count);
      if (!(s.mean[g] < mg.mean - t)) continue;
      const int m = index(mg.measure);
      std::vector<std::pair<double, int>> losses;
      for (std::size_t c = 0; c < r.cell.size(); ++c) {
        if (b.cell_type[c] != mg.type || b.cell_group[c][m] < 0) continue;
        const double loss = b.input.cell[c][m] - r.cell[c][m];
        if (loss > t) losses.emplace_back(loss, static_cast<int>(c));
      }
      std::sort(losses.begin(), losses.end(), std::greater<>());
      double covered = 0;
      for (const auto& [loss, c] : losses) {
        if (covered >= options.mean_cover * deficit) break;
        covered += loss;
        bad[c] = 1;
      }
    }
  }
  std::vector<int> out;
  for (std::size_t c = 0; c < bad.size(); ++c)
    if (bad[c]) out.push_back(static_cast<int>(c));
  return out;
}

}  // namespace tmop
