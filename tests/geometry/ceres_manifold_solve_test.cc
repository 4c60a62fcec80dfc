// The manifolds inside a real Ceres solve: pulling one sliding point towards a target off the
// geometry must end at the target's closest point of the geometry, with the point on the
// geometry throughout (manifold_ownership = DO_NOT_TAKE_OWNERSHIP, as the optimizer uses them).
#include <ceres/ceres.h>
#include <gtest/gtest.h>

#include <memory>

#include "tmop/geometry/polyline_manifold.h"
#include "tmop/geometry/sphere_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"

namespace tmop {
namespace {

struct PullTo {
  explicit PullTo(const double* t, int dim) : dim(dim) {
    for (int i = 0; i < dim; ++i) target[i] = t[i];
  }
  template <typename T>
  bool operator()(const T* x, T* r) const {
    for (int i = 0; i < dim; ++i) r[i] = x[i] - target[i];
    return true;
  }
  double target[3] = {0, 0, 0};
  int dim;
};

// Solves min |x - target|^2 with x on `m`, starting from x (updated in place).
void pull(const GeometryManifold& m, const double* target, double* x) {
  ceres::Problem::Options po;
  po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  const int dim = m.AmbientSize();
  ceres::CostFunction* cost =
      dim == 3 ? static_cast<ceres::CostFunction*>(
                     new ceres::AutoDiffCostFunction<PullTo, 3, 3>(new PullTo(target, 3)))
               : new ceres::AutoDiffCostFunction<PullTo, 2, 2>(new PullTo(target, 2));
  problem.AddResidualBlock(cost, nullptr, x);
  problem.SetManifold(x, const_cast<GeometryManifold*>(&m));
  ceres::Solver::Options options;
  options.max_num_iterations = 200;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
}

TEST(CeresManifoldSolve, SphereEndsAtTheRadialProjection) {
  const double c[3] = {1, 2, 3};
  SphereManifold sphere(c, 2);
  double x[3] = {3, 2, 3};
  const double target[3] = {1 + 3, 2 + 3, 3 - 1};  // direction (3, 3, -1)
  pull(sphere, target, x);
  // The objective is flat to second order at the minimum: Ceres stops at ~1e-8 from it.
  const double s = 2 / std::sqrt(19.0);
  EXPECT_NEAR(x[0], 1 + 3 * s, 1e-7);
  EXPECT_NEAR(x[1], 2 + 3 * s, 1e-7);
  EXPECT_NEAR(x[2], 3 - s, 1e-7);
  EXPECT_LE(sphere.Distance(x), 1e-14);
}

TEST(CeresManifoldSolve, PolylineSlidesAcrossVerticesToTheClosestPoint) {
  // An L-shaped open polyline in 2D; the target is closest to the vertical leg.
  PolylineManifold curve(2, {0, 0, 1, 0, 1, 1, 1, 2}, false);
  double x[2] = {0.1, 0};
  const double target[2] = {1.5, 1.3};
  pull(curve, target, x);
  EXPECT_NEAR(x[0], 1, 1e-12);
  EXPECT_NEAR(x[1], 1.3, 1e-9);
}

TEST(CeresManifoldSolve, TriangleSurfaceWalksToTheClosestPoint) {
  // A roof: two planes meeting at the ridge x = 1 (z = x on the left, z = 2 - x on the right).
  std::vector<double> v = {0, 0, 0, 1, 0, 1, 2, 0, 0, 0, 2, 0, 1, 2, 1, 2, 2, 0};
  std::vector<std::int32_t> t = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
  TriangleSurfaceManifold roof(v, t);
  double x[3] = {0.2, 0.5, 0.2};
  const double target[3] = {1.8, 1.2, 0.6};  // above the right plane
  pull(roof, target, x);
  // Closest point of z = 2 - x to the target: move along (1, 0, 1)/sqrt2 by ((x+z-2)/sqrt2).
  const double h = (1.8 + 0.6 - 2) / 2;
  EXPECT_NEAR(x[0], 1.8 - h, 1e-9);
  EXPECT_NEAR(x[1], 1.2, 1e-9);
  EXPECT_NEAR(x[2], 0.6 - h, 1e-9);
  EXPECT_LE(roof.Distance(x), 1e-14);
}

}  // namespace
}  // namespace tmop
