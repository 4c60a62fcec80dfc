#include "tmop/partition/partition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "../optimize/grid_meshes.h"

namespace tmop {
namespace {

using testing_grid::grid;

TEST(VertexCells, ListsEveryElementOfEveryNodeInOrder) {
  const Mesh mesh = grid(CellType::kTet4, 3);
  const VertexCells vc = vertex_cells(mesh);
  std::vector<int> seen(mesh.num_cells(), 0);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    EXPECT_TRUE(std::is_sorted(vc.begin(v), vc.end(v)));
    for (const std::int32_t* c = vc.begin(v); c != vc.end(v); ++c) {
      const std::int32_t* nodes = mesh.cell(*c);
      EXPECT_NE(std::find(nodes, nodes + mesh.cell_size(*c), v), nodes + mesh.cell_size(*c));
      ++seen[*c];
    }
  }
  for (int c = 0; c < mesh.num_cells(); ++c) EXPECT_EQ(seen[c], 4);
}

class Partition : public ::testing::TestWithParam<CellType> {};

// Every element in exactly one of k parts, the parts balanced (METIS's 3 % imbalance, some
// slack for small graphs), the same partition for the same seed; boundary facets get -1.
TEST_P(Partition, BalancedDeterministicAndComplete) {
  const CellType type = GetParam();
  Mesh mesh = grid(type, cell_dim(type) == 2 ? 40 : 10);
  const std::int32_t facet[2] = {0, 1};
  if (cell_dim(type) == 2) mesh.add_cell(CellType::kLine2, facet);
  ElementGraph graph;
  ASSERT_TRUE(element_graph(mesh, &graph).ok());
  PartitionOptions options;
  options.num_parts = 8;
  std::vector<int> part, again;
  ASSERT_TRUE(partition_elements(mesh, graph, options, &part).ok());
  ASSERT_TRUE(partition_elements(mesh, graph, options, &again).ok());
  EXPECT_EQ(part, again);
  std::vector<int> size(8, 0);
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) {
      EXPECT_EQ(part[c], -1);
      continue;
    }
    ASSERT_GE(part[c], 0);
    ASSERT_LT(part[c], 8);
    ++size[part[c]];
  }
  const double mean = mesh.num_elements() / 8.0;
  for (const int s : size) {
    EXPECT_GT(s, 0.85 * mean);
    EXPECT_LT(s, 1.1 * mean);
  }
}

// A second partition told to avoid the first's cut vertices puts most of them inside parts.
// Not all: in 3D the cut surfaces of two partitions meet along curves (here, 10^3 cubes in 8
// parts, 22-30 % of the first's cut vertices; fewer in larger parts).
TEST_P(Partition, SecondPartitionAvoidsTheFirstsCuts) {
  const CellType type = GetParam();
  const Mesh mesh = grid(type, cell_dim(type) == 2 ? 40 : 10);
  ElementGraph graph;
  ASSERT_TRUE(element_graph(mesh, &graph).ok());
  const VertexCells vc = vertex_cells(mesh);
  PartitionOptions options;
  options.num_parts = 8;
  std::vector<int> p1, p2;
  ASSERT_TRUE(partition_elements(mesh, graph, options, &p1).ok());
  const std::vector<char> cut1 = cut_vertices(mesh, vc, p1);
  options.avoid = &cut1;
  options.seed = 2;
  ASSERT_TRUE(partition_elements(mesh, graph, options, &p2).ok());
  const std::vector<char> cut2 = cut_vertices(mesh, vc, p2);
  int on_cut1 = 0, on_both = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    on_cut1 += cut1[v];
    on_both += cut1[v] && cut2[v];
  }
  ASSERT_GT(on_cut1, 0);
  EXPECT_LT(on_both, (cell_dim(type) == 2 ? 0.2 : 0.35) * on_cut1) << on_both << " of " << on_cut1;
}

INSTANTIATE_TEST_SUITE_P(Types, Partition,
                         ::testing::Values(CellType::kTri3, CellType::kQuad4, CellType::kTet4,
                                           CellType::kHex8),
                         [](const ::testing::TestParamInfo<CellType>& info) {
                           return std::string(cell_info(info.param).name);
                         });

// The dual graph, against the definition by brute force over all pairs: elements adjacent when
// they share at least d corners (boundary facets are not graph vertices), neighbours
// ascending, the same graph on 1 and 3 threads. Also a mesh of two cell types (hexes and the
// wedges of one split layer) and a quadratic mesh, whose mid-edge nodes must not count.
std::string graph_difference(const Mesh& mesh) {
  ElementGraph g, g3;
  if (!element_graph(mesh, &g).ok() || !element_graph(mesh, &g3, 3).ok()) return "failed";
  if (g.xadj != g3.xadj || g.adjncy != g3.adjncy) return "depends on the threads";
  const int d = mesh.dim();
  std::vector<int> elements;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) elements.push_back(c);
  if (g.element_cell != elements) return "element_cell";
  const std::size_t ne = elements.size();
  for (std::size_t a = 0; a < ne; ++a) {
    std::vector<std::int32_t> expected;
    const int* na = mesh.cell(elements[a]);
    const int ka = cell_info(mesh.cell_type(elements[a])).num_corners;
    for (std::size_t b = 0; b < ne; ++b) {
      if (a == b) continue;
      const int* nb = mesh.cell(elements[b]);
      const int kb = cell_info(mesh.cell_type(elements[b])).num_corners;
      int shared = 0;
      for (int i = 0; i < ka; ++i) shared += std::count(nb, nb + kb, na[i]) > 0;
      if (shared >= d) expected.push_back(static_cast<std::int32_t>(b));
    }
    const std::vector<std::int32_t> got(g.adjncy.begin() + g.xadj[a],
                                        g.adjncy.begin() + g.xadj[a + 1]);
    if (got != expected) return "element " + std::to_string(a);
  }
  return "";
}

TEST_P(Partition, DualGraphIsTheElementsSharingAFacet) {
  const CellType type = GetParam();
  Mesh mesh = grid(type, cell_dim(type) == 2 ? 9 : 4);
  const std::int32_t facet[3] = {0, 1, 2};
  mesh.add_cell(cell_dim(type) == 2 ? CellType::kLine2 : CellType::kTri3, facet);
  EXPECT_EQ(graph_difference(mesh), "");
  // Large enough for several workers (4096 elements each at least).
  const Mesh big = grid(type, cell_dim(type) == 2 ? 80 : 14);
  ElementGraph one, three;
  ASSERT_TRUE(element_graph(big, &one).ok());
  ASSERT_TRUE(element_graph(big, &three, 3).ok());
  EXPECT_EQ(one.xadj, three.xadj);
  EXPECT_EQ(one.adjncy, three.adjncy);
  EXPECT_GT(one.adjncy.size(), 0u);
}

TEST(Partition, DualGraphOfMixedAndQuadraticMeshes) {
  // Hexes, and a layer of them split into two wedges each: hex-wedge facets are quads,
  // wedge-wedge facets quads or triangles.
  Mesh mixed = grid(CellType::kHex8, 3);
  Mesh out;
  out.space_dim = 3;
  out.coords = mixed.coords;
  for (int c = 0; c < mixed.num_cells(); ++c) {
    const std::int32_t* h = mixed.cell(c);
    if (c % 3 != 1) {
      out.add_cell(CellType::kHex8, h);
      continue;
    }
    const std::int32_t w1[6] = {h[0], h[1], h[3], h[4], h[5], h[7]};
    const std::int32_t w2[6] = {h[1], h[2], h[3], h[5], h[6], h[7]};
    out.add_cell(CellType::kWedge6, w1);
    out.add_cell(CellType::kWedge6, w2);
  }
  EXPECT_EQ(graph_difference(out), "");
  // Tet10 with shared mid-edge nodes: two tets on one edge share 2 corners and 1 mid node,
  // 3 nodes, and are still not adjacent.
  const Mesh tets = grid(CellType::kTet4, 3);
  Mesh quadratic;
  quadratic.space_dim = 3;
  quadratic.coords = tets.coords;
  std::map<std::pair<int, int>, std::int32_t> mid;
  const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {2, 3}, {1, 3}};
  for (int c = 0; c < tets.num_cells(); ++c) {
    std::int32_t n[10];
    std::copy_n(tets.cell(c), 4, n);
    for (int e = 0; e < 6; ++e) {
      const int a = n[edges[e][0]], b = n[edges[e][1]];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it == mid.end()) {
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = 0.5 * (tets.vertex(a)[k] + tets.vertex(b)[k]);
        it = mid.emplace(key, quadratic.add_vertex(x)).first;
      }
      n[4 + e] = it->second;
    }
    quadratic.add_cell(CellType::kTet10, n);
  }
  EXPECT_EQ(graph_difference(quadratic), "");
}

TEST(Partition, OnePartAndTooFewElements) {
  const Mesh mesh = grid(CellType::kTri3, 2);  // 8 triangles
  ElementGraph graph;
  ASSERT_TRUE(element_graph(mesh, &graph).ok());
  for (const int k : {1, 20}) {
    PartitionOptions options;
    options.num_parts = k;
    std::vector<int> part;
    ASSERT_TRUE(partition_elements(mesh, graph, options, &part).ok());
    for (const int p : part) EXPECT_EQ(p, 0);
  }
}

}  // namespace
}  // namespace tmop
