// Tests of tmop/mesh/topology.h on meshes whose answers are known by hand or by formula.
#include "tmop/mesh/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "tests/mesh/test_meshes.h"

namespace tmop {
namespace {

using testing_meshes::KuhnTets;
using testing_meshes::MixedMesh;
using testing_meshes::QuadGrid2x2;
using testing_meshes::TwoTets;

// Outward: the facet's right-hand normal points away from its cell's corner centroid.
void ExpectOutward(const Mesh& m, const BoundaryFacet& f) {
  const int d = m.space_dim;
  double cc[3] = {0, 0, 0}, fc[3] = {0, 0, 0}, n[3] = {0, 0, 0};
  const int ncorner = cell_info(m.cell_type(f.cell)).num_corners;
  for (int k = 0; k < ncorner; ++k)
    for (int j = 0; j < d; ++j) cc[j] += m.vertex(m.cell(f.cell)[k])[j] / ncorner;
  for (int k = 0; k < f.num_corners; ++k)
    for (int j = 0; j < d; ++j) fc[j] += m.vertex(f.corners[k])[j] / f.num_corners;
  if (d == 2) {
    const double* a = m.vertex(f.corners[0]);
    const double* b = m.vertex(f.corners[1]);
    n[0] = b[1] - a[1];
    n[1] = a[0] - b[0];
  } else {
    for (int k = 0; k < f.num_corners; ++k) {  // Newell
      const double* p = m.vertex(f.corners[k]);
      const double* q = m.vertex(f.corners[(k + 1) % f.num_corners]);
      n[0] += (p[1] - q[1]) * (p[2] + q[2]);
      n[1] += (p[2] - q[2]) * (p[0] + q[0]);
      n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
  }
  double dot = 0;
  for (int j = 0; j < d; ++j) dot += n[j] * (fc[j] - cc[j]);
  EXPECT_GT(dot, 0) << "cell " << f.cell << " facet " << int(f.local);
}

// Brute force with std::map / std::set, independent of topology.cc's bucketing.
void ExpectMatchesBruteForce(const Mesh& m) {
  std::set<std::array<std::int32_t, 2>> edges;
  std::map<std::vector<std::int32_t>, int> facet_uses;
  for (int c = 0; c < m.num_cells(); ++c) {
    const CellInfo& info = cell_info(m.cell_type(c));
    for (int e = 0; e < info.num_edges; ++e) {
      std::int32_t a = m.cell(c)[info.edges[e][0]], b = m.cell(c)[info.edges[e][1]];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
    for (int f = 0; f < info.num_facets; ++f) {
      std::vector<std::int32_t> key;
      for (int k = 0; k < info.facets[f].num_corners; ++k)
        key.push_back(m.cell(c)[info.facets[f].corners[k]]);
      std::sort(key.begin(), key.end());
      ++facet_uses[key];
    }
  }
  const auto got_edges = mesh_edges(m);
  const std::vector<std::array<std::int32_t, 2>> expected_edges(edges.begin(), edges.end());
  EXPECT_EQ(expected_edges, got_edges);
  std::size_t singles = 0;
  for (const auto& kv : facet_uses) singles += kv.second == 1;
  const auto facets = boundary_facets(m);
  EXPECT_EQ(facets.size(), singles);
  for (const BoundaryFacet& f : facets) {
    std::vector<std::int32_t> key(f.corners, f.corners + f.num_corners);
    std::sort(key.begin(), key.end());
    EXPECT_EQ(facet_uses[key], 1);
    ExpectOutward(m, f);
  }
}

TEST(Topology, MixedHexPyramidTetWedge) {
  const Mesh m = MixedMesh();
  EXPECT_EQ(boundary_facets(m).size(), 14u);  // hex 4 + pyramid 3 + tet 3 + wedge 4
  ExpectMatchesBruteForce(m);
  const auto mask = boundary_vertex_mask(m);
  EXPECT_EQ(std::count(mask.begin(), mask.end(), 1), m.num_vertices());
}

TEST(Topology, MatchesBruteForceOnKuhnGrid) { ExpectMatchesBruteForce(KuhnTets(4, 3, 2)); }

TEST(Topology, TwoTetsSharingAFace) {
  const Mesh m = TwoTets();
  const auto edges = mesh_edges(m);
  ASSERT_EQ(edges.size(), 9u);
  // Every pair of the 5 vertices except (0, 4).
  std::set<std::array<std::int32_t, 2>> expected;
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b)
      if (!(a == 0 && b == 4)) expected.insert({a, b});
  using EdgeSet = std::set<std::array<std::int32_t, 2>>;
  EXPECT_EQ(EdgeSet(edges.begin(), edges.end()), expected);
  EXPECT_TRUE(std::is_sorted(edges.begin(), edges.end()));

  const auto facets = boundary_facets(m);
  ASSERT_EQ(facets.size(), 6u);
  for (const BoundaryFacet& f : facets) {
    EXPECT_EQ(f.num_corners, 3);
    std::set<int> s(f.corners, f.corners + 3);
    EXPECT_NE(s, (std::set<int>{1, 2, 3})) << "the shared face is interior";
    ExpectOutward(m, f);
  }
  const auto mask = boundary_vertex_mask(m);
  EXPECT_EQ(std::count(mask.begin(), mask.end(), 1), 5);
}

TEST(Topology, QuadGrid) {
  const Mesh m = QuadGrid2x2();
  EXPECT_EQ(mesh_edges(m).size(), 12u);
  const auto facets = boundary_facets(m);
  EXPECT_EQ(facets.size(), 8u);
  for (const BoundaryFacet& f : facets) {
    EXPECT_EQ(f.num_corners, 2);
    ExpectOutward(m, f);
  }
  const auto mask = boundary_vertex_mask(m);
  for (int v = 0; v < 9; ++v) EXPECT_EQ(mask[v], v == 4 ? 0 : 1) << v;
  const Adjacency adj = vertex_to_cells(m);
  ASSERT_EQ(adj.offsets.size(), 10u);
  const int expected_count[9] = {1, 2, 1, 2, 4, 2, 1, 2, 1};
  for (int v = 0; v < 9; ++v) EXPECT_EQ(adj.offsets[v + 1] - adj.offsets[v], expected_count[v]);
  EXPECT_EQ(std::vector<std::int32_t>(adj.items.begin() + adj.offsets[4],
                                      adj.items.begin() + adj.offsets[5]),
            (std::vector<std::int32_t>{0, 1, 2, 3}));
}

TEST(Topology, LowerDimensionalCellsAreIgnored) {
  Mesh m = QuadGrid2x2();
  const std::int32_t line[2] = {0, 1};
  m.add_cell(CellType::kLine2, line, 5);
  EXPECT_EQ(boundary_facets(m).size(), 8u);
  EXPECT_EQ(mesh_edges(m).size(), 12u);
  EXPECT_EQ(vertex_to_cells(m).items.size(), 16u);
}

// Two quad9 side by side and two hex27 stacked: the shared edge's / face's own nodes and the
// centres are interior, every other node is on the boundary.
TEST(Topology, BoundaryMaskIncludesQuadraticNodes) {
  {
    Mesh m;
    m.space_dim = 2;
    // Nodes on a 5 x 3 lattice (x = 0..4 halves, y = 0..2 halves); index 5 j + i.
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i) {
        const double x[2] = {0.5 * i, 0.5 * j};
        m.add_vertex(x);
      }
    auto id = [](int i, int j) { return 5 * j + i; };
    for (int c = 0; c < 2; ++c) {
      const int o = 2 * c;
      const std::int32_t q[9] = {id(o, 0),     id(o + 2, 0), id(o + 2, 2),
                                 id(o, 2),     id(o + 1, 0), id(o + 2, 1),
                                 id(o + 1, 2), id(o, 1),     id(o + 1, 1)};
      m.add_cell(CellType::kQuad9, q);
    }
    const auto mask = boundary_vertex_mask(m);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 5; ++i)
        EXPECT_EQ(mask[id(i, j)], (j == 1 && i >= 1 && i <= 3) ? 0 : 1) << i << "," << j;
    EXPECT_EQ(boundary_facets(m).size(), 6u);
  }
  {
    // Hex27 lattice 3 x 3 x 5 (z = 0..4), the two cells z in [0,2] and [2,4].
    Mesh m;
    m.space_dim = 3;
    auto id = [](int i, int j, int k) { return (k * 3 + j) * 3 + i; };
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
          const double x[3] = {double(i), double(j), double(k)};
          m.add_vertex(x);
        }
    for (int c = 0; c < 2; ++c) {
      std::int32_t nodes[27];
      for (int n = 0; n < 27; ++n) {
        const double* r = reference_node(CellType::kHex27, n);
        nodes[n] = id(int(r[0] + 1), int(r[1] + 1), int(r[2] + 1) + 2 * c);
      }
      m.add_cell(CellType::kHex27, nodes);
    }
    const auto mask = boundary_vertex_mask(m);
    int interior = 0;
    for (int v = 0; v < m.num_vertices(); ++v) {
      const double* x = m.vertex(v);
      const bool inside = x[0] == 1 && x[1] == 1 && x[2] > 0 && x[2] < 4;
      EXPECT_EQ(mask[v], inside ? 0 : 1) << v;
      interior += inside;
    }
    EXPECT_EQ(interior, 3);  // two centres and the shared face's node
    const auto facets = boundary_facets(m);
    EXPECT_EQ(facets.size(), 10u);
    for (const BoundaryFacet& f : facets) ExpectOutward(m, f);
  }
}

// Edges of the Kuhn grid: the grid's axis edges, one diagonal per grid face, one per cube.
std::size_t KuhnEdgeCount(std::size_t nx, std::size_t ny, std::size_t nz) {
  const std::size_t axis =
      nx * (ny + 1) * (nz + 1) + (nx + 1) * ny * (nz + 1) + (nx + 1) * (ny + 1) * nz;
  const std::size_t face = nx * ny * (nz + 1) + nx * nz * (ny + 1) + ny * nz * (nx + 1);
  return axis + face + nx * ny * nz;
}

TEST(Topology, KuhnGridCountsMatchFormulas) {
  const int nx = 3, ny = 4, nz = 5;
  const Mesh m = KuhnTets(nx, ny, nz);
  EXPECT_EQ(mesh_edges(m).size(), KuhnEdgeCount(nx, ny, nz));
  const auto facets = boundary_facets(m);
  EXPECT_EQ(facets.size(), std::size_t(4) * (nx * ny + ny * nz + nx * nz));
  for (const BoundaryFacet& f : facets) ExpectOutward(m, f);
  const auto mask = boundary_vertex_mask(m);
  EXPECT_EQ(std::count(mask.begin(), mask.end(), 0), (nx - 1) * (ny - 1) * (nz - 1));
}

// boundary_vertex_mask keeps its last answer for the same topology (boundary_vertex_mask in
// topology.cc): every change of cells, nodes, regions or entities gives a fresh mask, and
// masks of different meshes asked for in turn, from several threads, are each right.
TEST(Topology, BoundaryMaskFollowsEveryChangeOfTopology) {
  Mesh m = QuadGrid2x2();
  const std::vector<char> plain = boundary_vertex_mask(m);
  EXPECT_EQ(plain[4], 0);
  EXPECT_EQ(boundary_vertex_mask(m), plain);
  m.coords[3 * 4] += 0.1;  // coordinates do not matter
  EXPECT_EQ(boundary_vertex_mask(m), plain);
  m.cell_region.assign(m.num_cells(), 0);
  m.cell_region[0] = 7;  // a region interface through vertex 4
  EXPECT_EQ(boundary_vertex_mask(m)[4], 1);
  m.cell_region[0] = 0;
  EXPECT_EQ(boundary_vertex_mask(m)[4], 0);
  m.cell_entity.assign(m.num_cells(), 1);
  m.cell_entity[3] = 2;
  EXPECT_EQ(boundary_vertex_mask(m)[4], 1);
  m.cell_entity.clear();
  EXPECT_EQ(boundary_vertex_mask(m)[4], 0);
  // One cell fewer: vertex 4 is on the boundary.
  Mesh three = QuadGrid2x2();
  three.cell_types.pop_back();
  three.cell_offsets.pop_back();
  three.cell_nodes.resize(static_cast<std::size_t>(three.cell_offsets.back()));
  EXPECT_EQ(boundary_vertex_mask(three)[4], 1);
  EXPECT_EQ(boundary_facets(three).size(), 8u);  // was 8 for four quads too: 2 + 6 edges
  EXPECT_EQ(boundary_facets(QuadGrid2x2()).size(), 8u);
  const Mesh tets = TwoTets();
  EXPECT_EQ(boundary_facets(tets).size(), 6u);
  std::vector<std::thread> pool;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 3; ++t)
    pool.emplace_back([&, t] {
      for (int i = 0; i < 200; ++i) {
        if ((i + t) % 2) {
          if (boundary_vertex_mask(tets) != std::vector<char>(5, 1)) ++wrong;
        } else if (boundary_vertex_mask(three)[4] != 1 || boundary_vertex_mask(three)[0] != 1) {
          ++wrong;
        }
      }
    });
  for (std::thread& th : pool) th.join();
  EXPECT_EQ(wrong.load(), 0);
}

// About 1M tets: the topology functions must stay far below a second each (they are O(N) with
// tiny per-vertex sorts).
TEST(Topology, MillionTetsAreFast) {
  const int nx = 56, ny = 56, nz = 54;  // 6 * 56 * 56 * 54 = 1,016,064 tets
  const Mesh m = KuhnTets(nx, ny, nz);
  ASSERT_GT(m.num_cells(), 1000000);
  auto timed = [](const char* what, auto&& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s on 1M tets: %.3f s\n", what, s);
    return s;
  };
  std::vector<BoundaryFacet> facets;
  const double facet_seconds = timed("boundary_facets", [&] { facets = boundary_facets(m); });
  EXPECT_EQ(facets.size(), std::size_t(4) * (nx * ny + ny * nz + nx * nz));
  std::size_t num_edges = 0;
  const double edge_seconds = timed("mesh_edges", [&] { num_edges = mesh_edges(m).size(); });
  EXPECT_EQ(num_edges, KuhnEdgeCount(nx, ny, nz));
  std::size_t items = 0;
  const double adj_seconds =
      timed("vertex_to_cells", [&] { items = vertex_to_cells(m).items.size(); });
  EXPECT_EQ(items, std::size_t(4) * m.num_cells());
  // Generous bounds: the machine is shared; typical is ~0.2 s each in a Release build. Sanitized
  // and unoptimized builds are 5-20x slower and only check correctness.
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
  EXPECT_LT(facet_seconds, 3.0);
  EXPECT_LT(edge_seconds, 3.0);
  EXPECT_LT(adj_seconds, 3.0);
#else
  (void)facet_seconds, (void)edge_seconds, (void)adj_seconds;
#endif
}

}  // namespace
}  // namespace tmop
