#include "tmop/geometry/triangle_surface_manifold.h"

#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tmop/geometry/closest_point.h"
#include "tmop/geometry/vec3.h"

namespace tmop {
namespace {
constexpr int kMaxCrossings = 4096;
const double kInf = std::numeric_limits<double>::infinity();

// Barycentric coordinates of the in-plane point p and of the in-plane direction w in triangle
// (a, b, c): lam(p + t w) = lam + t dlam.
void barycentric(const double* a, const double* b, const double* c, const double* p,
                 const double* w, double* lam, double* dlam) {
  double e1[3], e2[3], r[3];
  vec3::sub(b, a, e1);
  vec3::sub(c, a, e2);
  vec3::sub(p, a, r);
  const double g11 = vec3::dot(e1, e1), g12 = vec3::dot(e1, e2), g22 = vec3::dot(e2, e2);
  const double det = g11 * g22 - g12 * g12;
  const double r1 = vec3::dot(r, e1), r2 = vec3::dot(r, e2);
  const double w1 = vec3::dot(w, e1), w2 = vec3::dot(w, e2);
  const double s = (g22 * r1 - g12 * r2) / det, t = (g11 * r2 - g12 * r1) / det;
  const double ds = (g22 * w1 - g12 * w2) / det, dt = (g11 * w2 - g12 * w1) / det;
  lam[0] = 1 - s - t;
  lam[1] = s;
  lam[2] = t;
  dlam[0] = -ds - dt;
  dlam[1] = ds;
  dlam[2] = dt;
}

// Unit vector in the plane of normal n, perpendicular to the unit edge direction e, pointing
// away from `inside` (a point of the triangle off the edge line through `on_edge`).
void edge_normal(const double* n, const double* e, const double* on_edge, const double* inside,
                 double* m) {
  vec3::cross(n, e, m);
  vec3::normalize(m);
  double r[3];
  vec3::sub(on_edge, inside, r);
  if (vec3::dot(m, r) < 0) {
    for (int i = 0; i < 3; ++i) m[i] = -m[i];
  }
}

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

// lam clamped onto the triangle (negative coordinates to 0, renormalised).
void clamp_barycentric(double* lam) {
  double sum = 0;
  for (int k = 0; k < 3; ++k) {
    lam[k] = std::max(lam[k], 0.0);
    sum += lam[k];
  }
  for (int k = 0; k < 3; ++k) lam[k] = sum > 0 ? lam[k] / sum : 1.0 / 3;
}

}  // namespace

TriangleSurfaceManifold::TriangleSurfaceManifold(std::vector<double> vertices,
                                                 const std::vector<std::int32_t>& triangles,
                                                 Shape shape)
    : vertices_(std::move(vertices)) {
  const int nt = static_cast<int>(triangles.size() / 3);
  std::vector<double> lo, hi;
  for (int t = 0; t < nt; ++t) {
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = vertices_.data() + 3 * triangles[3 * t + k];
    double e1[3], e2[3], n[3];
    vec3::sub(p[1], p[0], e1);
    vec3::sub(p[2], p[0], e2);
    vec3::cross(e1, e2, n);
    double h = 0;
    for (int k = 0; k < 3; ++k) {
      double e[3];
      vec3::sub(p[(k + 1) % 3], p[k], e);
      h = std::max(h, vec3::norm(e));
    }
    // Relative test: an area below round-off of the edge lengths has no meaningful normal.
    if (vec3::normalize(n) <= 1e-14 * h * h) continue;
    triangles_.insert(triangles_.end(), triangles.begin() + 3 * t, triangles.begin() + 3 * t + 3);
    double u[3], v[3];
    vec3::tangent_basis(n, u, v);
    frames_.insert(frames_.end(), n, n + 3);
    frames_.insert(frames_.end(), u, u + 3);
    frames_.insert(frames_.end(), v, v + 3);
    for (int i = 0; i < 3; ++i) {
      lo.push_back(std::min({p[0][i], p[1][i], p[2][i]}));
      hi.push_back(std::max({p[0][i], p[1][i], p[2][i]}));
    }
  }
  CHECK_GT(triangles_.size(), 0u) << "TriangleSurfaceManifold: no triangle with positive area";
  {
    double blo[3] = {kInf, kInf, kInf}, bhi[3] = {-kInf, -kInf, -kInf};
    for (std::size_t i = 0; i < lo.size(); ++i) {
      blo[i % 3] = std::min(blo[i % 3], lo[i]);
      bhi[i % 3] = std::max(bhi[i % 3], hi[i]);
    }
    double e[3];
    vec3::sub(bhi, blo, e);
    scale_ = vec3::norm(e);
  }
  if (shape == Shape::kSmooth) {
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
  tree_.Build(3, lo, hi);

  // Neighbours through sorted (edge, triangle, corner) records: an edge with exactly two
  // triangles joins them; any other count is a border where walks stop.
  const int kept = num_triangles();
  std::vector<std::array<std::int32_t, 4>> edges;  // lo vertex, hi vertex, triangle, corner
  edges.reserve(3 * kept);
  for (int t = 0; t < kept; ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = triangles_[3 * t + (k + 1) % 3], b = triangles_[3 * t + (k + 2) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), t, k});
    }
  }
  std::sort(edges.begin(), edges.end());
  neighbours_.assign(3 * kept, -1);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]) ++j;
    if (j - i == 2) {
      neighbours_[3 * edges[i][2] + edges[i][3]] = edges[i + 1][2];
      neighbours_[3 * edges[i + 1][2] + edges[i + 1][3]] = edges[i][2];
    }
    i = j;
  }
}

int TriangleSurfaceManifold::locate(const double* x, double max_dist2, double* closest) const {
  double d2;
  double p[3];
  const int tri = tree_.Nearest(
      x, max_dist2,
      [&](int t) { return closest_point_triangle(x, corner(t, 0), corner(t, 1), corner(t, 2), p); },
      &d2);
  if (tri >= 0) closest_point_triangle(x, corner(tri, 0), corner(tri, 1), corner(tri, 2), closest);
  return tri;
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

void TriangleSurfaceManifold::Project(const double* x, double* closest) const {
  if (smooth()) {
    double lam[3];
    locate_smooth(x, lam, closest);
    return;
  }
  locate(x, kInf, closest);
}

bool TriangleSurfaceManifold::Normal(const double* x, double* n) const {
  double p[3];
  if (smooth()) {
    double lam[3], ju[3], jv[3];
    const int tri = locate_smooth(x, lam, p);
    patch_tangents(tri, lam, ju, jv);
    vec3::cross(ju, jv, n);
    if (vec3::normalize(n) > 0) return true;
    for (int i = 0; i < 3; ++i) n[i] = frame(tri)[i];
    return true;
  }
  const int tri = locate(x, kInf, p);
  for (int i = 0; i < 3; ++i) n[i] = frame(tri)[i];
  return true;
}

int TriangleSurfaceManifold::leave_vertex(int tri, int corner_index, double* w) const {
  const std::int32_t vertex = triangles_[3 * tri + corner_index];
  // The fan of triangles around the vertex, collected by turning both ways through neighbours
  // (an open fan stops at border edges). Fixed capacity: valences beyond it are truncated.
  constexpr int kMaxFan = 64;
  int fan[kMaxFan];
  int size = 0;
  fan[size++] = tri;
  // Edge opposite corner j is (j + 1, j + 2): the two edges at the vertex (corner kv) are those
  // opposite kv + 1 and kv + 2; turn through the first until back at tri or at a border, then,
  // for an open fan, the other way.
  bool closed = false;
  for (int turn = 1; turn <= 2 && !closed; ++turn) {
    int cur = tri;
    while (size < kMaxFan) {
      int kv = 0;
      while (triangles_[3 * cur + kv] != vertex) ++kv;
      const int next = neighbours_[3 * cur + (kv + turn) % 3];
      if (next < 0) break;
      if (next == tri) {
        closed = true;
        break;
      }
      fan[size++] = next;
      cur = next;
    }
  }
  // The triangle whose corner wedge at the vertex contains w (projected onto its plane), or
  // the one that comes closest: the sign of both other barycentric rates says "inside".
  int best = tri;
  double best_score = -kInf;
  double best_w[3] = {w[0], w[1], w[2]};
  for (int i = 0; i < size; ++i) {
    const int f = fan[i];
    const double* n = frame(f);
    double wf[3];
    const double wn = vec3::dot(w, n);
    for (int k = 0; k < 3; ++k) wf[k] = w[k] - wn * n[k];
    if (vec3::normalize(wf) == 0) continue;
    double lam[3], dlam[3];
    const double* c[3] = {corner(f, 0), corner(f, 1), corner(f, 2)};
    barycentric(c[0], c[1], c[2], vertices_.data() + 3 * vertex, wf, lam, dlam);
    int kv = 0;
    while (triangles_[3 * f + kv] != vertex) ++kv;
    double e[3];
    vec3::sub(c[(kv + 1) % 3], c[(kv + 2) % 3], e);
    // Barycentric rates are per unit length / edge length: scale by the opposite edge.
    const double score = std::min(dlam[(kv + 1) % 3], dlam[(kv + 2) % 3]) * vec3::norm(e);
    if (score > best_score) {
      best_score = score;
      best = f;
      for (int k = 0; k < 3; ++k) best_w[k] = wf[k];
    }
  }
  for (int k = 0; k < 3; ++k) w[k] = best_w[k];
  return best;
}

void TriangleSurfaceManifold::walk(int* tri, double* p, double* w, double len) const {
  bool turned_at_vertex = false;
  for (int crossing = 0; crossing < kMaxCrossings && len > 0; ++crossing) {
    const double* c[3] = {corner(*tri, 0), corner(*tri, 1), corner(*tri, 2)};
    double lam[3], dlam[3];
    barycentric(c[0], c[1], c[2], p, w, lam, dlam);
    // The first barycentric coordinate to reach 0 names the edge the path leaves through.
    double exit_t = kInf;
    int exit_k = -1;
    for (int k = 0; k < 3; ++k) {
      if (dlam[k] < 0) {
        const double t = std::max(lam[k], 0.0) / -dlam[k];
        if (t < exit_t) {
          exit_t = t;
          exit_k = k;
        }
      }
    }
    if (exit_k < 0 || len <= exit_t) {
      for (int i = 0; i < 3; ++i) p[i] += len * w[i];
      return;
    }
    // At a mesh vertex (where every patch vertex starts) a zero-length exit would send the
    // path round the fan through edge after edge; instead pick, once, the fan triangle whose
    // corner the direction points into, and walk from the vertex inside it.
    const double kAtCorner = 1e-12;
    int at_vertex = -1;
    for (int k = 0; k < 3; ++k) {
      if (lam[k] >= 1 - kAtCorner) at_vertex = k;
    }
    if (at_vertex >= 0 && !turned_at_vertex && std::max(lam[exit_k], 0.0) <= kAtCorner) {
      turned_at_vertex = true;
      const std::int32_t v = triangles_[3 * *tri + at_vertex];
      *tri = leave_vertex(*tri, at_vertex, w);
      for (int i = 0; i < 3; ++i) p[i] = vertices_[3 * v + i];
      continue;
    }
    if (exit_t > 0) turned_at_vertex = false;
    // The exit point, built on the edge itself so that round-off cannot accumulate off it.
    const int k1 = (exit_k + 1) % 3, k2 = (exit_k + 2) % 3;
    double l1 = std::max(lam[k1] + exit_t * dlam[k1], 0.0);
    double l2 = std::max(lam[k2] + exit_t * dlam[k2], 0.0);
    const double sum = l1 + l2 > 0 ? l1 + l2 : 1.0;
    l1 /= sum;
    l2 = 1 - l1;
    for (int i = 0; i < 3; ++i) p[i] = l1 * c[k1][i] + l2 * c[k2][i];
    len -= exit_t;
    const int next = neighbours_[3 * *tri + exit_k];
    if (next < 0) return;  // a border: the walk ends on it
    // Unfold: keep the component along the edge, turn the across-edge component into the
    // neighbour's plane, pointing into the neighbour.
    double e[3], m_from[3], m_to[3];
    vec3::sub(c[k2], c[k1], e);
    vec3::normalize(e);
    edge_normal(frame(*tri), e, c[k1], c[exit_k], m_from);
    int opposite = 0;
    for (int k = 0; k < 3; ++k) {
      if (neighbours_[3 * next + k] == *tri) opposite = k;
    }
    edge_normal(frame(next), e, corner(next, opposite), c[k1], m_to);
    // m_from points out of the triangle left behind, m_to into the neighbour (away from the
    // edge, towards its far corner).
    const double we = vec3::dot(w, e), wm = vec3::dot(w, m_from);
    for (int i = 0; i < 3; ++i) w[i] = we * e[i] + wm * m_to[i];
    vec3::normalize(w);
    *tri = next;
  }
}

bool TriangleSurfaceManifold::Plus(const double* x, const double* delta,
                                   double* x_plus_delta) const {
  double p[3];
  double lam[3];
  int tri;
  if (smooth()) {
    double on[3];
    tri = locate_smooth(x, lam, on);
    if (delta[0] == 0 && delta[1] == 0) {
      for (int i = 0; i < 3; ++i) x_plus_delta[i] = on[i];
      return true;
    }
    for (int i = 0; i < 3; ++i)
      p[i] = lam[0] * corner(tri, 0)[i] + lam[1] * corner(tri, 1)[i] + lam[2] * corner(tri, 2)[i];
  } else {
    tri = locate(x, kInf, p);
  }
  const double* f = frame(tri);
  double w[3];
  for (int i = 0; i < 3; ++i) w[i] = delta[0] * f[3 + i] + delta[1] * f[6 + i];
  const double len = vec3::normalize(w);
  if (len > 0) walk(&tri, p, w, len);
  if (smooth()) {
    double dlam[3];
    barycentric(corner(tri, 0), corner(tri, 1), corner(tri, 2), p, frame(tri), lam, dlam);
    clamp_barycentric(lam);
    eval_patch(tri, lam, x_plus_delta, nullptr);
    return true;
  }
  // Snap onto the final triangle: removes the round-off of the in-plane moves.
  closest_point_triangle(p, corner(tri, 0), corner(tri, 1), corner(tri, 2), x_plus_delta);
  return true;
}

bool TriangleSurfaceManifold::PlusJacobian(const double* x, double* jacobian) const {
  double p[3];
  if (smooth()) {
    double lam[3], ju[3], jv[3];
    const int tri = locate_smooth(x, lam, p);
    patch_tangents(tri, lam, ju, jv);
    for (int i = 0; i < 3; ++i) {
      jacobian[2 * i] = ju[i];
      jacobian[2 * i + 1] = jv[i];
    }
    return true;
  }
  const double* f = frame(locate(x, kInf, p));
  for (int i = 0; i < 3; ++i) {
    jacobian[2 * i] = f[3 + i];
    jacobian[2 * i + 1] = f[6 + i];
  }
  return true;
}

bool TriangleSurfaceManifold::Minus(const double* y, const double* x, double* y_minus_x) const {
  double px[3], py[3];
  if (smooth()) {
    // Both points back to their flat parameter points, then the flat chart.
    double lx[3], ly[3], on[3];
    const int tx = locate_smooth(x, lx, on);
    const int ty = locate_smooth(y, ly, on);
    for (int i = 0; i < 3; ++i) {
      px[i] = lx[0] * corner(tx, 0)[i] + lx[1] * corner(tx, 1)[i] + lx[2] * corner(tx, 2)[i];
      py[i] = ly[0] * corner(ty, 0)[i] + ly[1] * corner(ty, 1)[i] + ly[2] * corner(ty, 2)[i];
    }
    flat_minus(py, ty, px, tx, y_minus_x);
    return true;
  }
  const int tx = locate(x, kInf, px);
  const int ty = locate(y, kInf, py);
  flat_minus(y, ty, x, tx, y_minus_x);
  return true;
}

void TriangleSurfaceManifold::flat_minus(const double* y, int ty, const double* x, int tx,
                                         double* y_minus_x) const {
  const double* fx = frame(tx);
  double r[3];
  vec3::sub(y, x, r);
  int shared = -1;  // corner of tx opposite the edge shared with ty
  for (int k = 0; k < 3; ++k) {
    if (neighbours_[3 * tx + k] == ty) shared = k;
  }
  if (ty != tx && shared >= 0) {
    // Unfold y about the shared edge into x's plane: the inverse of one edge crossing.
    const double* a = corner(tx, (shared + 1) % 3);
    const double* b = corner(tx, (shared + 2) % 3);
    double e[3], m_x[3], m_y[3];
    vec3::sub(b, a, e);
    vec3::normalize(e);
    edge_normal(fx, e, a, corner(tx, shared), m_x);  // out of tx
    int opposite = 0;
    for (int k = 0; k < 3; ++k) {
      if (neighbours_[3 * ty + k] == tx) opposite = k;
    }
    edge_normal(frame(ty), e, a, corner(ty, opposite), m_y);  // out of ty, i.e. towards tx
    double ya[3];
    vec3::sub(y, a, ya);
    const double along = vec3::dot(ya, e), across = -vec3::dot(ya, m_y);
    for (int i = 0; i < 3; ++i) r[i] = a[i] + along * e[i] + across * m_x[i] - x[i];
  } else if (ty != tx) {
    // Farther away: first-order coordinates, with the length of y - x kept.
    const double len = vec3::norm(r);
    const double rn = vec3::dot(r, fx);
    for (int i = 0; i < 3; ++i) r[i] -= rn * fx[i];
    const double tl = vec3::norm(r);
    if (tl > 0) {
      for (int i = 0; i < 3; ++i) r[i] *= len / tl;
    }
  }
  y_minus_x[0] = vec3::dot(fx + 3, r);
  y_minus_x[1] = vec3::dot(fx + 6, r);
}

bool TriangleSurfaceManifold::MinusJacobian(const double* x, double* jacobian) const {
  double p[3];
  if (smooth()) {
    // Rows 1, 2 of [ju jv n]^-1: a move of y along n (off the patch) does not change Minus.
    double lam[3], ju[3], jv[3];
    const int tri = locate_smooth(x, lam, p);
    patch_tangents(tri, lam, ju, jv);
    const double* n = frame(tri);
    double r0[3], r1[3], m[3];
    vec3::cross(jv, n, r0);
    vec3::cross(n, ju, r1);
    vec3::cross(ju, jv, m);
    const double det = vec3::dot(m, n);
    for (int i = 0; i < 3; ++i) {
      jacobian[i] = r0[i] / det;
      jacobian[3 + i] = r1[i] / det;
    }
    return true;
  }
  const double* f = frame(locate(x, kInf, p));
  for (int i = 0; i < 3; ++i) {
    jacobian[i] = f[3 + i];
    jacobian[3 + i] = f[6 + i];
  }
  return true;
}

}  // namespace tmop
