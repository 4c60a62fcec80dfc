// The shape recipe's guarantees on an unstructured gmsh hex mesh (a recombined annulus-like
// sector extruded in layers) and its perturbed copy: the worst element never gets worse (the
// minimum quality tmop_quality prints, here the scaled Jacobian) and nothing is folded at a
// corner, with the default corner rule and with centroid or Gauss sampling (where the barrier
// sees no corner: the stage guards the corners, SamplePointCost::set_guard).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "tests/recipes/recipe_test_meshes.h"
#include "tmop/quality/worst_quality.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

using testing_recipes::exit_code;
using testing_recipes::have_gmsh;

Mesh hex_sector() {
  // One directory per call: ctest runs the parameterised cases in parallel.
  char templ[] = "/tmp/tmop_shape_guard_XXXXXX";
  if (!mkdtemp(templ)) return Mesh();
  const std::string dir = std::string(templ) + "/";
  std::ofstream(dir + "h.geo")
      << "SetFactory(\"OpenCASCADE\");\n"
         "Disk(1) = {0, 0, 0, 1, 0.7};\n"
         "Disk(2) = {0.2, 0, 0, 0.3, 0.3};\n"
         "BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }\n"
         "Mesh.CharacteristicLengthMax = 0.12;\n"
         "Mesh.Algorithm = 6;\n"
         "Mesh.RecombinationAlgorithm = 3;\n"
         "Recombine Surface{1};\n"
         "Extrude {0, 0, 0.6} { Surface{1}; Layers{5}; Recombine; }\n";
  Mesh m;
  if (exit_code("gmsh -3 " + dir + "h.geo -o " + dir + "h.msh -format msh41 > /dev/null 2>&1") == 0)
    read_mesh(dir + "h.msh", &m);
  m.remove_lower_dimensional_cells();
  exit_code("rm -rf " + dir);
  return m;
}

// Interior vertices moved by `amount` of their shortest edge, each move kept only if no
// incident corner inverts.
void perturb(Mesh* m, double amount, unsigned seed) {
  const std::vector<char> boundary = boundary_vertex_mask(*m);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> shortest(m->num_vertices(), 1e300);
  for (const auto& e : mesh_edges(*m)) {
    double l2 = 0;
    for (int a = 0; a < 3; ++a) l2 += std::pow(m->vertex(e[0])[a] - m->vertex(e[1])[a], 2);
    shortest[e[0]] = std::min(shortest[e[0]], std::sqrt(l2));
    shortest[e[1]] = std::min(shortest[e[1]], std::sqrt(l2));
  }
  for (int v = 0; v < m->num_vertices(); ++v) {
    if (boundary[v]) continue;
    const std::vector<double> keep(m->vertex(v), m->vertex(v) + 3);
    for (int a = 0; a < 3; ++a) m->vertex(v)[a] += amount * shortest[v] * u(rng);
    if (measure_mesh(*m, SampleRule::kCorners).inverted > 0)
      std::copy(keep.begin(), keep.end(), m->vertex(v));
  }
}

class ShapeGuard : public ::testing::TestWithParam<SampleRule> {};

TEST_P(ShapeGuard, WorstElementNeverWorseAndNoCornerFolds) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  Mesh base = hex_sector();
  ASSERT_GT(base.num_cells(), 200);
  for (int variant = 0; variant < 2; ++variant) {
    Mesh mesh = base;
    if (variant == 1) perturb(&mesh, 0.3, 7);
    const double worst_before = worst_quality(mesh, 1);
    const std::vector<double> input = mesh.coords;
    ShapeOptions opt;
    opt.rule = GetParam();
    opt.solver.threads = 1;
    RecipeResult result;
    ASSERT_TRUE(improve_shape(&mesh, opt, &result).ok());
    const double worst_after = worst_quality(mesh, 1);
    std::printf("hex sector %s, %s: %d hexes, %zu solves, scaled Jacobian min %.4f -> %.4f\n",
                variant ? "perturbed" : "as meshed", sample_rule_name(GetParam()),
                mesh.num_elements(), result.stages.size(), worst_before, worst_after);
    EXPECT_GE(worst_after, worst_before - opt.guard_tolerance);
    EXPECT_EQ(measure_mesh(mesh, SampleRule::kCorners).inverted, 0);
    // The default rule sees every corner, so it moves the mesh (the guard may put the cells
    // that lose back, after the last stage's objective was taken); centroid and Gauss points do
    // not see the corners the scaled Jacobian measures, and the guard may keep the input there.
    if (GetParam() == SampleRule::kDefault)
      EXPECT_NE(mesh.coords, input);
    else
      EXPECT_LE(result.stages.back().final_objective,
                result.stages.front().initial_objective + 1e-12);
  }
}

INSTANTIATE_TEST_SUITE_P(Rules, ShapeGuard,
                         ::testing::Values(SampleRule::kDefault, SampleRule::kCentroid,
                                           SampleRule::kGauss),
                         [](const ::testing::TestParamInfo<SampleRule>& info) {
                           return std::string(sample_rule_name(info.param));
                         });

}  // namespace
}  // namespace tmop
