// Small meshes built in code for the quality tests.
#ifndef TMOP_TESTS_QUALITY_TEST_MESHES_H_
#define TMOP_TESTS_QUALITY_TEST_MESHES_H_

#include <cstdlib>
#include <random>
#include <string>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace testing_meshes {

// An n x n x n block of unit cubes, each split into 6 positively oriented tets around its main
// diagonal, with vertices moved by up to `jitter` (uniform, seeded).
inline Mesh tet_block(int n, double jitter, unsigned seed = 1) {
  Mesh m;
  m.space_dim = 3;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x[3] = {i + u(rng), j + u(rng), k + u(rng)};
        m.add_vertex(x);
      }
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  const int tets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                          {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int v[8] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        for (const auto& t : tets) {
          const std::int32_t c[4] = {v[t[0]], v[t[1]], v[t[2]], v[t[3]]};
          m.add_cell(CellType::kTet4, c);
        }
      }
  return m;
}

// An n x n grid of unit squares split into two triangles each, in the plane (space_dim 2).
inline Mesh tri_grid(int n, double jitter, unsigned seed = 1) {
  Mesh m;
  m.space_dim = 2;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x[2] = {i + u(rng), j + u(rng)};
      m.add_vertex(x);
    }
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t a[3] = {id(i, j), id(i + 1, j), id(i + 1, j + 1)};
      const std::int32_t b[3] = {id(i, j), id(i + 1, j + 1), id(i, j + 1)};
      m.add_cell(CellType::kTri3, a);
      m.add_cell(CellType::kTri3, b);
    }
  return m;
}

// Runs `command` through the shell; true when it exits 0.
inline bool run(const std::string& command) { return std::system(command.c_str()) == 0; }

inline bool have_python() { return run("test -x /usr/bin/python3"); }

}  // namespace testing_meshes
}  // namespace tmop

#endif  // TMOP_TESTS_QUALITY_TEST_MESHES_H_
