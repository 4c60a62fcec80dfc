// The way optimize/ consumes BoundaryConstraints, end to end: a Ceres problem over the mesh's
// own coordinates (spring energy sum |x_a - x_b|^2 over the element edges), fixed vertices
// constant, sliding vertices with their manifolds (DO_NOT_TAKE_OWNERSHIP). After the solve every
// vertex is still on its geometry and the corners have not moved.
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <random>

#include "tests/geometry/geometry_test_meshes.h"
#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

struct Spring {
  template <typename T>
  bool operator()(const T* a, const T* b, T* r) const {
    for (int i = 0; i < 3; ++i) r[i] = a[i] - b[i];
    return true;
  }
};

// perturb > 0: first moves every sliding vertex by a random Plus step of that size (on its
// geometry), so that an equilibrium mesh (the hex grid) has something to undo.
void smooth_and_check(const std::string& name, const BoundaryOptions& options, double perturb) {
  Mesh mesh = testing_util::load_geometry_mesh(name);
  std::unique_ptr<BoundaryConstraints> bc;
  ASSERT_TRUE(BoundaryConstraints::Build(mesh, options, &bc).ok());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-perturb, perturb);
  for (int v = 0; v < mesh.num_vertices() && perturb > 0; ++v) {
    if (const ceres::Manifold* m = bc->manifold(v)) {
      const double d[2] = {u(rng), u(rng)};
      double y[3];
      ASSERT_TRUE(m->Plus(mesh.vertex(v), d, y));
      std::copy(y, y + 3, mesh.vertex(v));
    }
  }
  const Mesh original = mesh;
  ceres::Problem::Options po;
  po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  po.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  ceres::AutoDiffCostFunction<Spring, 3, 3, 3> spring(new Spring);
  for (const auto& e : mesh_edges(mesh)) {
    problem.AddResidualBlock(&spring, nullptr, mesh.vertex(e[0]), mesh.vertex(e[1]));
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!problem.HasParameterBlock(mesh.vertex(v))) continue;
    if (bc->fixed(v)) {
      problem.SetParameterBlockConstant(mesh.vertex(v));
    } else if (const ceres::Manifold* m = bc->manifold(v)) {
      // Ceres takes a non-const pointer but only calls const methods.
      problem.SetManifold(mesh.vertex(v), const_cast<ceres::Manifold*>(m));
    }
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  so.max_num_iterations = 10;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  EXPECT_LT(summary.final_cost, summary.initial_cost) << summary.BriefReport();
  // The perturbed hex grid: springs along planes and straight edges form a quadratic problem
  // whose minimum is the regular grid again (cost 9.375), up to the solver tolerance.
  if (perturb > 0) {
    EXPECT_NEAR(summary.final_cost, 9.375, 1e-6) << summary.BriefReport();
  }
  double moved = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const double* x = mesh.vertex(v);
    EXPECT_LE(bc->distance(v, x), 1e-13)
        << name << " vertex " << v << " " << vertex_kind_name(bc->kind(v));
    for (int i = 0; i < 3; ++i) moved = std::max(moved, std::fabs(x[i] - original.vertex(v)[i]));
  }
  EXPECT_GT(moved, 1e-3);  // the boundary vertices did slide
}

TEST(ConstrainedSmoothing, BoxHexStaysOnPlanesAndEdges) {
  smooth_and_check("box_hex.msh", {}, 0.05);
}

TEST(ConstrainedSmoothing, PartStaysOnItsOwnBoundaryAndTheAnalyticCavity) {
  BoundaryOptions options;
  options.feature_angle_deg = 40;
  smooth_and_check("part.msh", options, 0);
  options.geometry = "sphere:1.45,0.5,0.5,0.25";
  smooth_and_check("part.msh", options, 0);
}

}  // namespace
}  // namespace tmop
