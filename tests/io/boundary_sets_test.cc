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
  const std::string dir = test::temp_dir();
  for (int nd : {3, 2}) {
    const Mesh a =
        with_sides(nd == 3 ? std::vector<CellType>(std::begin(kVolumeTypes), std::end(kVolumeTypes))
                           : std::vector<CellType>(std::begin(kAreaTypes), std::end(kAreaTypes)),
                   nd);
    const std::string path = dir + "/s" + std::to_string(nd) + ".exo";
    ASSERT_TRUE(write_mesh(path, a).ok());
    EXPECT_EQ(exodus_side_set_count(path), nd == 3 ? 6 : 4) << nd;
    Mesh b;
    const Status s = read_mesh(path, &b);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(b.num_cells(), a.num_cells());
    EXPECT_EQ(tmop_fuzz::mesh_difference(a, b, tmop_fuzz::holds("exo", false)), "") << nd;
  }
}

// A quad4 on a hex27's face is not that element's side (a quad9): its region gets no side set
// (the block keeps it), and the file reads back the same.
TEST(ExodusSides, LinearFacesOfQuadraticElementsAreNoSideSet) {
  Mesh a = test::straight_cells_mesh({CellType::kHex27, CellType::kHex8});
  for (int c = 0; c < 2; ++c) {
    CellType st;
    std::int32_t nodes[kMaxCellNodes];
    ASSERT_TRUE(io::exodus_side_cell(a, c, 5, 3, &st, nodes));
    a.add_cell(CellType::kQuad4, nodes, 7 + c, 0);  // region 7 on the hex27, 8 on the hex8
  }
  const std::string path = test::temp_dir() + "/q.exo";
  ASSERT_TRUE(write_mesh(path, a).ok());
  EXPECT_EQ(exodus_side_set_count(path), 1);  // region 8 only
  Mesh b;
  ASSERT_TRUE(read_mesh(path, &b).ok());
  EXPECT_EQ(tmop_fuzz::mesh_difference(a, b, tmop_fuzz::holds("exo", false)), "");
}

// A Cubit-style file: element blocks of volume (or 2D) cells only and side sets naming their
// sides, written with libexodusii. 3D: a unit-cube HEX8, a TETRA, a WEDGE, a PYRAMID and a HEX20
// (Exodus node order) at x = 0, 2, 4, 6, 8; 2D: a QUAD4 and a TRI3. Side set 10 b + s holds side
// s of element b and is named "bB_sS". bad_elem / bad_side replace the first entry.
struct CubitElement {
  const char* type;
  std::vector<V3> nodes;
};
std::vector<CubitElement> cubit_elements(bool two_d) {
  const std::vector<V3> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  if (two_d)
    return {{"QUAD4", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
            {"TRI3", {{2, 0, 0}, {3, 0, 0}, {2, 1, 0}}}};
  std::vector<CubitElement> e = {
      {"HEX8", cube},
      {"TETRA", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
      {"WEDGE", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}},
      {"PYRAMID", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}},
      {"HEX20", cube}};
  // HEX20's mid-edge nodes 9..20 (Exodus II manual): 1-2 2-3 3-4 4-1, 1-5 2-6 3-7 4-8, 5-6 6-7
  // 7-8 8-5.
  const int mid[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                          {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  for (const auto& m : mid) {
    V3 p;
    for (int k = 0; k < 3; ++k) p[k] = 0.5 * (cube[m[0]][k] + cube[m[1]][k]);
    e[4].nodes.push_back(p);
  }
  for (std::size_t b = 0; b < e.size(); ++b)
    for (V3& p : e[b].nodes) p[0] += 2.0 * b;
  return e;
}

// The outward unit normals of the sides as the Exodus II manual draws them (side 1 first).
std::vector<V3> manual_normals(const std::string& type) {
  const double r2 = std::sqrt(0.5), r3 = std::sqrt(1.0 / 3), r5 = std::sqrt(0.2);
  if (type == "HEX8" || type == "HEX20")
    return {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  if (type == "TETRA") return {{0, -1, 0}, {r3, r3, r3}, {-1, 0, 0}, {0, 0, -1}};
  if (type == "WEDGE") return {{0, -1, 0}, {r2, r2, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  if (type == "PYRAMID")
    return {{0, -2 * r5, r5}, {2 * r5, 0, r5}, {0, 2 * r5, r5}, {-2 * r5, 0, r5}, {0, 0, -1}};
  if (type == "QUAD4") return {{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  return {{0, -1, 0}, {r2, r2, 0}, {-1, 0, 0}};  // TRI3
}

std::string write_cubit(const std::string& path, bool two_d, int bad_elem = 0, int bad_side = 0) {
  const std::vector<CubitElement> elems = cubit_elements(two_d);
  std::vector<double> x, y, z;
  for (const CubitElement& e : elems)
    for (const V3& p : e.nodes) x.push_back(p[0]), y.push_back(p[1]), z.push_back(p[2]);
  int nss = 0;
  for (const CubitElement& e : elems) nss += static_cast<int>(manual_normals(e.type).size());
  int ws = 8, io = 8;
  const int f = ex_create(path.c_str(), EX_CLOBBER, &ws, &io);
  if (f < 0) return "ex_create failed";
  const int nb = static_cast<int>(elems.size());
  if (ex_put_init(f, "cubit-style", two_d ? 2 : 3, static_cast<int>(x.size()), nb, nb, 0, nss) <
          0 ||
      ex_put_coord(f, x.data(), y.data(), two_d ? nullptr : z.data()) < 0)
    return "header";
  int next = 1;
  std::vector<std::string> block_names, set_names;
  for (int b = 0; b < nb; ++b) {
    const int n = static_cast<int>(elems[b].nodes.size());
    std::vector<int> conn;
    for (int i = 0; i < n; ++i) conn.push_back(next++);
    if (ex_put_block(f, EX_ELEM_BLOCK, b + 1, elems[b].type, 1, n, 0, 0, 0) < 0 ||
        ex_put_conn(f, EX_ELEM_BLOCK, b + 1, conn.data(), nullptr, nullptr) < 0)
      return "block";
    block_names.push_back(std::string("vol_") + elems[b].type);
    for (std::size_t s = 1; s <= manual_normals(elems[b].type).size(); ++s) {
      const int id = 10 * (b + 1) + static_cast<int>(s);
      int elem = b + 1, side = static_cast<int>(s);
      if (set_names.empty() && bad_elem) elem = bad_elem;
      if (set_names.empty() && bad_side) side = bad_side;
      if (ex_put_set_param(f, EX_SIDE_SET, id, 1, 0) < 0 ||
          ex_put_set(f, EX_SIDE_SET, id, &elem, &side) < 0)
        return "side set";
      set_names.push_back("b" + std::to_string(b + 1) + "_s" + std::to_string(s));
    }
  }
  std::vector<char*> bp, sp;
  for (std::string& n : block_names) bp.push_back(&n[0]);
  for (std::string& n : set_names) sp.push_back(&n[0]);
  if (ex_put_names(f, EX_ELEM_BLOCK, bp.data()) < 0 || ex_put_names(f, EX_SIDE_SET, sp.data()) < 0)
    return "names";
  ex_close(f);
  return "";
}

// Each side becomes a boundary cell of its set's region and name, with the manual's outward
// normal; HEX20's sides are quad8 with their mid-edge nodes at the edge midpoints.
TEST(ExodusSides, CubitStyleFileGivesNamedOutwardBoundaryCells) {
  const std::string dir = test::temp_dir();
  for (bool two_d : {false, true}) {
    const std::string path = dir + (two_d ? "/cubit2.exo" : "/cubit3.exo");
    ASSERT_EQ(write_cubit(path, two_d), "");
    Mesh m;
    const Status st = read_mesh(path, &m);
    ASSERT_TRUE(st.ok()) << st.message();
    const std::vector<CubitElement> elems = cubit_elements(two_d);
    const int nb = static_cast<int>(elems.size()), nd = two_d ? 2 : 3;
    int sides = 0;
    for (const CubitElement& e : elems) sides += static_cast<int>(manual_normals(e.type).size());
    ASSERT_EQ(m.num_cells(), nb + sides);
    EXPECT_EQ(m.dim(), nd);
    std::vector<int> seen(10 * (nb + 1), 0);
    for (int c = nb; c < m.num_cells(); ++c) {
      const int r = m.cell_region[c], b = r / 10, s = r % 10;
      ASSERT_TRUE(b >= 1 && b <= nb && s >= 1) << r;
      ++seen[r];
      const std::vector<V3> want = manual_normals(elems[b - 1].type);
      ASSERT_LE(s, static_cast<int>(want.size()));
      const std::string* name = m.physical_name(nd - 1, r);
      ASSERT_NE(name, nullptr) << r;
      EXPECT_EQ(*name, "b" + std::to_string(b) + "_s" + std::to_string(s));
      const CellInfo& info = cell_info(m.cell_types[c]);
      EXPECT_EQ(info.dim, nd - 1);
      const bool quadratic = std::string(elems[b - 1].type) == "HEX20";
      EXPECT_EQ(m.cell_types[c], quadratic ? CellType::kQuad8 : cell_info(m.cell_types[c]).linear);
      const V3 n = side_normal(m, m.cell(c), info.num_corners, {0, 0, 1});
      EXPECT_GT(dot(n, want[s - 1]), 1 - 1e-9) << elems[b - 1].type << " side " << s << ": normal "
                                               << n[0] << " " << n[1] << " " << n[2];
      if (quadratic)
        for (int j = 0; j < 4; ++j) {
          const V3 a = point(m, m.cell(c)[j]), e = point(m, m.cell(c)[4 + j]);
          const V3 b2 = point(m, m.cell(c)[(j + 1) % 4]);
          for (int k = 0; k < 3; ++k) EXPECT_EQ(e[k], 0.5 * (a[k] + b2[k])) << "side " << s;
        }
    }
    for (int b = 1; b <= nb; ++b)
      for (std::size_t s = 1; s <= manual_normals(elems[b - 1].type).size(); ++s)
        EXPECT_EQ(seen[10 * b + s], 1) << b << " " << s;
    // Written back by tmop and read again: the same mesh (now the sides come from blocks too).
    const std::string again = dir + (two_d ? "/again2.exo" : "/again3.exo");
    ASSERT_TRUE(write_mesh(again, m).ok());
    Mesh back;
    ASSERT_TRUE(read_mesh(again, &back).ok());
    EXPECT_EQ(tmop_fuzz::mesh_difference(m, back, tmop_fuzz::holds("exo", false)), "");
  }
}

TEST(ExodusSides, BadElementOrSideIsAOneLineErrorNamingFileAndSet) {
  struct Bad {
    int elem, side;
    std::string want;
  };
  const Bad bad[] = {
      {99, 0, "side set 11, entry 1: element 99 is out of range 1..5"},
      {-3, 0, "side set 11, entry 1: element -3 is out of range 1..5"},
      {0, 7, "side set 11, entry 1: side 7 is out of range 1..6 of element 1 (hex8)"},
      {0, -1, "side set 11, entry 1: side -1 is out of range 1..6"}};
  for (const Bad& b : bad) {
    const std::string path = test::temp_dir() + "/bad.exo";
    ASSERT_EQ(write_cubit(path, false, b.elem, b.side), "");
    Mesh m;
    const Status st = read_mesh(path, &m);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find(path + ": " + b.want), std::string::npos) << st.message();
    EXPECT_EQ(st.message().find('\n'), std::string::npos);
  }
}

#endif  // TMOP_TEST_WITH_EXODUS

#ifdef TMOP_TEST_WITH_CGNS

struct CgBc {
  std::string name;
  CGNS_ENUMT(PointSetType_t) type;
  CGNS_ENUMT(GridLocation_t) location;
};
std::vector<CgBc> cgns_bcs(const std::string& path) {
  std::vector<CgBc> out;
  int fn = 0, n = 0;
  if (cg_open(path.c_str(), CG_MODE_READ, &fn) != CG_OK) return out;
  cg_nbocos(fn, 1, 1, &n);
  for (int bc = 1; bc <= n; ++bc) {
    char name[33] = {0};
    CGNS_ENUMT(BCType_t) bt;
    CgBc b;
    cgsize_t np = 0, nl = 0;
    int ni[3], nds = 0;
    CGNS_ENUMT(DataType_t) dt;
    cg_boco_info(fn, 1, 1, bc, name, &bt, &b.type, &np, ni, &nl, &dt, &nds);
    cg_boco_gridlocation_read(fn, 1, 1, bc, &b.location);
    b.name = name;
    if (bt == CGNS_ENUMV(FamilySpecified)) out.push_back(b);
  }
  cg_close(fn);
  return out;
}

// tmop -> tmop keeps the cells and regions; the BCs name the side regions whose cells are in
// sections of several types (so no section carries the name) and the file holds one
// FamilySpecified BC per boundary region, PointRange for the contiguous one.
TEST(CgnsBcs, RoundTripWritesOneBcPerBoundaryRegionAndNamesRegions) {
  const std::string dir = test::temp_dir();
  for (int nd : {3, 2}) {
    const Mesh a =
        with_sides(nd == 3 ? std::vector<CellType>(std::begin(kVolumeTypes), std::end(kVolumeTypes))
                           : std::vector<CellType>(std::begin(kAreaTypes), std::end(kAreaTypes)),
                   nd);
    const std::string path = dir + "/s" + std::to_string(nd) + ".cgns";
    ASSERT_TRUE(write_mesh(path, a).ok());
    const std::vector<CgBc> bcs = cgns_bcs(path);
    const int sides = nd == 3 ? 6 : 4;
    ASSERT_EQ(bcs.size(), static_cast<std::size_t>(sides + 1));
    for (int s = 1; s <= sides; ++s) {
      EXPECT_EQ(bcs[s - 1].name, "side_" + std::to_string(s));
      EXPECT_EQ(bcs[s - 1].type, CGNS_ENUMV(PointList));
    }
    EXPECT_EQ(bcs[sides].name, "loose");
    EXPECT_EQ(bcs[sides].type, CGNS_ENUMV(PointRange));
    for (const CgBc& b : bcs)
      EXPECT_EQ(b.location, nd == 3 ? CGNS_ENUMV(FaceCenter) : CGNS_ENUMV(EdgeCenter));
    Mesh b;
    const Status st = read_mesh(path, &b);
    ASSERT_TRUE(st.ok()) << st.message();
    EXPECT_EQ(tmop_fuzz::mesh_difference(a, b, tmop_fuzz::holds("cgns", false)), "") << nd;
    for (int s = 1; s <= sides; ++s) {
      const std::string* name = b.physical_name(nd - 1, 100 + s);
      ASSERT_NE(name, nullptr) << s;
      EXPECT_EQ(*name, "side_" + std::to_string(s));
    }
    ASSERT_NE(b.physical_name(nd - 1, 301), nullptr);
    EXPECT_EQ(*b.physical_name(nd - 1, 301), "loose");
  }
}

// A CFD-style file written with libcgns: a HEXA_8 section "fluid" (element 1), all six faces in
// one QUAD_4 section "QuadElements" (elements 2..7, face k = Exodus side k of the cube), and BCs
// "bottom" (PointList {6}: z = 0), "others" (PointRange 2..5 and 7: listed as a PointList) and a
// vertex BC "corners" that is ignored. bad_point replaces bottom's element.
std::string write_cfd(const std::string& path, cgsize_t bad_point = 0,
                      CGNS_ENUMT(GridLocation_t) loc = CGNS_ENUMV(FaceCenter)) {
  int fn = 0, B = 0, Z = 0, S = 0, C = 0, BC = 0;
  if (cg_open(path.c_str(), CG_MODE_WRITE, &fn) != CG_OK) return cg_get_error();
  cg_base_write(fn, "Base", 3, 3, &B);
  cgsize_t size[3] = {8, 1, 0};
  cg_zone_write(fn, B, "blk", size, CGNS_ENUMV(Unstructured), &Z);
  const double x[8] = {0, 1, 1, 0, 0, 1, 1, 0}, y[8] = {0, 0, 1, 1, 0, 0, 1, 1},
               z[8] = {0, 0, 0, 0, 1, 1, 1, 1};
  cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateX", x, &C);
  cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateY", y, &C);
  cg_coord_write(fn, B, Z, CGNS_ENUMV(RealDouble), "CoordinateZ", z, &C);
  const cgsize_t hex[8] = {1, 2, 3, 4, 5, 6, 7, 8};
  const cgsize_t quads[24] = {1, 2, 6, 5, 2, 3, 7, 6, 3, 4, 8, 7,
                              1, 5, 8, 4, 1, 4, 3, 2, 5, 6, 7, 8};
  cg_section_write(fn, B, Z, "fluid", CGNS_ENUMV(HEXA_8), 1, 1, 0, hex, &S);
  cg_section_write(fn, B, Z, "QuadElements", CGNS_ENUMV(QUAD_4), 2, 7, 0, quads, &S);
  const cgsize_t bottom[1] = {bad_point ? bad_point : 6}, others[5] = {2, 3, 4, 5, 7};
  const cgsize_t corners[2] = {1, 2};
  if (cg_boco_write(fn, B, Z, "bottom", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointList), 1, bottom,
                    &BC) != CG_OK ||
      cg_boco_gridlocation_write(fn, B, Z, BC, loc) != CG_OK ||
      cg_boco_write(fn, B, Z, "others", CGNS_ENUMV(BCFarfield), CGNS_ENUMV(PointList), 5, others,
                    &BC) != CG_OK ||
      cg_boco_gridlocation_write(fn, B, Z, BC, CGNS_ENUMV(FaceCenter)) != CG_OK ||
      cg_boco_write(fn, B, Z, "corners", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointList), 2, corners,
                    &BC) != CG_OK)
    return cg_get_error();
  cg_close(fn);
  return "";
}

TEST(CgnsBcs, CfdStyleBcsNameAndSplitTheBoundarySection) {
  const std::string path = test::temp_dir() + "/cfd.cgns";
  ASSERT_EQ(write_cfd(path), "");
  Mesh m;
  const Status st = read_mesh(path, &m);
  ASSERT_TRUE(st.ok()) << st.message();
  ASSERT_EQ(m.num_cells(), 7);
  int bottom = 0, others = 0;
  for (int c = 1; c < 7; ++c) {
    const std::string* name = m.physical_name(2, m.cell_region[c]);
    ASSERT_NE(name, nullptr) << c;
    const V3 n = side_normal(m, m.cell(c), 4, {0, 0, 1});
    if (*name == "bottom") {
      ++bottom;
      EXPECT_EQ(c, 5);  // element 6
      EXPECT_LT(n[2], -0.999);
    } else {
      EXPECT_EQ(*name, "others");
      ++others;
    }
  }
  EXPECT_EQ(bottom, 1);
  EXPECT_EQ(others, 5);
  EXPECT_NE(m.cell_region[5], m.cell_region[1]);
}

TEST(CgnsBcs, BadBcIsAOneLineErrorNamingFileAndBc) {
  struct Bad {
    cgsize_t point;
    std::string want;
  };
  const Bad bad[] = {
      {99, "zone 1, boundary condition 1 'bottom': element 99 is in no element section"},
      {-1, "zone 1, boundary condition 1 'bottom': element -1 is in no element section"},
      {1, "zone 1, boundary condition 1 'bottom': element 1 is a hex8, not a boundary cell"}};
  for (const Bad& b : bad) {
    const std::string path = test::temp_dir() + "/bad.cgns";
    ASSERT_EQ(write_cfd(path, b.point), "");
    Mesh m;
    const Status st = read_mesh(path, &m);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.message().find(path + ": " + b.want), std::string::npos) << st.message();
    EXPECT_EQ(st.message().find('\n'), std::string::npos);
  }
  // A vertex-located bottom names nothing: its face keeps the section's region and name.
  const std::string path = test::temp_dir() + "/vertex.cgns";
  ASSERT_EQ(write_cfd(path, 6, CGNS_ENUMV(Vertex)), "");
  Mesh m;
  ASSERT_TRUE(read_mesh(path, &m).ok());
  ASSERT_NE(m.physical_name(2, m.cell_region[5]), nullptr);
  EXPECT_EQ(*m.physical_name(2, m.cell_region[5]), "QuadElements");
}

#endif  // TMOP_TEST_WITH_CGNS

#if defined(TMOP_TEST_WITH_EXODUS) && defined(TMOP_TEST_WITH_CGNS)
// VTK's vtkExodusIIReader (its own side table) and vtkCGNSReader (LoadBndPatch) see every side
// set and BC patch by name with the cells, point sets and (side sets) orientation of the boundary
// blocks of that name (vtk_boundary_sets_check.py). pyramid14 has no VTK type.
TEST(BoundarySets, VtkReadsSideSetsAndBcPatchesWithTheirNames) {
  if (!test::have_python_module("vtk")) GTEST_SKIP() << "python3-vtk9 not installed";
  const std::string dir = test::temp_dir();
  for (int nd : {3, 2}) {
    std::vector<CellType> types(std::begin(kAreaTypes), std::end(kAreaTypes));
    if (nd == 3) types.assign(std::begin(kVolumeTypes), std::end(kVolumeTypes) - 1);
    const Mesh m = with_sides(types, nd);
    const std::string v = dir + "/v" + std::to_string(nd);
    ASSERT_TRUE(write_mesh(v + ".exo", m).ok());
    ASSERT_TRUE(write_mesh(v + ".cgns", m).ok());
    std::string out;
    ASSERT_EQ(test::run(std::string("/usr/bin/python3 ") + TMOP_SOURCE_DIR +
                            "/tests/io/vtk_boundary_sets_check.py " + v + ".exo " + v + ".cgns",
                        &out),
              0)
        << out;
    const std::vector<int> counts =
        nd == 3 ? std::vector<int>{10, 10, 10, 10, 8, 3} : std::vector<int>{5, 5, 5, 3};
    for (std::size_t s = 1; s <= counts.size(); ++s)
      for (const char* kind : {"sideset", "patch"})
        EXPECT_NE(out.find(std::string(kind) + " side_" + std::to_string(s) + " " +
                           std::to_string(counts[s - 1]) + "\n"),
                  std::string::npos)
            << nd << " " << kind << " " << s << "\n"
            << out;
    EXPECT_NE(out.find("patch loose 1\n"), std::string::npos) << out;
    EXPECT_EQ(out.find("sideset loose"), std::string::npos) << out;
  }
}
#endif

}  // namespace
}  // namespace tmop
