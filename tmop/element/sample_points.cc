#include "tmop/element/sample_points.h"

#include <array>
#include <cmath>

#include "tmop/element/shape.h"

namespace tmop {
namespace {

constexpr int kNumRules = 5;
const char* const kRuleNames[kNumRules] = {"default", "corners", "nodes", "centroid", "gauss"};

using Rule = std::vector<SamplePoint>;

void SetEqualWeights(Rule* r) {
  for (SamplePoint& p : *r) p.weight = 1.0 / static_cast<double>(r->size());
}

// Nodes first .. first + count - 1 but `skip` (-1: none).
Rule NodeRule(CellType type, int first, int count, int skip = -1) {
  Rule r;
  for (int i = first; i < first + count; ++i) {
    if (i == skip) continue;
    const double* x = reference_node(type, i);
    r.push_back({{x[0], x[1], x[2]}, 0});
  }
  SetEqualWeights(&r);
  return r;
}

Rule CentroidRule(CellType type) {
  switch (cell_info(type).linear) {
    case CellType::kTri3:
      return {{{1.0 / 3, 1.0 / 3, 0}, 1}};
    case CellType::kTet4:
      return {{{0.25, 0.25, 0.25}, 1}};
    case CellType::kWedge6:
      return {{{1.0 / 3, 1.0 / 3, 0}, 1}};
    case CellType::kPyramid5:  // the volume centroid of a pyramid is a quarter of the height up
      return {{{0, 0, 0.25}, 1}};
    default:  // vertex, lines, quads, hexes: the origin
      return {{{0, 0, 0}, 1}};
  }
}

// Gauss rules exact for polynomials of degree 2 in the reference coordinates, weights scaled to
// sum to 1.
Rule GaussRule(CellType type) {
  const double g = 1 / std::sqrt(3.0);  // 2-point Gauss-Legendre, exact to degree 3
  const double g2[2] = {-g, g};
  // 3-point Gauss-Legendre on [-1, 1] (degree 5), for the pyramid's collapsed axis.
  const double g3[3] = {-std::sqrt(0.6), 0, std::sqrt(0.6)};
  const double w3[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  // Strang-Fix 3-point triangle rule (degree 2).
  const double tri[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
  Rule r;
  switch (cell_info(type).linear) {
    case CellType::kVertex:
      return {{{0, 0, 0}, 1}};
    case CellType::kLine2:
      for (double x : g2) r.push_back({{x, 0, 0}, 0.5});
      return r;
    case CellType::kQuad4:
      for (double y : g2)
        for (double x : g2) r.push_back({{x, y, 0}, 0.25});
      return r;
    case CellType::kHex8:
      for (double z : g2)
        for (double y : g2)
          for (double x : g2) r.push_back({{x, y, z}, 0.125});
      return r;
    case CellType::kTri3:
      for (const auto& p : tri) r.push_back({{p[0], p[1], 0}, 1.0 / 3});
      return r;
    case CellType::kTet4: {
      // Keast's 4-point rule (degree 2): a = (5 - sqrt5)/20, b = 1 - 3a.
      const double a = (5 - std::sqrt(5.0)) / 20, b = 1 - 3 * a;
      r.push_back({{a, a, a}, 0.25});
      r.push_back({{b, a, a}, 0.25});
      r.push_back({{a, b, a}, 0.25});
      r.push_back({{a, a, b}, 0.25});
      return r;
    }
    case CellType::kWedge6:
      for (double z : g2)
        for (const auto& p : tri) r.push_back({{p[0], p[1], z}, 1.0 / 6});
      return r;
    case CellType::kPyramid5: {
      // Collapsed cube: xi = u (1 - w), eta = v (1 - w), zeta = w, dV = (1 - w)^2 du dv dw with
      // u, v in [-1, 1], w in [0, 1]. A monomial xi^a eta^b zeta^c with a + b + c <= 2 becomes
      // u^a v^b times a polynomial of degree <= 4 in w: 2 points in u, v and 3-point
      // Gauss-Legendre in w (degree 5) integrate it exactly. The pyramid's volume is 4/3.
      for (int k = 0; k < 3; ++k) {
        const double w = 0.5 * (g3[k] + 1), s = 1 - w;
        for (double v : g2)
          for (double u : g2) r.push_back({{u * s, v * s, w}, 0.5 * w3[k] * s * s / (4.0 / 3)});
      }
      return r;
    }
    default:
      return r;
  }
}

Rule MakeRule(CellType type, SampleRule rule) {
  const CellInfo& info = cell_info(type);
  const bool pyramid = info.linear == CellType::kPyramid5;
  switch (rule) {
    case SampleRule::kCorners:
      // A pyramid's apex is a degenerate point of its map (the gradients are singular there).
      return NodeRule(type, 0, info.num_corners, pyramid ? 4 : -1);
    case SampleRule::kNodes:
      return NodeRule(type, 0, info.num_nodes, pyramid ? 4 : -1);
    case SampleRule::kCentroid:
      return CentroidRule(type);
    case SampleRule::kGauss:
      return GaussRule(type);
    case SampleRule::kDefault:
      break;
  }
  // Linear simplices have a constant Jacobian: one point carries all the information.
  if (info.order == 1 && (type == CellType::kLine2 || type == CellType::kTri3 ||
                          type == CellType::kTet4 || type == CellType::kVertex))
    return CentroidRule(type);
  if (info.order == 1) return MakeRule(type, SampleRule::kCorners);
  return MakeRule(type, SampleRule::kNodes);
}

struct RuleTable {
  std::array<std::array<Rule, kNumRules>, kNumCellTypes> rules;
  RuleTable() {
    for (int t = 0; t < kNumCellTypes; ++t)
      for (int k = 0; k < kNumRules; ++k)
        rules[t][k] = MakeRule(static_cast<CellType>(t), static_cast<SampleRule>(k));
  }
};

}  // namespace

const std::vector<SamplePoint>& sample_points(CellType type, SampleRule rule) {
  static const RuleTable table;  // built once; C++11 guarantees thread-safe initialisation
  return table.rules[static_cast<int>(type)][static_cast<int>(rule)];
}

bool sample_rule_from_name(const std::string& name, SampleRule* rule) {
  for (int k = 0; k < kNumRules; ++k) {
    if (name == kRuleNames[k]) {
      *rule = static_cast<SampleRule>(k);
      return true;
    }
  }
  return false;
}

const char* sample_rule_name(SampleRule rule) { return kRuleNames[static_cast<int>(rule)]; }

SampleRule validity_rule(SampleRule rule) {
  return rule == SampleRule::kCentroid || rule == SampleRule::kGauss ? SampleRule::kDefault : rule;
}

}  // namespace tmop
