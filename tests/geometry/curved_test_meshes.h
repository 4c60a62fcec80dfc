// tests/geometry/curved_test_meshes.h
// Generated curved surface meshes for the geometry-fidelity tests (tests/geometry and
// tests/recipes): a cube projected onto a sphere (quads or triangles), optionally with every
// vertex moved along the sphere by a deterministic pseudo-random fraction of the edge length, and
// an open spherical cap (a pole fan and rings of triangles).
#ifndef TMOP_TESTS_GEOMETRY_CURVED_TEST_MESHES_H_
#define TMOP_TESTS_GEOMETRY_CURVED_TEST_MESHES_H_

#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace curved_meshes {

// A deterministic value in [-1, 1] for (i, k).
inline double jitter(int i, int k) {
  const double s = std::sin(12.9898 * i + 78.233 * k + 0.5) * 43758.5453;
  return 2 * (s - std::floor(s)) - 1;
}

// Radius-r sphere centred at c: each cube face split n x n, projected (quads outward, or each
// quad split into two triangles). perturb > 0 moves every vertex by up to perturb x the cube
// edge (2 r / n) per coordinate, then back onto the sphere.
inline Mesh cube_sphere(int n, double r, const double* c, bool triangles, double perturb = 0) {
  Mesh m;
  m.space_dim = 3;
  std::map<std::tuple<long, long, long>, int> ids;
  auto vertex = [&](double x, double y, double z) {
    const auto key =
        std::make_tuple(std::lround(x * 1e6), std::lround(y * 1e6), std::lround(z * 1e6));
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const double len = std::sqrt(x * x + y * y + z * z);
    const double p[3] = {c[0] + r * x / len, c[1] + r * y / len, c[2] + r * z / len};
    const int id = m.add_vertex(p);
    ids[key] = id;
    return id;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = -1; side <= 1; side += 2) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          std::int32_t q[4];
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for (int k = 0; k < 4; ++k) {
            double p[3];
            p[axis] = side;
            p[(axis + 1) % 3] = -1 + 2.0 * (i + di[k]) / n;
            p[(axis + 2) % 3] = -1 + 2.0 * (j + dj[k]) / n;
            q[k] = vertex(p[0], p[1], p[2]);
          }
          // (axis + 1, axis + 2) is right-handed with the axis: outward for side +1.
          if (side < 0) std::swap(q[1], q[3]);
          if (triangles) {
            const std::int32_t a[3] = {q[0], q[1], q[2]}, b[3] = {q[0], q[2], q[3]};
            m.add_cell(CellType::kTri3, a);
            m.add_cell(CellType::kTri3, b);
          } else {
            m.add_cell(CellType::kQuad4, q);
          }
        }
      }
    }
  }
  if (perturb > 0) {
    const double h = 2 * r / n;
    for (int v = 0; v < m.num_vertices(); ++v) {
      double* x = m.vertex(v);
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = x[k] + perturb * h * jitter(v, k) - c[k];
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int k = 0; k < 3; ++k) x[k] = c[k] + r * d[k] / len;
    }
  }
  return m;
}

// Open cap of the radius-r sphere at the origin around +z, polar angles up to alpha: pole, then
// rings of `around` vertices (rim last: vertices num_vertices() - around .. end). perturb moves
// every vertex along the sphere as in cube_sphere (by up to perturb x the ring spacing), the rim
// too (it stays on the sphere, off its plane).
inline Mesh spherical_cap(double r, double alpha, int rings, int around, double perturb = 0) {
  Mesh m;
  m.space_dim = 3;
  const double pole[3] = {0, 0, r};
  m.add_vertex(pole);
  for (int k = 1; k <= rings; ++k) {
    const double a = alpha * k / rings;
    for (int i = 0; i < around; ++i) {
      const double t = 2 * M_PI * (i + 0.5 * (k % 2)) / around;
      const double p[3] = {r * std::sin(a) * std::cos(t), r * std::sin(a) * std::sin(t),
                           r * std::cos(a)};
      m.add_vertex(p);
    }
  }
  auto id = [&](int k, int i) { return 1 + (k - 1) * around + (i % around); };
  for (int i = 0; i < around; ++i) {
    const std::int32_t t[3] = {0, id(1, i), id(1, i + 1)};
    m.add_cell(CellType::kTri3, t);
  }
  for (int k = 1; k < rings; ++k) {
    for (int i = 0; i < around; ++i) {
      const std::int32_t a[3] = {id(k, i), id(k + 1, i), id(k + 1, i + 1)};
      const std::int32_t b[3] = {id(k, i), id(k + 1, i + 1), id(k, i + 1)};
      m.add_cell(CellType::kTri3, a);
      m.add_cell(CellType::kTri3, b);
    }
  }
  if (perturb > 0) {
    const double h = r * alpha / rings;
    for (int v = 0; v < m.num_vertices(); ++v) {
      double* x = m.vertex(v);
      double d[3];
      for (int k = 0; k < 3; ++k) d[k] = x[k] + perturb * h * jitter(v, k);
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int k = 0; k < 3; ++k) x[k] = r * d[k] / len;
    }
  }
  return m;
}

// Largest | |x - c| - r | over the vertices.
inline double sphere_drift(const Mesh& m, const double* c, double r) {
  double worst = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const double* x = m.vertex(v);
    const double d[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    worst = std::max(worst, std::abs(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - r));
  }
  return worst;
}

}  // namespace curved_meshes
}  // namespace tmop

#endif  // TMOP_TESTS_GEOMETRY_CURVED_TEST_MESHES_H_
