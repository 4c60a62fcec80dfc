#include "tmop/optimize/stage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "grid_meshes.h"
#include "tmop/recipes/equal_edge.h"
#include "tmop/recipes/improve_shape.h"

namespace tmop {
namespace {

using testing_grid::grid;
using testing_grid::perturb;

double max_distance(const Mesh& a, const Mesh& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.coords.size(); ++i)
    worst = std::max(worst, std::abs(a.coords[i] - b.coords[i]));
  return worst;
}

StageSpec recovery_stage(const Mesh& reference) {
  StageSpec spec;
  TermSpec term;
  term.metric = std::shared_ptr<const Metric>(
      make_metric("size_shape_orientation", reference.space_dim).release());
  term.target.type = TargetType::kReference;
  term.target.reference = &reference;
  spec.terms.push_back(term);
  spec.solver.threads = 1;
  return spec;
}

class ExactRecovery : public ::testing::TestWithParam<CellType> {};

// Targets from the unperturbed grid and |T - I|^2: the unique minimiser is the grid itself.
TEST_P(ExactRecovery, ReturnsToTheUnperturbedGrid) {
  const int n = cell_dim(GetParam()) == 2 ? 6 : 3;
  const Mesh original = grid(GetParam(), n);
  Mesh mesh = original;
  std::mt19937 rng(7);
  perturb(&mesh, n, 0.3, &rng);
  ASSERT_GT(max_distance(mesh, original), 0.01 / n);
  StageResult result;
  ASSERT_TRUE(optimize_stage(&mesh, recovery_stage(original), &result).ok());
  EXPECT_LT(max_distance(mesh, original), 1e-8 / n) << result.termination;
  EXPECT_LT(result.final_objective, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Types, ExactRecovery,
                         ::testing::Values(CellType::kTri3, CellType::kQuad4, CellType::kTet4,
                                           CellType::kHex8),
                         [](const auto& info) { return std::string(cell_name(info.param)); });

// 1000 randomly perturbed small meshes, barrier shape improvement: nothing inverts and the
// objective never increases.
TEST(BarrierShape, NeverInvertsAndNeverIncreasesTheObjective) {
  std::mt19937 rng(2026);
  const CellType types[4] = {CellType::kTri3, CellType::kQuad4, CellType::kTet4, CellType::kHex8};
  int runs = 0;
  for (int trial = 0; trial < 250; ++trial) {
    for (CellType type : types) {
      const int n = cell_dim(type) == 2 ? 5 : 3;  // 16 and 8 free vertices
      Mesh mesh = grid(type, n);
      perturb(&mesh, n, 0.45, &rng);
      ShapeOptions opt;
      opt.solver.threads = 1;
      opt.solver.max_iterations = 50;
      RecipeResult result;
      ASSERT_TRUE(improve_shape(&mesh, opt, &result).ok());
      ++runs;
      EXPECT_EQ(measure_mesh(mesh, SampleRule::kDefault).inverted, 0);
      EXPECT_EQ(measure_mesh(mesh, SampleRule::kCorners).inverted, 0);
      for (const StageResult& st : result.stages)
        EXPECT_LE(st.final_objective, st.initial_objective * (1 + 1e-12));
    }
  }
  EXPECT_EQ(runs, 1000);
}

// The same mesh scaled by 1e-3 and 1e3, rotated and translated, gives the same result up to
// that transform: converged tightly, and with the default stopping rules (the stage solves in
// the mesh's principal-axes frame, so the transformed problems are the same to round-off).
class BarrierShapeInvariance : public ::testing::TestWithParam<bool> {};

TEST_P(BarrierShapeInvariance, ToScaleRotationAndTranslation) {
  const bool tight = GetParam();
  for (CellType type : {CellType::kTri3, CellType::kTet4, CellType::kHex8}) {
    const int d = cell_dim(type);
    const int n = d == 2 ? 5 : 3;
    Mesh base = grid(type, n);
    std::mt19937 rng(11);
    perturb(&base, n, 0.35, &rng);
    ShapeOptions opt;
    opt.solver.threads = 1;
    opt.solver.linear_solver = SolverOptions::LinearSolver::kSparseCholesky;
    if (tight) {
      opt.solver.function_tolerance = 0;  // converge on the gradient and movement rules
      opt.solver.objective_tolerance = 0;
      opt.solver.gradient_tolerance = 1e-13;
      opt.solver.movement_tolerance = 1e-13;
    }
    Mesh ref = base;
    RecipeResult result;
    ASSERT_TRUE(improve_shape(&ref, opt, &result).ok());
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (double scale : {1e-3, 1e3}) {
      Mesh m = base;
      auto transform = [&](const double* x, double* y) {
        if (d == 2) {
          y[0] = scale * (c * x[0] - s * x[1]) + 5;
          y[1] = scale * (s * x[0] + c * x[1]) - 3;
        } else {
          y[0] = scale * (c * x[0] - s * x[1]) + 5;
          y[1] = scale * (s * x[0] + c * x[1]) - 3;
          y[2] = scale * x[2] + 1;
        }
      };
      for (int v = 0; v < m.num_vertices(); ++v) transform(base.vertex(v), m.vertex(v));
      ASSERT_TRUE(improve_shape(&m, opt, &result).ok());
      double worst = 0;
      for (int v = 0; v < m.num_vertices(); ++v) {
        double y[3];
        transform(ref.vertex(v), y);
        for (int a = 0; a < d; ++a) {
          const double offset = a == 0 ? 5 : (a == 1 ? -3 : 1);
          worst = std::max(worst, std::abs((m.vertex(v)[a] - y[a])) / scale);
          (void)offset;
        }
      }
      EXPECT_LT(worst, 1e-8) << cell_name(type) << " scale " << scale
                             << (tight ? " tight" : " default tolerances");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Tolerances, BarrierShapeInvariance, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return std::string(info.param ? "Tight" : "Default");
                         });

TEST(BarrierShape, RefusesAnInvertedMeshNamingTheCells) {
  Mesh mesh = grid(CellType::kTri3, 4);
  // push the centre vertex across its neighbours
  const int centre = 2 + 5 * 2;
  mesh.vertex(centre)[0] += 0.6;
  ShapeOptions opt;
  RecipeResult result;
  const std::vector<double> before = mesh.coords;
  Status s = improve_shape(&mesh, opt, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("inverted cells"), std::string::npos) << s.message();
  EXPECT_EQ(mesh.coords, before);
}

TEST(BarrierShape, WorstElementDoesNotGetWorse) {
  std::mt19937 rng(5);
  for (CellType type : {CellType::kTri3, CellType::kTet4}) {
    const int n = cell_dim(type) == 2 ? 8 : 4;
    Mesh mesh = grid(type, n);
    perturb(&mesh, n, 0.45, &rng);
    ShapeOptions opt;
    RecipeResult result;
    ASSERT_TRUE(improve_shape(&mesh, opt, &result).ok());
    EXPECT_GE(result.after.min_quality, result.before.min_quality);
    EXPECT_EQ(result.after.inverted, 0);
  }
}

}  // namespace
}  // namespace tmop

namespace tmop {
namespace {

// Ceres's dogleg cannot run on CGNR: under the auto linear solver it gets sparse Cholesky at
// any size (here past the Cholesky size limits), and an explicit CGNR is refused in one line.
TEST(Dogleg, UsesSparseCholeskyUnderAutoAndRefusesCgnr) {
  const int n = 3;
  Mesh mesh = testing_grid::grid(CellType::kTet4, n);
  std::mt19937 rng(5);
  testing_grid::perturb(&mesh, n, 0.3, &rng);
  ShapeOptions opt;
  opt.solver.threads = 1;
  opt.solver.method = SolverOptions::Method::kDogleg;
  opt.solver.cholesky_max_free_coordinates_2d = 0;
  opt.solver.cholesky_max_free_coordinates_3d = 0;
  Mesh a = mesh;
  RecipeResult result;
  ASSERT_TRUE(improve_shape(&a, opt, &result).ok());
  ASSERT_FALSE(result.stages.empty());
  EXPECT_EQ(result.stages[0].linear_solver, "sparse_normal_cholesky");
  EXPECT_LT(result.stages[0].final_objective, result.stages[0].initial_objective);

  opt.solver.linear_solver = SolverOptions::LinearSolver::kCgnr;
  Mesh b = mesh;
  const Status s = improve_shape(&b, opt, &result);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("dogleg"), std::string::npos) << s.message();
  EXPECT_EQ(b.coords, mesh.coords);  // the mesh is left as it was
}

// The auto linear solver: sparse Cholesky up to kCholeskyMaxFreeCoordinates2d / 3d free
// coordinates, CGNR + Jacobi beyond (CHOLMOD loses from a few hundred on: solver_options.h);
// equal_edge keeps Cholesky up to its own, larger limits; a caller's limit wins over both.
TEST(AutoLinearSolver, CholeskyForSmallProblemsCgnrBeyondEqualEdgeLonger) {
  struct Case {
    CellType type;
    int n;              // grid cells per side: d (n - 1)^d free coordinates (boundary fixed)
    const char* shape;  // improve_shape's choice
    const char* equal;  // equal_edge's
  };
  // Free coordinates in the comments; the pairs bracket each limit.
  const Case cases[] = {
      {CellType::kTri3, 23, "sparse_normal_cholesky", "sparse_normal_cholesky"},  // 968
      {CellType::kTri3, 24, "cgnr_jacobi", "sparse_normal_cholesky"},             // 1,058
      {CellType::kTet4, 5, "sparse_normal_cholesky", "sparse_normal_cholesky"},   // 192
      {CellType::kTet4, 6, "cgnr_jacobi", "sparse_normal_cholesky"},              // 375
      {CellType::kTet4, 12, "cgnr_jacobi", "sparse_normal_cholesky"},             // 3,993
      {CellType::kTet4, 13, "cgnr_jacobi", "cgnr_jacobi"},                        // 5,184
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(cell_info(c.type).name) + " n = " + std::to_string(c.n));
    Mesh mesh = testing_grid::grid(c.type, c.n);
    std::mt19937 rng(7);
    testing_grid::perturb(&mesh, c.n, 0.2, &rng);
    ShapeOptions shape;
    shape.solver.threads = 1;
    shape.solver.max_iterations = 2;
    RecipeResult result;
    Mesh a = mesh;
    ASSERT_TRUE(improve_shape(&a, shape, &result).ok());
    ASSERT_FALSE(result.stages.empty());
    EXPECT_EQ(result.stages[0].linear_solver, c.shape);

    EqualEdgeOptions equal;
    equal.solver = shape.solver;
    Mesh b = mesh;
    ASSERT_TRUE(equal_edge(&b, equal, &result).ok());
    ASSERT_FALSE(result.stages.empty());
    EXPECT_EQ(result.stages[0].linear_solver, c.equal);

    // The caller's limits are kept, by both.
    equal.solver.cholesky_max_free_coordinates_2d = 0;
    equal.solver.cholesky_max_free_coordinates_3d = 0;
    Mesh e = mesh;
    ASSERT_TRUE(equal_edge(&e, equal, &result).ok());
    EXPECT_EQ(result.stages[0].linear_solver, "cgnr_jacobi");
    shape.solver.cholesky_max_free_coordinates_2d = 1 << 20;
    shape.solver.cholesky_max_free_coordinates_3d = 1 << 20;
    Mesh f = mesh;
    ASSERT_TRUE(improve_shape(&f, shape, &result).ok());
    EXPECT_EQ(result.stages[0].linear_solver, "sparse_normal_cholesky");
  }
}

}  // namespace
}  // namespace tmop
