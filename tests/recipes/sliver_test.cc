// The sliver recipe on the bundled part mesh (51 slivers among 5902 tets after a random
// perturbation): no sliver left, nothing inverted, and tets away from the slivers keep their
// volume (the second term holds them to their initial Jacobians). On the acceptance mesh
// (a 10-layer anisotropic boundary layer under a far field with slivers, made by gmsh from
// tests/data/geo/boundary_layer_slivers.geo): no sliver left, the layer's cells keep max
// dihedral <= 110 deg and their volumes within 5 %, nothing inverted, the boundary slides on
// its planes; and why the recipe holds the layer's outer surface.
#include "tmop/recipes/sliver.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "recipe_test_meshes.h"
#include "tmop/io/mesh_io.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/quality_report.h"

namespace tmop {
namespace {

double tet_volume(const Mesh& m, int c) {
  const double* p[4];
  for (int i = 0; i < 4; ++i) p[i] = m.vertex(m.cell(c)[i]);
  double u[3], v[3], w[3];
  for (int a = 0; a < 3; ++a) {
    u[a] = p[1][a] - p[0][a];
    v[a] = p[2][a] - p[0][a];
    w[a] = p[3][a] - p[0][a];
  }
  return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
          u[2] * (v[0] * w[1] - v[1] * w[0])) /
         6;
}

TEST(SliverRecipe, RemovesSliversAndKeepsTheRest) {
  Mesh input;
  ASSERT_TRUE(read_mesh(TMOP_SOURCE_DIR "/data/part_perturbed.msh", &input).ok());
  const QualityReport before = compute_quality(input);
  ASSERT_GT(before.slivers, 10);
  Mesh mesh = input;
  SliverOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  Status s = remove_slivers(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  const QualityReport after = compute_quality(mesh);
  EXPECT_EQ(after.slivers, 0);
  EXPECT_EQ(after.inverted_cells, 0);
  // No boundary layer here: the 25 stretched tets come in groups of at most 4, not a layer.
  EXPECT_EQ(result.layer_cells, 0);

  // Tets with no vertex on a tet whose initial max dihedral exceeds 135 degrees (where c_k >= 1/2)
  // keep their volume.
  std::vector<char> near(input.num_vertices(), 0);
  std::vector<double> max_dihedral(input.num_cells(), 0);
  for (int c = 0; c < input.num_cells(); ++c) {
    if (input.cell_type(c) != CellType::kTet4) continue;
    double x[12];
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 3; ++a) x[3 * i + a] = input.vertex(input.cell(c)[i])[a];
    max_dihedral[c] = cell_quality(CellType::kTet4, x, nullptr).max_dihedral_deg;
    if (max_dihedral[c] > 135)
      for (int i = 0; i < 4; ++i) near[input.cell(c)[i]] = 1;
  }
  int far = 0, kept = 0;
  for (int c = 0; c < input.num_cells(); ++c) {
    if (input.cell_type(c) != CellType::kTet4) continue;
    bool is_far = true;
    for (int i = 0; i < 4; ++i) is_far &= !near[input.cell(c)[i]];
    if (!is_far) continue;
    ++far;
    kept += std::abs(tet_volume(mesh, c) / tet_volume(input, c) - 1) <= 0.05;
  }
  std::printf(
      "sliver: %lld -> %lld slivers, dihedral %.2f..%.2f -> %.2f..%.2f; %d of %d tets "
      "away from slivers keep their volume within 5%%\n",
      static_cast<long long>(before.slivers), static_cast<long long>(after.slivers),
      before.min_dihedral.min, before.max_dihedral.max, after.min_dihedral.min,
      after.max_dihedral.max, kept, far);
  ASSERT_GT(far, 100);
  // Measured 443 of 496 (89 %) with the keep term at the seed's magnitude; 368 (74 %) with half
  // of it (the barrier form |T2 - I|^2 / (2 det T2) unscaled).
  EXPECT_GE(kept, 0.7 * far);
}

// The acceptance mesh, made once per test binary by the gmsh program (nullptr without gmsh).
const Mesh* boundary_layer_mesh() {
  static Mesh mesh;
  static bool tried = false, ok = false;
  if (!tried) {
    tried = true;
    if (!testing_recipes::have_gmsh()) return nullptr;
    char dir[] = "/tmp/tmop_sliver_bl_XXXXXX";
    if (mkdtemp(dir) == nullptr) return nullptr;
    const std::string msh = std::string(dir) + "/bl.msh";
    ok = testing_recipes::exit_code("gmsh -3 '" TMOP_SOURCE_DIR
                                    "/tests/data/geo/boundary_layer_slivers.geo' -format msh41 "
                                    "-o '" +
                                    msh + "' > /dev/null 2>&1") == 0 &&
         read_mesh(msh, &mesh).ok();
    testing_recipes::exit_code("rm -rf '" + std::string(dir) + "'");
    if (ok) mesh.remove_lower_dimensional_cells();
  }
  return ok ? &mesh : nullptr;
}

constexpr int kLayerRegion = 1;  // Physical Volume("boundary_layer", 1) in the .geo

CellQuality tet_quality(const Mesh& m, int c) {
  double x[12];
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) x[3 * i + a] = m.vertex(m.cell(c)[i])[a];
  return cell_quality(CellType::kTet4, x, nullptr);
}

// The acceptance measures of `after` against the generated mesh `before` (same cells); the
// layer's cells are those of region 1 in `before`, whatever tags the run saw.
struct LayerAcceptance {
  long long slivers = 0, inverted = 0;
  int layer_cells = 0;
  double layer_min_dihedral = 180, layer_max_dihedral = 0;
  int layer_volume_outside_5pct = 0;
  double layer_max_volume_change = 0;  // max |V / V0 - 1|
  int boundary_vertices = 0, boundary_slid = 0;
  double boundary_max_off_plane = 0;  // distance from the box face a vertex started on
};

LayerAcceptance measure_layer(const Mesh& before, const Mesh& after) {
  LayerAcceptance r;
  const QualityReport q = compute_quality(after);
  r.slivers = q.slivers;
  r.inverted = q.inverted_cells;
  for (int c = 0; c < after.num_cells(); ++c) {
    if (after.cell_type(c) != CellType::kTet4 || before.cell_region[c] != kLayerRegion) continue;
    ++r.layer_cells;
    const CellQuality cq = tet_quality(after, c);
    r.layer_min_dihedral = std::min(r.layer_min_dihedral, cq.min_dihedral_deg);
    r.layer_max_dihedral = std::max(r.layer_max_dihedral, cq.max_dihedral_deg);
    const double change = std::abs(tet_volume(after, c) / tet_volume(before, c) - 1);
    r.layer_max_volume_change = std::max(r.layer_max_volume_change, change);
    r.layer_volume_outside_5pct += change > 0.05;
  }
  // The box's faces: vertices that started on one stay on it.
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int v = 0; v < before.num_vertices(); ++v)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], before.vertex(v)[a]);
      hi[a] = std::max(hi[a], before.vertex(v)[a]);
    }
  for (int v = 0; v < before.num_vertices(); ++v) {
    bool on = false;
    double moved = 0;
    for (int a = 0; a < 3; ++a) {
      const double x0 = before.vertex(v)[a], x1 = after.vertex(v)[a];
      moved = std::max(moved, std::abs(x1 - x0));
      for (double plane : {lo[a], hi[a]})
        if (x0 == plane) {
          on = true;
          r.boundary_max_off_plane = std::max(r.boundary_max_off_plane, std::abs(x1 - plane));
        }
    }
    r.boundary_vertices += on;
    r.boundary_slid += on && moved > 1e-6;
  }
  return r;
}

void print_layer(const char* label, const LayerAcceptance& a) {
  std::printf(
      "%s: %lld slivers, %lld inverted; layer (%d tets) dihedral %.3f..%.3f, volume change max "
      "%.2e, %d outside 5%%; %d of %d box-face vertices slid, max off their face %.1e\n",
      label, a.slivers, a.inverted, a.layer_cells, a.layer_min_dihedral, a.layer_max_dihedral,
      a.layer_max_volume_change, a.layer_volume_outside_5pct, a.boundary_slid, a.boundary_vertices,
      a.boundary_max_off_plane);
}

// The acceptance for recipe sliver, on the generated mesh (fixture checked first).
void expect_acceptance(bool keep_region_tags) {
  const Mesh* generated = boundary_layer_mesh();
  if (generated == nullptr) GTEST_SKIP() << "no gmsh";
  const LayerAcceptance input = measure_layer(*generated, *generated);
  print_layer("input", input);
  // The fixture is the mesh: a 10-layer anisotropic layer (min dihedral ~1 deg, max
  // <= 108) under a far field with slivers, small enough for a test.
  ASSERT_GT(input.layer_cells, 5000);
  ASSERT_LT(generated->num_elements(), 20000);
  ASSERT_LT(input.layer_min_dihedral, 2);
  ASSERT_LE(input.layer_max_dihedral, 108);
  ASSERT_GE(input.slivers, 20);

  Mesh mesh = *generated;
  if (!keep_region_tags) {  // one region: the layer must be recognised from the cells alone
    std::fill(mesh.cell_region.begin(), mesh.cell_region.end(), 0);
    std::fill(mesh.cell_entity.begin(), mesh.cell_entity.end(), 0);
  }
  SliverOptions opt;  // the defaults: boundary vertices slide on their geometry
  opt.solver.threads = 1;
  RecipeResult result;
  const auto start = std::chrono::steady_clock::now();
  const Status s = remove_slivers(&mesh, opt, &result);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(s.ok()) << s.message();
  const LayerAcceptance after = measure_layer(*generated, mesh);
  print_layer("sliver", after);
  std::printf("%d layer cells found, %d vertices held, %.2f s\n", result.layer_cells,
              result.held_vertices, seconds);

  EXPECT_EQ(after.slivers, 0);
  EXPECT_EQ(after.inverted, 0);
  EXPECT_LE(after.layer_max_dihedral, 110);
  EXPECT_EQ(after.layer_volume_outside_5pct, 0);  // every layer tet within 5 %
  // Boundary vertices slid on their planes (the default), and stayed on them.
  EXPECT_GT(after.boundary_slid, 50);
  EXPECT_LT(after.boundary_max_off_plane, 1e-9);
  // The recipe found the layer: all of region 1 and nothing else (measured separation on this
  // mesh: longest/shortest edge >= 3.41 in the layer, <= 2.63 in the far field).
  EXPECT_EQ(result.layer_cells, input.layer_cells);
}

TEST(SliverRecipe, BoundaryLayerMeshAcceptance) { expect_acceptance(true); }

// The same mesh as one region (no physical or entity tags, as .vtk files and many solvers' meshes
// come): the layer is recognised by its stretched cells, not by a region interface.
TEST(SliverRecipe, BoundaryLayerMeshAcceptanceWithoutRegionTags) { expect_acceptance(false); }

// The seed's objective F = sum_k c_k mu_304(T1) + (1 - c_k) |T2 - I|^2 of `mesh` (tets), with
// c_k and W2 from `input`.
double seed_objective(const Mesh& input, const Mesh& mesh) {
  // Columns: edges from corner 0 of the regular tet of unit edge.
  const double s3 = std::sqrt(3.0);
  const Eigen::Matrix3d w1 =
      (Eigen::Matrix3d() << 1, 0.5, 0.5, 0, s3 / 2, s3 / 6, 0, 0, std::sqrt(2.0 / 3)).finished();
  auto jacobian = [](const Mesh& m, int c) {
    Eigen::Matrix3d a;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        a(i, j) = m.vertex(m.cell(c)[j + 1])[i] - m.vertex(m.cell(c)[0])[i];
    return a;
  };
  SliverOptions defaults;
  double f = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_type(c) != CellType::kTet4) continue;
    const double d = tet_quality(input, c).max_dihedral_deg;
    const double ck = 1 / (1 + std::exp(-defaults.steepness * (d - defaults.threshold_deg)));
    const Eigen::Matrix3d a = jacobian(mesh, c);
    const Eigen::Matrix3d t1 = a * w1.inverse(), t2 = a * jacobian(input, c).inverse();
    const double mu304 = std::pow(t1.norm(), 3) / (3 * s3 * t1.determinant()) - 1;
    f += ck * mu304 + (1 - ck) * (t2 - Eigen::Matrix3d::Identity()).squaredNorm();
  }
  return f;
}

// Why the recipe holds the layer's outer surface: with every vertex free (layer_edge_ratio = 0)
// the seed's formula itself moves the layer. The minimiser reached from the input shears the
// layer's top cells, where slivers share vertices with them, and its F is lower than that of
// the mesh with the layer held: the intact layer is not a minimiser of F.
TEST(SliverRecipe, TheFormulaAloneMovesTheBoundaryLayer) {
  const Mesh* generated = boundary_layer_mesh();
  if (generated == nullptr) GTEST_SKIP() << "no gmsh";
  Mesh held = *generated, free = *generated;
  SliverOptions opt;
  opt.solver.threads = 1;
  RecipeResult result;
  ASSERT_TRUE(remove_slivers(&held, opt, &result).ok());
  opt.layer_edge_ratio = 0;
  ASSERT_TRUE(remove_slivers(&free, opt, &result).ok());
  EXPECT_EQ(result.held_vertices, 0);
  const LayerAcceptance a = measure_layer(*generated, free);
  print_layer("layer free", a);
  const double f0 = seed_objective(*generated, *generated),
               f_held = seed_objective(*generated, held), f_free = seed_objective(*generated, free);
  std::printf("seed F: input %.3f, layer held %.3f, layer free %.3f\n", f0, f_held, f_free);
  EXPECT_EQ(a.slivers, 0);
  EXPECT_GT(a.layer_volume_outside_5pct, 10);
  EXPECT_LT(f_free, f_held);
}

}  // namespace
}  // namespace tmop
