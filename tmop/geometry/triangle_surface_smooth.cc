// tmop/geometry/triangle_surface_smooth.cc
// TriangleSurfaceManifold's smooth shape (Shape::kSmooth): vertex normals, the cubic Bezier
// patch of each triangle, and locating, evaluating and differentiating the patches
// (docs/geometry.md, "smooth patches").
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "tmop/geometry/closest_point.h"
#include "tmop/geometry/triangle_surface_internal.h"
#include "tmop/geometry/triangle_surface_manifold.h"
#include "tmop/geometry/vec3.h"

namespace tmop {
using surface_internal::barycentric;
using surface_internal::clamp_barycentric;
using surface_internal::kInf;
namespace {

// Cubic Bezier triangle: control point order b300 b030 b003 b210 b120 b021 b012 b102 b201 b111
// (exponents of lam0 lam1 lam2) and the multinomial coefficients.
constexpr int kExp[10][3] = {{3, 0, 0}, {0, 3, 0}, {0, 0, 3}, {2, 1, 0}, {1, 2, 0},
                             {0, 2, 1}, {0, 1, 2}, {1, 0, 2}, {2, 0, 1}, {1, 1, 1}};
constexpr double kCoef[10] = {1, 1, 1, 3, 3, 3, 3, 3, 3, 6};

double ipow(double x, int e) { return e == 0 ? 1.0 : (e == 1 ? x : (e == 2 ? x * x : x * x * x)); }

// The control point next to p on the edge to q: the chord projected onto p's tangent plane
// (normal n), of a circular arc's handle length; the straight third of the chord when n says
// nothing about the edge (chord within round-off of the plane's normal, or beyond 60 degrees).
void edge_handle(const double* p, const double* n, const double* q, double* out) {
  double c[3], t[3];
  vec3::sub(q, p, c);
  const double len = vec3::norm(c);
  const double cn = n ? vec3::dot(c, n) : 0.0;
  for (int i = 0; i < 3; ++i) t[i] = c[i] - (n ? cn * n[i] : 0.0);
  const double tl = vec3::norm(t);
  if (!(len > 0) || !(tl > 0.5 * len)) {
    for (int i = 0; i < 3; ++i) out[i] = p[i] + c[i] / 3;
    return;
  }
  const double cos_a = tl / len;
  const double h = 2 * len / (3 * (1 + cos_a));
  for (int i = 0; i < 3; ++i) out[i] = p[i] + h * t[i] / tl;
}

// Refines the unit normal n of the surface at p by a least-squares quadric through p,
// h(x, y) = a x^2 + b xy + c y^2 + d x + e y over the tangent plane of n, fitted to the points
// q (count * 3): n becomes the fit's normal (-d, -e, 1). Unchanged when the fit is singular.
void fit_normal(const double* p, const std::vector<const double*>& q, double* n) {
  for (int round = 0; round < 2; ++round) {
    double u[3], v[3];
    vec3::tangent_basis(n, u, v);
    Eigen::Matrix<double, 5, 5> a = Eigen::Matrix<double, 5, 5>::Zero();
    Eigen::Matrix<double, 5, 1> rhs = Eigen::Matrix<double, 5, 1>::Zero();
    double scale = 0;
    for (const double* x : q) {
      double r[3];
      vec3::sub(x, p, r);
      scale = std::max(scale, vec3::norm(r));
    }
    if (!(scale > 0) || q.size() < 5) return;
    for (const double* x : q) {
      double r[3];
      vec3::sub(x, p, r);
      const double xu = vec3::dot(r, u) / scale, xv = vec3::dot(r, v) / scale;
      const double h = vec3::dot(r, n) / scale;
      Eigen::Matrix<double, 5, 1> row;
      row << xu * xu, xu * xv, xv * xv, xu, xv;
      a += row * row.transpose();
      rhs += h * row;
    }
    Eigen::JacobiSVD<Eigen::Matrix<double, 5, 5>> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const auto sv = svd.singularValues();
    if (!(sv(4) > 1e-10 * sv(0))) return;
    const Eigen::Matrix<double, 5, 1> c = svd.solve(rhs);
    double m[3];
    for (int i = 0; i < 3; ++i) m[i] = n[i] - c(3) * u[i] - c(4) * v[i];
    if (!(vec3::normalize(m) > 0)) return;
    for (int i = 0; i < 3; ++i) n[i] = m[i];
  }
}

}  // namespace

// The vertex normals and every triangle's control points; *lo / *hi become the patches' boxes
// (they held the flat triangles' boxes, which the flat tree is built from first).
void TriangleSurfaceManifold::build_smooth(std::vector<double>* lo_out,
                                           std::vector<double>* hi_out) {
  std::vector<double>& lo = *lo_out;
  std::vector<double>& hi = *hi_out;
  // Vertex normals: facet normals weighted by the corner angle, each turned to agree with the
  // sum so far (a patch of inconsistently oriented cells still gets a normal line).
  const int nv = static_cast<int>(vertices_.size() / 3);
  std::vector<double> vn(3 * static_cast<std::size_t>(nv), 0.0);
  for (int t = 0; t < num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      double a[3], b[3];
      vec3::sub(corner(t, (k + 1) % 3), corner(t, k), a);
      vec3::sub(corner(t, (k + 2) % 3), corner(t, k), b);
      const double la = vec3::norm(a), lb = vec3::norm(b);
      if (!(la > 0 && lb > 0)) continue;
      const double angle = std::acos(std::clamp(vec3::dot(a, b) / (la * lb), -1.0, 1.0));
      double* acc = &vn[3 * triangles_[3 * t + k]];
      const double sign = vec3::dot(acc, frame(t)) < 0 ? -1.0 : 1.0;
      for (int i = 0; i < 3; ++i) acc[i] += sign * angle * frame(t)[i];
    }
  }
  std::vector<char> has_normal(nv, 0);
  for (int v = 0; v < nv; ++v) has_normal[v] = vec3::normalize(&vn[3 * v]) > 0;
  // The facets' mean normal is first order on irregular neighbourhoods (a perturbed sphere):
  // refine it by a quadric fit to the vertex's neighbours (1-ring, 2-ring when it has < 6).
  std::vector<std::vector<std::int32_t>> ring(nv);
  for (int t = 0; t < num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      for (int j = 1; j < 3; ++j)
        ring[triangles_[3 * t + k]].push_back(triangles_[3 * t + (k + j) % 3]);
    }
  }
  for (auto& r : ring) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  std::vector<const double*> q;
  std::vector<std::int32_t> wide;
  for (int v = 0; v < nv; ++v) {
    if (!has_normal[v] || ring[v].empty()) continue;
    wide = ring[v];
    if (wide.size() < 6) {
      for (std::int32_t w : ring[v]) wide.insert(wide.end(), ring[w].begin(), ring[w].end());
      std::sort(wide.begin(), wide.end());
      wide.erase(std::unique(wide.begin(), wide.end()), wide.end());
    }
    q.clear();
    for (std::int32_t w : wide) {
      if (w != v) q.push_back(vertices_.data() + 3 * w);
    }
    fit_normal(vertices_.data() + 3 * v, q, &vn[3 * v]);
  }
  patches_.resize(30 * static_cast<std::size_t>(num_triangles()));
  flat_tree_.Build(3, lo, hi);
  lo.assign(3 * num_triangles(), kInf);
  hi.assign(3 * num_triangles(), -kInf);
  for (int t = 0; t < num_triangles(); ++t) {
    double* b = patches_.data() + 30 * t;
    const double* p[3] = {corner(t, 0), corner(t, 1), corner(t, 2)};
    const double* n[3];
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v = triangles_[3 * t + k];
      n[k] = has_normal[v] ? &vn[3 * v] : nullptr;
      for (int i = 0; i < 3; ++i) b[3 * k + i] = p[k][i];
    }
    // Handles in kExp order: 210 (0 -> 1), 120 (1 -> 0), 021 (1 -> 2), 012 (2 -> 1),
    // 102 (2 -> 0), 201 (0 -> 2).
    const int from[6] = {0, 1, 1, 2, 2, 0}, to[6] = {1, 0, 2, 1, 0, 2};
    double e[3] = {0, 0, 0}, c[3] = {0, 0, 0};
    for (int h = 0; h < 6; ++h) {
      edge_handle(p[from[h]], n[from[h]], p[to[h]], b + 3 * (3 + h));
      for (int i = 0; i < 3; ++i) e[i] += b[3 * (3 + h) + i] / 6;
    }
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) c[i] += p[k][i] / 3;
    }
    for (int i = 0; i < 3; ++i) b[27 + i] = e[i] + (e[i] - c[i]) / 2;
    for (int j = 0; j < 10; ++j) {
      for (int i = 0; i < 3; ++i) {
        lo[3 * t + i] = std::min(lo[3 * t + i], b[3 * j + i]);
        hi[3 * t + i] = std::max(hi[3 * t + i], b[3 * j + i]);
      }
    }
  }
}

void TriangleSurfaceManifold::eval_patch(int tri, const double* lam, double* out,
                                         double* dl) const {
  const double* b = patch(tri);
  for (int i = 0; i < 3; ++i) out[i] = 0;
  if (dl) {
    for (int i = 0; i < 9; ++i) dl[i] = 0;
  }
  for (int j = 0; j < 10; ++j) {
    const int* e = kExp[j];
    const double w = kCoef[j] * ipow(lam[0], e[0]) * ipow(lam[1], e[1]) * ipow(lam[2], e[2]);
    for (int i = 0; i < 3; ++i) out[i] += w * b[3 * j + i];
    if (!dl) continue;
    for (int a = 0; a < 3; ++a) {
      if (e[a] == 0) continue;
      double wa = kCoef[j] * e[a];
      for (int k = 0; k < 3; ++k) wa *= ipow(lam[k], k == a ? e[k] - 1 : e[k]);
      for (int i = 0; i < 3; ++i) dl[3 * a + i] += wa * b[3 * j + i];
    }
  }
}

bool TriangleSurfaceManifold::solve_patch(int tri, const double* x, double* lam, double* on) const {
  const double* c[3] = {corner(tri, 0), corner(tri, 1), corner(tri, 2)};
  const double* n = frame(tri);
  double dlam[3];
  barycentric(c[0], c[1], c[2], x, n, lam, dlam);  // the flat projection (n: any direction)
  double dl[9];
  double prev = kInf;
  for (int it = 0; it < 16; ++it) {
    eval_patch(tri, lam, on, dl);
    // Unknowns (lam1, lam2, s) with lam0 = 1 - lam1 - lam2: [b1 b2 n] step = x - b - s n,
    // where s (the offset along n) drops out of the lam part: solve with x - b directly.
    double b1[3], b2[3], r[3];
    for (int i = 0; i < 3; ++i) {
      b1[i] = dl[3 + i] - dl[i];
      b2[i] = dl[6 + i] - dl[i];
      r[i] = x[i] - on[i];
    }
    double m[3];
    vec3::cross(b1, b2, m);
    const double det = vec3::dot(m, n);
    if (!(std::fabs(det) > 0)) break;
    double rn2[3], b1r[3];
    vec3::cross(r, b2, rn2);
    vec3::cross(b1, r, b1r);
    const double s1 = vec3::dot(rn2, n) / det, s2 = vec3::dot(b1r, n) / det;  // Cramer
    const double step = std::fabs(s1) + std::fabs(s2);
    if (!(step < prev)) break;  // converged to round-off (or diverging): keep the last
    prev = step;
    lam[1] += s1;
    lam[2] += s2;
    lam[0] = 1 - lam[1] - lam[2];
    if (step < 1e-15) {
      eval_patch(tri, lam, on, nullptr);
      break;
    }
  }
  const bool inside = lam[0] >= 0 && lam[1] >= 0 && lam[2] >= 0;
  if (!inside) clamp_barycentric(lam);
  eval_patch(tri, lam, on, nullptr);
  return inside;
}

int TriangleSurfaceManifold::locate_smooth(const double* x, double* lam, double* on) const {
  // Fast path for points on the surface (every Plus, Minus and Jacobian query but the first
  // projection of a point): the facet nearest to x, or one of its neighbours, holds x in its
  // patch. Accepted only when the patch reproduces x to round-off; else the full search.
  double d2, p[3];
  const int t0 = flat_tree_.Nearest(
      x, kInf,
      [&](int t) { return closest_point_triangle(x, corner(t, 0), corner(t, 1), corner(t, 2), p); },
      &d2);
  const double tol2 = 1e-24 * scale_ * scale_;
  for (int k = -1; k < 3 && t0 >= 0; ++k) {
    const int t = k < 0 ? t0 : neighbours_[3 * t0 + k];
    if (t < 0) continue;
    double r[3];
    const bool inside = solve_patch(t, x, lam, on);
    vec3::sub(x, on, r);
    if (inside && vec3::dot(r, r) <= tol2) return t;
  }
  const int tri = tree_.Nearest(
      x, kInf,
      [&](int t) {
        double l[3], p[3], r[3];
        solve_patch(t, x, l, p);
        vec3::sub(x, p, r);
        return vec3::dot(r, r);
      },
      &d2);
  solve_patch(tri, x, lam, on);
  return tri;
}

void TriangleSurfaceManifold::patch_tangents(int tri, const double* lam, double* ju,
                                             double* jv) const {
  double p[3], dl[9], l[3], dlu[3], dlv[3];
  eval_patch(tri, lam, p, dl);
  const double* c[3] = {corner(tri, 0), corner(tri, 1), corner(tri, 2)};
  const double* f = frame(tri);
  barycentric(c[0], c[1], c[2], c[0], f + 3, l, dlu);
  barycentric(c[0], c[1], c[2], c[0], f + 6, l, dlv);
  for (int i = 0; i < 3; ++i) {
    ju[i] = dl[i] * dlu[0] + dl[3 + i] * dlu[1] + dl[6 + i] * dlu[2];
    jv[i] = dl[i] * dlv[0] + dl[3 + i] * dlv[1] + dl[6 + i] * dlv[2];
  }
}

}  // namespace tmop
