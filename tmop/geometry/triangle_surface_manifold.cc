#include "tmop/geometry/triangle_surface_manifold.h"

#include <glog/logging.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "tmop/geometry/closest_point.h"
#include "tmop/geometry/triangle_surface_internal.h"
#include "tmop/geometry/vec3.h"

namespace tmop {
using surface_internal::barycentric;
using surface_internal::clamp_barycentric;
using surface_internal::kInf;
namespace {
constexpr int kMaxCrossings = 4096;

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
  if (shape == Shape::kSmooth) build_smooth(&lo, &hi);
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
