// Exodus II side sets and CGNS boundary conditions (io/exodus_sides.cc, io/cgns_bc.cc): the side
// table against the cell table and against the Exodus manual's pictures, round trips, files in
// the Cubit style (volume blocks and side sets only) and in the CFD style (one boundary section
// split by BC_t nodes) written here with the format libraries, bad sets, and VTK's readers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "tests/fuzz/same_mesh.h"
#include "tmop/io/exodus_sides.h"
#include "tmop/io/mesh_io.h"

#ifdef TMOP_TEST_WITH_EXODUS
#include <exodusII.h>
#endif
#ifdef TMOP_TEST_WITH_CGNS
#include <cgnslib.h>
#endif

namespace tmop {
namespace {

using V3 = std::array<double, 3>;

const CellType kVolumeTypes[] = {CellType::kTet4,      CellType::kHex8,     CellType::kWedge6,
                                 CellType::kPyramid5,  CellType::kTet10,    CellType::kHex20,
                                 CellType::kHex27,     CellType::kWedge15,  CellType::kWedge18,
                                 CellType::kPyramid13, CellType::kPyramid14};
const CellType kAreaTypes[] = {CellType::kTri3, CellType::kQuad4, CellType::kTri6, CellType::kQuad8,
                               CellType::kQuad9};

V3 point(const Mesh& m, int v) {
  V3 p = {0, 0, 0};
  for (int k = 0; k < m.space_dim; ++k) p[k] = m.vertex(v)[k];
  return p;
}
V3 sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 cross(V3 a, V3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 centroid(const Mesh& m, const std::int32_t* nodes, int n) {
  V3 c = {0, 0, 0};
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) c[k] += point(m, nodes[i])[k] / n;
  return c;
}
// The unit outward normal of a side (corners p[0..n)): the right-hand normal of a face; for an
// edge (n == 2) of a 2D cell with normal up, edge x up.
V3 side_normal(const Mesh& m, const std::int32_t* s, int n, V3 up) {
  V3 nrm =
      n == 2 ? cross(sub(point(m, s[1]), point(m, s[0])), up)
             : cross(sub(point(m, s[1]), point(m, s[0])), sub(point(m, s[n - 1]), point(m, s[0])));
  const double len = std::sqrt(dot(nrm, nrm));
  for (double& x : nrm) x /= len;
  return nrm;
}

// Every Exodus side is one of the cell table's facets, in the same cyclic (outward) order, each
// facet once; its normal points away from the element; its mid-edge nodes are the midpoints of
// its edges and a quad9 side's centre the mean of its corners (straight cells).
TEST(ExodusSides, MatchTheCellTableOutwardWithTheirQuadraticNodes) {
  std::vector<CellType> types(std::begin(kVolumeTypes), std::end(kVolumeTypes));
  types.insert(types.end(), std::begin(kAreaTypes), std::end(kAreaTypes));
  for (CellType t : types) {
    const Mesh m = test::straight_cells_mesh({t});
    const CellInfo& info = cell_info(t);
    const int nd = info.dim;
    ASSERT_EQ(io::exodus_num_sides(t, nd), info.num_facets) << cell_name(t);
    EXPECT_EQ(io::exodus_num_sides(t, 3), nd == 3 ? info.num_facets : 0) << cell_name(t);
    const std::int32_t* cn = m.cell(0);
    const V3 mid = centroid(m, cn, info.num_corners);
    const V3 up = nd == 2 ? cross(sub(point(m, cn[1]), point(m, cn[0])),
                                  sub(point(m, cn[2]), point(m, cn[0])))
                          : V3{0, 0, 0};
    std::vector<int> used(info.num_facets, 0);
    for (int s = 1; s <= info.num_facets; ++s) {
      CellType st;
      std::int32_t nodes[kMaxCellNodes];
      ASSERT_TRUE(io::exodus_side_cell(m, 0, s, nd, &st, nodes));
      const int n = cell_info(st).num_corners;
      int match = -1;
      for (int f = 0; f < info.num_facets; ++f) {
        const CellFacet& fc = info.facets[f];
        if (fc.num_corners != n) continue;
        for (int rot = 0; rot < n; ++rot) {
          bool same = true;
          for (int j = 0; j < n; ++j) same = same && cn[fc.corners[(j + rot) % n]] == nodes[j];
          if (same) match = f;
        }
      }
      ASSERT_GE(match, 0) << cell_name(t) << " side " << s << " is no outward facet";
      ++used[match];
      EXPECT_GT(dot(side_normal(m, nodes, n, up), sub(centroid(m, nodes, n), mid)), 0)
          << cell_name(t) << " side " << s;
      EXPECT_EQ(cell_info(st).order, info.order) << cell_name(t) << " side " << s;
      const int edges = n == 2 ? 1 : n;
      if (info.order == 2)
        for (int j = 0; j < edges; ++j) {
          const V3 a = point(m, nodes[j]), b = point(m, nodes[(j + 1) % n]);
          const V3 e = point(m, nodes[n + j]);
          for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(e[k], 0.5 * (a[k] + b[k]), 1e-12) << cell_name(t) << " side " << s;
        }
      const bool centre = facet_node(info, match) >= 0;
      EXPECT_EQ(st == CellType::kQuad9, centre) << cell_name(t) << " side " << s;
      if (centre) {
        const V3 c = centroid(m, nodes, 4), e = point(m, nodes[8]);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[k], c[k], 1e-12) << cell_name(t);
      }
    }
    for (int f = 0; f < info.num_facets; ++f) EXPECT_EQ(used[f], 1) << cell_name(t);
  }
}

// straight_cells_mesh of the types, each with every side as a boundary cell in region 100 + side
// named "side_S", and a quad4 of region 300 ("loose") that is no element's side.
Mesh with_sides(const std::vector<CellType>& types, int nd) {
  Mesh m = test::straight_cells_mesh(types);
  if (nd == 2) {
    std::vector<double> xy;
    for (int v = 0; v < m.num_vertices(); ++v) xy.insert(xy.end(), m.vertex(v), m.vertex(v) + 2);
    m.space_dim = 2;
    m.coords = xy;
  }
  const int elements = m.num_cells();
  for (int c = 0; c < elements; ++c)
    for (int s = 1; s <= io::exodus_num_sides(m.cell_types[c], nd); ++s) {
      CellType st;
      std::int32_t nodes[kMaxCellNodes];
      io::exodus_side_cell(m, c, s, nd, &st, nodes);
      m.add_cell(st, nodes, 100 + s, 0);
      m.set_physical_name(nd - 1, 100 + s, "side_" + std::to_string(s));
    }
  const std::int32_t loose[4] = {0, nd == 3 ? 1 : 4, 2, 3};  // {0, 4}: no tri3's edge
  if (nd == 3) m.add_cell(CellType::kLine2, loose, 300, 0);  // a 1D cell: no BC, no side set
  m.add_cell(nd == 3 ? CellType::kQuad4 : CellType::kLine2, loose, 301, 0);
  m.set_physical_name(nd - 1, 301, "loose");
  return m;
}

#ifdef TMOP_TEST_WITH_EXODUS

int exodus_side_set_count(const std::string& path) {
  int ws = 8, io = 0;
  float version = 0;
  const int f = ex_open(path.c_str(), EX_READ, &ws, &io, &version);
  if (f < 0) return -1;
  const int n = static_cast<int>(ex_inquire_int(f, EX_INQ_SIDE_SETS));
  ex_close(f);
  return n;
}

// tmop -> tmop keeps the cells (no duplicates from the side sets), regions and names; the file
// holds one side set per side region and none for "loose".
TEST(ExodusSides, RoundTripWritesSideSetsAndReadsNoDuplicates) {
  for (int nd : {3, 2}) {
    const Mesh a =
        with_sides(nd == 3 ? std::vector<CellType>(std::begin(kVolumeTypes), std::end(kVolumeTypes))
                           : std::vector<CellType>(std::begin(kAreaTypes), std::end(kAreaTypes)),
                   nd);
    const std::string path = test::temp_dir() + "/s" + std::to_string(nd) + ".exo";
    ASSERT_TRUE(write_mesh(path, a).ok());
    EXPECT_EQ(exodus_side_set_count(path), nd == 3 ? 6 : 4) << nd;
    Mesh b;
    const Status s = read_mesh(path, &b);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(b.num_cells(), a.num_cells());
    EXPECT_EQ(tmop_fuzz::mesh_difference(a, b, tmop_fuzz::holds("exo", false)), "") << nd;
  }
}

#endif  // TMOP_TEST_WITH_EXODUS

}  // namespace
}  // namespace tmop
