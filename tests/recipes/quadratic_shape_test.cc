// The shape stage on quadratic meshes (recipes/quadratic_shape.h), through the default recipe
// (untangle -> improve_shape, as tmop_optimize's auto runs it): meshes made by gmsh at order 2.
// Straight edges must stay on their chords, curved edges keep their shape, every per-type
// measure (corner cell, curved cell, dihedral range, slivers) keeps its worst and its mean, every
// cell stays certified valid, and the corner mesh still improves.
#include "tmop/recipes/quadratic_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "recipe_test_meshes.h"
#include "tmop/element/cell_type.h"
#include "tmop/element/shape.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/topology.h"
#include "tmop/quality/guarantees.h"
#include "tmop/quality/quality_report.h"
#include "tmop/recipes/improve_shape.h"
#include "tmop/recipes/quadratic_curving.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

using testing_recipes::exit_code;
using testing_recipes::have_gmsh;

// geo: gmsh geometry text; dim: 2 or 3. Order 2, straight-sided unless the geometry is curved
// (gmsh puts boundary mid nodes on the curve).
bool gmsh_order2(const std::string& name, const std::string& geo, int dim, Mesh* mesh) {
  const std::string base = "/tmp/tmop_quadratic_shape_" + name + "_" + std::to_string(::getpid());
  std::ofstream(base + ".geo") << geo << "Mesh.ElementOrder = 2;\nMesh.HighOrderOptimize = 0;\n";
  const std::string cmd = "gmsh -" + std::to_string(dim) + " -nt 1 " + base +
                          ".geo -format msh41 -o " + base + ".msh > /dev/null 2>&1";
  if (exit_code(cmd) != 0) return false;
  const bool ok = read_mesh(base + ".msh", mesh).ok();
  std::remove((base + ".geo").c_str());
  std::remove((base + ".msh").c_str());
  if (ok) mesh->remove_lower_dimensional_cells();
  return ok;
}

// A non-convex polygon (like Gmsh's tutorial t1, with a notch): straight boundary, ~500 tri6.
const char kPolygon[] =
    "lc = 0.09;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 0.6, 0, lc};\n"
    "Point(4) = {0.55, 0.35, 0, lc / 3}; Point(5) = {0.4, 1, 0, lc}; Point(6) = {0, 1, 0, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};\n"
    "Line(6) = {6, 1}; Curve Loop(1) = {1, 2, 3, 4, 5, 6}; Plane Surface(1) = {1};\n";

// A box with a notch corner refined (a few hundred straight-sided tet10).
const char kBox[] =
    "lc = 0.45;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};\n"
    "Point(4) = {0, 1, 0, lc / 4};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
    "Extrude {0, 0, 1} { Surface{1}; }\n";

// A structured hex27 box (3 x 3 x 3 cells).
const char kHexBox[] =
    "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
    "Transfinite Curve{1, 2, 3, 4} = 5; Transfinite Surface{1}; Recombine Surface{1};\n"
    "Extrude {0, 0, 1} { Surface{1}; Layers{4}; Recombine; }\n";

// A disk: curved boundary, boundary mid nodes on the circle.
const char kDisk[] =
    "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0, 0, 0, 1};\n"
    "Mesh.MeshSizeMax = 0.2;\n";

struct TypeSummary {
  int count = 0;
  double worst[3] = {1e300, 1e300, 1e300}, mean[3] = {0, 0, 0};
  double min_dihedral = 1e300, max_dihedral = -1e300;
  int slivers = 0, invalid = 0;
};

// Per quadratic type: corner quality, pointwise mean ratio, det J ratio (worst, mean).
std::map<CellType, TypeSummary> summarize(const Mesh& mesh) {
  std::map<CellType, TypeSummary> out;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d) || cell_info(mesh.cell_type(c)).order != 2) continue;
    double x[kMaxCellNodes * 3] = {};
    for (int i = 0; i < mesh.cell_size(c); ++i)
      for (int a = 0; a < mesh.space_dim; ++a) x[3 * i + a] = mesh.vertex(mesh.cell(c)[i])[a];
    const QuadraticCellMeasures m = quadratic_cell_measures(mesh.cell_type(c), x);
    TypeSummary& s = out[mesh.cell_type(c)];
    ++s.count;
    const double v[3] = {m.corner, m.pointwise_ratio, m.det_ratio};
    for (int k = 0; k < 3; ++k) {
      if (std::isnan(v[k])) continue;
      s.worst[k] = std::min(s.worst[k], v[k]);
      s.mean[k] += v[k];
    }
    if (!std::isnan(m.min_dihedral)) {
      s.min_dihedral = std::min(s.min_dihedral, m.min_dihedral);
      s.max_dihedral = std::max(s.max_dihedral, m.max_dihedral);
      s.slivers += m.max_dihedral > 150 && m.min_dihedral < 10;
    }
    s.invalid += !m.valid;
  }
  for (auto& [t, s] : out)
    for (double& v : s.mean) v /= s.count;
  return out;
}

// Relative deviation |mid - chord midpoint| / chord length of every mid-edge node, keyed by the
// edge's corners.
std::map<std::pair<int, int>, double> edge_deviation(const Mesh& mesh) {
  std::map<std::pair<int, int>, double> out;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d) || cell_info(mesh.cell_type(c)).order != 2) continue;
    const CellInfo& info = cell_info(mesh.cell_type(c));
    for (int e = 0; e < info.num_edges; ++e) {
      const int a = mesh.cell(c)[info.edges[e][0]], b = mesh.cell(c)[info.edges[e][1]];
      const int m = mesh.cell(c)[info.num_corners + e];
      double dev2 = 0, len2 = 0;
      for (int k = 0; k < mesh.space_dim; ++k) {
        const double mid = 0.5 * (mesh.vertex(a)[k] + mesh.vertex(b)[k]);
        dev2 += std::pow(mesh.vertex(m)[k] - mid, 2);
        len2 += std::pow(mesh.vertex(b)[k] - mesh.vertex(a)[k], 2);
      }
      out[{std::min(a, b), std::max(a, b)}] = std::sqrt(dev2 / len2);
    }
  }
  return out;
}

// Every guarantee of quadratic_shape.h, input -> output; returns the output's corner mean.
void expect_never_worse(const Mesh& in, const Mesh& out, const std::string& label) {
  const auto before = summarize(in), after = summarize(out);
  const double tol = 1e-6;
  for (const auto& [t, b] : before) {
    const TypeSummary& a = after.at(t);
    const char* names[3] = {"corner quality", "pointwise mean ratio", "det J ratio"};
    for (int k = 0; k < 3; ++k) {
      if (b.worst[k] > 1e299) continue;  // not defined for this type
      EXPECT_GE(a.worst[k], b.worst[k] - tol)
          << label << " " << cell_name(t) << " worst " << names[k];
      EXPECT_GE(a.mean[k], b.mean[k] - tol) << label << " " << cell_name(t) << " mean " << names[k];
    }
    EXPECT_GE(a.min_dihedral, b.min_dihedral - 1e-6) << label;
    EXPECT_LE(a.max_dihedral, b.max_dihedral + 1e-6) << label;
    EXPECT_LE(a.slivers, b.slivers) << label;
    EXPECT_EQ(a.invalid, 0) << label << " " << cell_name(t) << " cells not certified valid";
    const double bw1 = b.worst[1] > 1e299 ? NAN : b.worst[1];  // quad9 / hex27: not defined
    const double aw1 = a.worst[1] > 1e299 ? NAN : a.worst[1];
    std::printf(
        "%s: corner worst %.4f -> %.4f mean %.4f -> %.4f; pointwise mean ratio worst %.4f "
        "-> %.4f; det J ratio worst %.4f -> %.4f mean %.4f -> %.4f\n",
        label.c_str(), b.worst[0], a.worst[0], b.mean[0], a.mean[0], bw1, aw1, b.worst[2],
        a.worst[2], b.mean[2], a.mean[2]);
  }
  const QualityReport q = compute_quality(out);
  EXPECT_EQ(q.inverted_cells, 0) << label;
  EXPECT_EQ(q.certified_cells, q.certifiable_cells) << label;
}

// The edges (corner pairs) of the cells within kCurvingRings rings of a cell with a curved
// boundary edge: the curved-node stage may curve them (quadratic_curving.h).
std::set<std::pair<int, int>> near_curved_boundary(const Mesh& mesh) {
  const int d = mesh.dim();
  const std::vector<char> boundary = boundary_vertex_mask(mesh);
  const auto dev = edge_deviation(mesh);
  std::vector<char> in(mesh.num_cells(), 0);
  std::vector<std::vector<int>> vertex_cells(mesh.num_vertices());
  auto key = [&](int c, int e) {
    const CellInfo& info = cell_info(mesh.cell_type(c));
    const int a = mesh.cell(c)[info.edges[e][0]], b = mesh.cell(c)[info.edges[e][1]];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d) || cell_info(mesh.cell_type(c)).order != 2) continue;
    const CellInfo& info = cell_info(mesh.cell_type(c));
    for (int i = 0; i < info.num_nodes; ++i) vertex_cells[mesh.cell(c)[i]].push_back(c);
    for (int e = 0; e < info.num_edges; ++e)
      in[c] |= boundary[mesh.cell(c)[info.num_corners + e]] && dev.at(key(c, e)) > 1e-12;
  }
  for (int r = 0; r < kCurvingRings; ++r) {
    std::vector<char> next = in;
    for (int c = 0; c < mesh.num_cells(); ++c)
      if (in[c])
        for (int i = 0; i < mesh.cell_size(c); ++i)
          for (int e : vertex_cells[mesh.cell(c)[i]]) next[e] = 1;
    in.swap(next);
  }
  std::set<std::pair<int, int>> out;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (in[c])
      for (int e = 0; e < cell_info(mesh.cell_type(c)).num_edges; ++e) out.insert(key(c, e));
  return out;
}

// Edges straight in the input (deviation < 1e-12) stay straight (< 1e-9) unless they are near a
// curved boundary (near_curved_boundary); curved ones keep their relative deviation. Returns the
// number of straight edges whose corners moved.
int expect_edges_kept(const Mesh& in, const Mesh& out, const std::string& label) {
  const auto d0 = edge_deviation(in), d1 = edge_deviation(out);
  const auto may_curve = near_curved_boundary(in);
  double worst_straight = 0, worst_curved = 0;
  int moved = 0;
  for (const auto& [e, dev] : d0) {
    const double now = d1.at(e);
    if (dev < 1e-12 && may_curve.count(e)) continue;
    if (dev < 1e-12) {
      worst_straight = std::max(worst_straight, now);
      bool m = false;
      for (int k = 0; k < in.space_dim; ++k) m |= in.vertex(e.first)[k] != out.vertex(e.first)[k];
      moved += m;
    } else {
      worst_curved = std::max(worst_curved, std::abs(now - dev));
    }
  }
  EXPECT_LT(worst_straight, 1e-9) << label << ": a straight edge was curved";
  return moved;
}

RecipeResult run_auto(Mesh* mesh) {
  UntangleOptions opt;  // what tmop_optimize's default recipe runs
  opt.solver.threads = 1;
  RecipeResult result;
  const Status s = untangle(mesh, opt, &result);
  EXPECT_TRUE(s.ok()) << s.message();
  return result;
}

// Moves the interior corners by up to `amount` of the mesh size and puts every other node at the
// corners' linear interpolation: a valid straight-sided mesh that can be improved.
void perturb_straight(Mesh* mesh, double amount, unsigned seed) {
  const std::vector<char> boundary = boundary_vertex_mask(*mesh);
  std::vector<char> corner(mesh->num_vertices(), 0);
  const int d = mesh->dim();
  for (int c = 0; c < mesh->num_cells(); ++c)
    if (mesh->is_element(c, d))
      for (int i = 0; i < cell_info(mesh->cell_type(c)).num_corners; ++i)
        corner[mesh->cell(c)[i]] = 1;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (int v = 0; v < mesh->num_vertices(); ++v)
    if (corner[v] && !boundary[v])
      for (int a = 0; a < mesh->space_dim; ++a) mesh->vertex(v)[a] += u(rng);
  double N[kMaxCellNodes];
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!mesh->is_element(c, d)) continue;
    const CellType t = mesh->cell_type(c);
    const CellInfo& info = cell_info(t);
    for (int k = info.num_corners; k < info.num_nodes; ++k) {
      shape_values(info.linear, reference_node(t, k), N);
      for (int a = 0; a < mesh->space_dim; ++a) {
        double x = 0;
        for (int i = 0; i < info.num_corners; ++i) x += N[i] * mesh->vertex(mesh->cell(c)[i])[a];
        mesh->vertex(mesh->cell(c)[k])[a] = x;
      }
    }
  }
}

TEST(QuadraticShape, CornerMeshHasTheLinearCellsOnTheSameVertices) {
  Mesh m;
  m.space_dim = 2;
  const double x[] = {0, 0, 1, 0, 0, 1, 0.5, 0, 0.5, 0.5, 0, 0.5};
  m.coords.assign(x, x + 12);
  const std::int32_t tri6[] = {0, 1, 2, 3, 4, 5};
  m.add_cell(CellType::kTri6, tri6, 7, 3);
  const Mesh c = corner_mesh(m);
  ASSERT_EQ(c.num_cells(), 1);
  EXPECT_EQ(c.cell_type(0), CellType::kTri3);
  EXPECT_EQ(c.cell_size(0), 3);
  EXPECT_EQ(c.cell_region[0], 7);
  EXPECT_EQ(c.cell_entity[0], 3);
  EXPECT_EQ(c.coords, m.coords);
  EXPECT_TRUE(use_quadratic_shape(m));
  EXPECT_FALSE(use_quadratic_shape(c));
}

// A valid tri6 whose corner triangle is inverted (its bottom edge bulges far below the opposite
// corner): the barrier corner stage cannot include it, so it is held; the free vertex of its
// neighbour still moves and both cells stay certified.
TEST(QuadraticShape, ValidCellWithAnInvertedCornerCellIsHeld) {
  Mesh m;
  m.space_dim = 2;
  // 0, 1, 2: the thin cell's corners (clockwise), 3: the neighbour's free corner; mid nodes 4-8.
  const double x[][2] = {{0, 0},
                         {1, 0},
                         {0.5, -0.02},
                         {0.9, 0.5},
                         {0.50592843358, -0.20415890975},
                         {0.75419913964, -0.01822946770},
                         {0.38481096833, -0.14721855277},
                         {0.95, 0.25},
                         {0.7, 0.24}};
  for (const auto& p : x) m.add_vertex(p);
  const std::int32_t thin[] = {0, 1, 2, 4, 5, 6};
  const std::int32_t right[] = {2, 1, 3, 5, 7, 8};  // edge 2-1 shares mid node 5
  m.add_cell(CellType::kTri6, thin);
  m.add_cell(CellType::kTri6, right);
  double nodes[kMaxCellNodes * 3] = {};
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 2; ++k) nodes[3 * i + k] = m.vertex(thin[i])[k];
  const QuadraticCellMeasures thin_m = quadratic_cell_measures(CellType::kTri6, nodes);
  ASSERT_TRUE(thin_m.valid);
  ASSERT_LT(thin_m.corner, 0);
  const QualityReport before = compute_quality(m);
  ASSERT_EQ(before.inverted_cells, 0);
  const Mesh input = m;
  ShapeOptions opt;
  opt.solver.threads = 1;
  opt.fixed.assign(m.num_vertices(), 1);
  opt.fixed[3] = 0;  // only the neighbour's free corner moves; its mid nodes follow
  RecipeResult result;
  const Status s = improve_shape(&m, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 2; ++k) EXPECT_EQ(m.vertex(thin[i])[k], input.vertex(thin[i])[k]);
  EXPECT_NE(m.vertex(3)[0], input.vertex(3)[0]) << "the free corner should move";
  const QualityReport after = compute_quality(m);
  EXPECT_EQ(after.inverted_cells, 0);
  EXPECT_EQ(after.certified_cells, 2);
}

TEST(QuadraticShape, PolygonTri6StaysStraightAndNeverWorse) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh mesh;
  ASSERT_TRUE(gmsh_order2("polygon", kPolygon, 2, &mesh));
  ASSERT_GT(mesh.num_elements(), 200);
  const Mesh input = mesh;
  run_auto(&mesh);
  expect_never_worse(input, mesh, "polygon tri6");
  EXPECT_GT(expect_edges_kept(input, mesh, "polygon tri6"), 50) << "the corners should move";
  EXPECT_GT(summarize(mesh).at(CellType::kTri6).mean[0],
            summarize(input).at(CellType::kTri6).mean[0] + 1e-4)
      << "the corner mesh should improve";
}

TEST(QuadraticShape, BoxTet10StaysStraightAndNeverWorse) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh mesh;
  ASSERT_TRUE(gmsh_order2("box", kBox, 3, &mesh));
  ASSERT_GT(mesh.num_elements(), 100);
  const Mesh input = mesh;
  run_auto(&mesh);
  expect_never_worse(input, mesh, "box tet10");
  EXPECT_GT(expect_edges_kept(input, mesh, "box tet10"), 20) << "the corners should move";
  const auto a = summarize(mesh).at(CellType::kTet10), b = summarize(input).at(CellType::kTet10);
  EXPECT_GT(a.mean[0], b.mean[0] + 1e-4) << "the corner mesh should improve";
  EXPECT_GT(a.worst[0], b.worst[0]) << "the worst corner tet should improve";
}

// tmop_optimize hands its guarantee baseline of the quadratic input to the recipe
// (RecipeOptions::input_baseline): the result must be the one computed without it. The corner
// mesh's guard must not take it (it is of the quadratic cells: with it every corner cell
// "broke a guarantee" and t3 at order 2 came back unchanged).
TEST(QuadraticShape, TheCallersBaselineOfTheQuadraticInputChangesNothing) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh input;
  ASSERT_TRUE(gmsh_order2("box", kBox, 3, &input));
  const GuaranteeBaseline baseline = guarantee_baseline(input, 1);
  Mesh own = input, given = input;
  UntangleOptions opt;
  opt.solver.threads = 1;
  opt.shape.solver.threads = 1;
  RecipeResult a, b;
  ASSERT_TRUE(untangle(&own, opt, &a).ok());
  opt.shape.input_baseline = &baseline;
  ASSERT_TRUE(untangle(&given, opt, &b).ok());
  EXPECT_NE(own.coords, input.coords) << "the corner mesh should move";
  EXPECT_EQ(own.coords, given.coords);
}

TEST(QuadraticShape, Quad9AndHex27StayStraightAndNeverWorse) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh quads, hexes;
  ASSERT_TRUE(gmsh_order2("quads", std::string(kPolygon) + "Recombine Surface{1};\n", 2, &quads));
  ASSERT_TRUE(gmsh_order2("hexes", kHexBox, 3, &hexes));
  ASSERT_EQ(quads.cell_type(0), CellType::kQuad9);
  ASSERT_EQ(hexes.cell_type(0), CellType::kHex27);
  perturb_straight(&hexes, 0.06, 7);  // a quarter of the 0.25 spacing
  for (Mesh* mesh : {&quads, &hexes}) {
    const std::string label = cell_name(mesh->cell_type(0));
    const Mesh input = *mesh;
    run_auto(mesh);
    expect_never_worse(input, *mesh, label);
    EXPECT_GT(expect_edges_kept(input, *mesh, label), 10) << label << ": the corners should move";
    EXPECT_GT(summarize(*mesh).at(mesh->cell_type(0)).mean[0],
              summarize(input).at(mesh->cell_type(0)).mean[0] + 1e-4)
        << label << ": the corner mesh should improve";
  }
}

// Interior edges curved on purpose: straight ones stay straight, the curved ones follow their
// chords and then their nodes are relaxed by the curved-node stage, which must raise the det J
// ratio (the curvature is not needed here) without breaking any guarantee.
TEST(QuadraticShape, CurvedInteriorEdgesAreRelaxedStraightOnesStayStraight) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh mesh;
  ASSERT_TRUE(gmsh_order2("polygon_curved", kPolygon, 2, &mesh));
  const std::vector<char> boundary = boundary_vertex_mask(mesh);
  // Push every 5th interior mid-edge node sideways by 3 % of its edge.
  const CellInfo& info = cell_info(CellType::kTri6);
  std::vector<char> done(mesh.num_vertices(), 0);
  int curved = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.cell(c)[info.edges[e][0]], b = mesh.cell(c)[info.edges[e][1]];
      const int m = mesh.cell(c)[3 + e];
      if (boundary[m] || done[m]) continue;
      done[m] = 1;
      if (m % 5) continue;
      const double tx = mesh.vertex(b)[0] - mesh.vertex(a)[0],
                   ty = mesh.vertex(b)[1] - mesh.vertex(a)[1];
      mesh.vertex(m)[0] += -0.03 * ty;
      mesh.vertex(m)[1] += 0.03 * tx;
      ++curved;
    }
  }
  ASSERT_GT(curved, 20);
  const Mesh input = mesh;
  const RecipeResult result = run_auto(&mesh);
  expect_never_worse(input, mesh, "curved polygon tri6");
  expect_edges_kept(input, mesh, "curved polygon tri6");
  EXPECT_TRUE(std::any_of(result.stages.begin(), result.stages.end(), [](const StageResult& s) {
    return s.name.find("curved nodes") != std::string::npos;
  }));
  EXPECT_GT(summarize(mesh).at(CellType::kTri6).mean[2],
            summarize(input).at(CellType::kTri6).mean[2] + 1e-4)
      << "the det J ratio should rise";
  const auto d0 = edge_deviation(input), d1 = edge_deviation(mesh);
  int less_curved = 0;
  for (const auto& [e, dev] : d0) less_curved += dev > 1e-3 && d1.at(e) < dev;
  EXPECT_GT(less_curved, curved / 2) << "most curved edges should straighten";
}

// Triangles extruded in layers without recombination (3 tets per prism: a narrow dihedral
// range, 14.1..133.0 deg here) under a layer of wedges, like Gmsh's t3. The corner mesh's guard
// sees tet4 guarantees only; the first solve leaves some tets outside the tet10 dihedral range.
// Holding them and solving again from the input found new ones each round (5 corner solves,
// tet10 corner mean ratio mean 0.8119); the violators are stepped back over rings of
// neighbours instead (quadratic_guard.h) and the next round starts there (0.8132 in 4 corner
// solves; with the linear guard's vertex repair, recipes/vertex_moves.h, the rounds keep
// gaining: 0.8137 in 5). The criterion is the mean, which the old cascade did not reach.
const char kExtrudedTets[] =
    "lc = 0.12;\n"
    "Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc / 3};\n"
    "Point(4) = {0, 1, 0, lc};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
    "a[] = Extrude {0, 0, 0.4} { Surface{1}; Layers{4}; };\n"
    "b[] = Extrude {0, 0, 0.3} { Surface{a[0]}; Layers{3}; Recombine; };\n"
    "Physical Volume(1) = {a[1], b[1]};\n";

TEST(QuadraticShape, ExtrudedTetsOutsideTheirDihedralRangeAreSteppedBack) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh mesh;
  ASSERT_TRUE(gmsh_order2("extruded", kExtrudedTets, 3, &mesh));
  ASSERT_GT(mesh.num_elements(), 3000);
  const Mesh input = mesh;
  const RecipeResult result = run_auto(&mesh);
  expect_never_worse(input, mesh, "extruded tet10 + wedge18");
  expect_edges_kept(input, mesh, "extruded tet10 + wedge18");
  int stepped = 0;
  for (const StageResult& s : result.stages)
    stepped += s.termination.find("stepped back towards the round's start") != std::string::npos;
  EXPECT_GT(stepped, 0) << "the violators should be stepped back";
  const auto a = summarize(mesh).at(CellType::kTet10), b = summarize(input).at(CellType::kTet10);
  EXPECT_GT(a.mean[0], b.mean[0] + 0.048) << "the corner tets should improve (before: +0.047)";
}

// A curved boundary: with the boundary fixed every boundary node stays where it is; sliding,
// the mid nodes stay on the boundary (the polyline through the input's boundary nodes: within
// the sagitta of its segments, (h / 2)^2 / 8 = 1.25e-3 of the radius for h = 0.2). Both stay
// certified valid.
TEST(QuadraticShape, DiskTri6StaysCertifiedWithItsBoundaryOnTheCircle) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh disk;
  ASSERT_TRUE(gmsh_order2("disk", kDisk, 2, &disk));
  const std::vector<char> boundary = boundary_vertex_mask(disk);
  for (bool slide : {false, true}) {
    Mesh mesh = disk;
    UntangleOptions opt;
    opt.solver.threads = 1;
    opt.slide = slide;
    RecipeResult result;
    const Status s = untangle(&mesh, opt, &result);
    ASSERT_TRUE(s.ok()) << s.message();
    const std::string label = slide ? "disk tri6 sliding" : "disk tri6 fixed";
    expect_never_worse(disk, mesh, label);
    expect_edges_kept(disk, mesh, label);
    EXPECT_EQ(result.uncertified, 0);
    double off = 0;
    int boundary_moved = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      if (!boundary[v]) continue;
      off = std::max(off, std::abs(std::hypot(mesh.vertex(v)[0], mesh.vertex(v)[1]) - 1));
      boundary_moved +=
          mesh.vertex(v)[0] != disk.vertex(v)[0] || mesh.vertex(v)[1] != disk.vertex(v)[1];
    }
    if (slide) {
      EXPECT_LT(off, 1.5e-3) << label;
    } else {
      EXPECT_EQ(boundary_moved, 0) << label;
    }
    std::printf("%s: %d boundary nodes moved, farthest %.2e off the circle\n", label.c_str(),
                boundary_moved, off);
  }
}

// A sphere (r 0.55) cut out of a box, tet10 with the sphere's mid nodes on it and every interior
// edge straight (1,070 cells, valid): the curving stage spreads the sphere's curvature into the
// tets next to it. Every guarantee holds (the power objective lowered the det J ratio's and the
// pointwise mean ratio's means here, so the stage takes the plain mean); straight edges away from
// the sphere stay straight; the det J ratio worst reaches more than Gmsh 4.8's HighOrderElastic
// on this mesh (0.532, while it lowers the pointwise mean ratio's mean 0.784 -> 0.781). Main
// before the curving stage: 0.414.
TEST(QuadraticShape, SphereInABoxTet10CurvesNextToTheSphere) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh input;
  ASSERT_TRUE(gmsh_order2("sphere_box",
                          "SetFactory(\"OpenCASCADE\");\nBox(1) = {-1, -1, -1, 2, 2, 2};\n"
                          "Sphere(2) = {0, 0, 0, 0.55};\n"
                          "BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
                          "Mesh.CharacteristicLengthMax = 0.6;\n",
                          3, &input));
  Mesh mesh = input;
  run_auto(&mesh);
  expect_never_worse(input, mesh, "sphere in a box tet10");
  expect_edges_kept(input, mesh, "sphere in a box tet10");
  double worst = 1;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, 3)) continue;
    double nodes[10 * 3];
    for (int i = 0; i < 10; ++i)
      for (int a = 0; a < 3; ++a) nodes[3 * i + a] = mesh.vertex(mesh.cell(c)[i])[a];
    worst = std::min(worst, quadratic_cell_measures(mesh.cell_type(c), nodes).det_ratio);
  }
  std::printf("sphere in a box tet10: det J ratio worst %.3f\n", worst);
  EXPECT_GT(worst, 0.6);
  GuaranteeOptions g;
  for (const GuaranteeViolation& v :
       check_guarantees(guarantee_baseline(input, 1), guarantee_values(mesh, 1), g))
    ADD_FAILURE() << v.message();
}

}  // namespace
}  // namespace tmop
