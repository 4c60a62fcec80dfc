// Small meshes with known answers, shared by the tests in tests/mesh/.
#ifndef TMOP_TESTS_MESH_TEST_MESHES_H_
#define TMOP_TESTS_MESH_TEST_MESHES_H_

#include <array>
#include <cstdint>
#include <vector>

#include "tmop/element/shape.h"
#include "tmop/mesh/mesh.h"

namespace tmop {
namespace testing_meshes {

// Two positive tets (0,1,2,3) and (1,2,3,4) sharing the face {1,2,3}.
inline Mesh TwoTets() {
  Mesh m;
  m.space_dim = 3;
  const double p[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  m.add_cell(CellType::kTet4, a);
  m.add_cell(CellType::kTet4, b);
  return m;
}

// 2x2 unit quads on [0,2]^2; vertex (i, j) has index 3 j + i.
inline Mesh QuadGrid2x2() {
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const double x[2] = {double(i), double(j)};
      m.add_vertex(x);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const std::int32_t q[4] = {3 * j + i, 3 * j + i + 1, 3 * (j + 1) + i + 1, 3 * (j + 1) + i};
      m.add_cell(CellType::kQuad4, q);
    }
  return m;
}

// Kuhn (Freudenthal) subdivision of an nx x ny x nz grid of unit cubes into 6 positive tets per
// cube, all around the cube diagonal (0,0,0)-(1,1,1): a conforming tet mesh.
inline Mesh KuhnTets(int nx, int ny, int nz) {
  Mesh m;
  m.space_dim = 3;
  m.coords.reserve(std::size_t(nx + 1) * (ny + 1) * (nz + 1) * 3);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double x[3] = {double(i), double(j), double(k)};
        m.add_vertex(x);
      }
  auto id = [&](int i, int j, int k) { return std::int32_t((k * (ny + 1) + j) * (nx + 1) + i); };
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  const bool odd[6] = {false, true, true, false, false, true};
  m.cell_types.reserve(std::size_t(6) * nx * ny * nz);
  m.cell_nodes.reserve(std::size_t(24) * nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (int p = 0; p < 6; ++p) {
          int c[3] = {i, j, k};
          std::int32_t t[4];
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[perms[p][s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          // The path x, y, z (identity) gives a positive tet; odd permutations mirror it.
          if (odd[p]) std::swap(t[1], t[2]);
          m.add_cell(CellType::kTet4, t);
        }
  return m;
}

// A hex with a pyramid on top, a tet on one pyramid face and a wedge on the hex's x = 1 face:
// every facet kind and every pair of kinds that can share a facet.
inline Mesh MixedMesh() {
  Mesh m;
  m.space_dim = 3;
  const double p[][3] = {{0, 0, 0},       {1, 0, 0},       {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1},       {1, 0, 1},       {1, 1, 1}, {0, 1, 1},
                         {0.5, 0.5, 1.5}, {1.5, 0.5, 1.6}, {2, 0, 0}, {2, 1, 0}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::int32_t pyramid[5] = {4, 5, 6, 7, 8};
  const std::int32_t tet[4] = {5, 6, 8, 9};
  const std::int32_t wedge[6] = {1, 5, 10, 2, 6, 11};
  m.add_cell(CellType::kHex8, hex);
  m.add_cell(CellType::kPyramid5, pyramid);
  m.add_cell(CellType::kTet4, tet);
  m.add_cell(CellType::kWedge6, wedge);
  return m;
}

// One cell of `type` placed by an affine map of its reference element plus a smooth bend of the
// quadratic nodes (positive det J everywhere for small `bend`).
inline Mesh SingleCell(CellType type, double bend) {
  Mesh m;
  m.space_dim = cell_dim(type) == 2 ? 2 : 3;
  const double M[3][3] = {{1.2, 0.2, 0.1}, {-0.1, 0.9, 0.2}, {0.1, -0.2, 1.1}};
  std::vector<std::int32_t> nodes;
  for (int i = 0; i < cell_num_nodes(type); ++i) {
    const double* r = reference_node(type, i);
    double x[3] = {0.3, -0.2, 0.5};
    for (int a = 0; a < m.space_dim; ++a)
      for (int b = 0; b < m.space_dim; ++b) x[a] += M[a][b] * r[b];
    x[0] += bend * r[1] * r[1];
    nodes.push_back(m.add_vertex(x));
  }
  m.add_cell(type, nodes.data());
  return m;
}

}  // namespace testing_meshes
}  // namespace tmop

#endif  // TMOP_TESTS_MESH_TEST_MESHES_H_
