// Structured test meshes built in code: n^d grids of the unit square / cube split into
// tri3 / quad4 / tet4 (Kuhn: 6 per cube) / hex8, positively oriented, and a random perturbation
// of the interior vertices that keeps every element valid.
#ifndef TMOP_TESTS_OPTIMIZE_GRID_MESHES_H_
#define TMOP_TESTS_OPTIMIZE_GRID_MESHES_H_

#include <random>

#include "tmop/mesh/mesh.h"
#include "tmop/mesh/topology.h"
#include "tmop/optimize/stage.h"

namespace tmop {
namespace testing_grid {

inline Mesh grid(CellType type, int n) {
  Mesh m;
  const int d = cell_dim(type);
  m.space_dim = d;
  const int nz = d == 3 ? n : 0;
  auto id = [&](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x[3] = {double(i) / n, double(j) / n, double(k) / n};
        m.add_vertex(x);
      }
  for (int k = 0; k < (d == 3 ? n : 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (type == CellType::kQuad4) {
          const std::int32_t q[4] = {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0),
                                     id(i, j + 1, 0)};
          m.add_cell(type, q);
        } else if (type == CellType::kTri3) {
          const std::int32_t a[3] = {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)};
          const std::int32_t b[3] = {id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)};
          m.add_cell(type, a);
          m.add_cell(type, b);
        } else {
          const std::int32_t c[8] = {
              id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
              id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
          if (type == CellType::kHex8) {
            m.add_cell(type, c);
          } else {  // Kuhn split of the cube along its 0-6 diagonal: 6 positive tets
            const int paths[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
            for (const auto& p : paths) {
              std::int32_t t[4] = {c[0], c[p[0]], c[p[1]], c[6]};
              // orient positively
              const double* a = m.vertex(t[0]);
              double e[3][3];
              for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s) e[r][s] = m.vertex(t[r + 1])[s] - a[s];
              const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                 e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                 e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
              if (det < 0) std::swap(t[1], t[2]);
              m.add_cell(CellType::kTet4, t);
            }
          }
        }
      }
  return m;
}

// Moves every interior vertex by up to `amount` x grid spacing in each coordinate; retries a
// vertex's move until no element is inverted.
inline void perturb(Mesh* m, int n, double amount, std::mt19937* rng) {
  const std::vector<char> boundary = boundary_vertex_mask(*m);
  std::uniform_real_distribution<double> u(-amount / n, amount / n);
  for (int v = 0; v < m->num_vertices(); ++v) {
    if (boundary[v]) continue;
    double saved[3];
    for (int a = 0; a < m->space_dim; ++a) saved[a] = m->vertex(v)[a];
    for (int attempt = 0; attempt < 20; ++attempt) {
      for (int a = 0; a < m->space_dim; ++a) m->vertex(v)[a] = saved[a] + u(*rng);
      if (measure_mesh(*m, SampleRule::kDefault).inverted == 0) break;
      for (int a = 0; a < m->space_dim; ++a) m->vertex(v)[a] = saved[a];
    }
  }
}

}  // namespace testing_grid
}  // namespace tmop

#endif  // TMOP_TESTS_OPTIMIZE_GRID_MESHES_H_
