// The quadratic pyramids (shape_families.h): a monomial space and its nodal basis.
#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "tmop/element/cell_type.h"
#include "tmop/element/shape.h"
#include "tmop/element/shape_families.h"

namespace tmop {
namespace internal {
namespace {

constexpr int kMaxTerms = 14;

// The term u^i v^j s^k = xi^i eta^j s^m, m = k - i - j (m < 0: a rational term).
struct Term {
  int i, j, m;
};

struct Space {
  int count = 0;
  std::array<Term, kMaxTerms> terms{};
  // coefficients(t, n): the weight of term t in node n's basis function (the inverse of the
  // terms' values at the nodes).
  Eigen::Matrix<double, kMaxTerms, kMaxTerms> coefficients;
};

inline double IntPow(double x, int e) {
  double r = 1;
  for (int k = 0; k < e; ++k) r *= x;
  return r;
}

// Values (and, when g is not null, gradients) of the terms at xi. Below s = 1e-14 (the apex) the
// rational terms are 0 (their limit, since |xi|, |eta| <= s inside the pyramid) with gradient 0.
void EvalTerms(const Space& sp, const double* xi, double* f, double (*g)[3]) {
  const double x = xi[0], y = xi[1], s = 1 - xi[2];
  const bool apex = s < 1e-14;
  for (int t = 0; t < sp.count; ++t) {
    const Term& T = sp.terms[t];
    if (T.m < 0 && apex) {
      f[t] = 0;
      if (g) g[t][0] = g[t][1] = g[t][2] = 0;
      continue;
    }
    const double xp = IntPow(x, T.i), yp = IntPow(y, T.j);
    const double sp_m = T.m >= 0 ? IntPow(s, T.m) : 1 / IntPow(s, -T.m);
    f[t] = xp * yp * sp_m;
    if (!g) continue;
    g[t][0] = T.i > 0 ? T.i * IntPow(x, T.i - 1) * yp * sp_m : 0;
    g[t][1] = T.j > 0 ? T.j * xp * IntPow(y, T.j - 1) * sp_m : 0;
    // d/dzeta s^m = -m s^(m - 1)
    g[t][2] = T.m != 0 ? -T.m * xp * yp * sp_m / s : 0;
  }
}

Space MakeSpace(bool complete) {
  Space sp;
  for (int k = 0; k <= 2; ++k)
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= k; ++j) {
        if (!complete && i == 2 && j == 2) continue;
        sp.terms[sp.count++] = {i, j, k - i - j};
      }
  const CellType type = complete ? CellType::kPyramid14 : CellType::kPyramid13;
  const int n = sp.count;   // == the node count
  Eigen::MatrixXd V(n, n);  // V(node, term)
  for (int node = 0; node < n; ++node) {
    double f[kMaxTerms];
    EvalTerms(sp, reference_node(type, node), f, nullptr);
    for (int t = 0; t < n; ++t) V(node, t) = f[t];
  }
  // N_node(x) = sum_t C(t, node) f_t(x) with V C = I.
  const Eigen::MatrixXd C = V.fullPivLu().inverse();
  sp.coefficients.setZero();
  sp.coefficients.topLeftCorner(n, n) = C;
  return sp;
}

}  // namespace

void quadratic_pyramid(bool complete, const double* xi, double* N, double* dN) {
  static const Space kSpace13 = MakeSpace(false), kSpace14 = MakeSpace(true);
  const Space& sp = complete ? kSpace14 : kSpace13;
  const int n = sp.count;
  double f[kMaxTerms], g[kMaxTerms][3];
  EvalTerms(sp, xi, f, g);
  for (int node = 0; node < n; ++node) {
    double v = 0, d[3] = {0, 0, 0};
    for (int t = 0; t < n; ++t) {
      const double c = sp.coefficients(t, node);
      v += c * f[t];
      for (int j = 0; j < 3; ++j) d[j] += c * g[t][j];
    }
    N[node] = v;
    for (int j = 0; j < 3; ++j) dN[node * 3 + j] = d[j];
  }
}

}  // namespace internal
}  // namespace tmop
