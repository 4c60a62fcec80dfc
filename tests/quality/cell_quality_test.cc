// Checks each measure of cell_quality against an independent route written here: different
// formulas (Frobenius norm of A W^-1, face normals vs projected edges, law of cosines, shape
// functions vs corner edges), on random cells, to 1e-9 relative.
#include "tmop/quality/cell_quality.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;
const double kPi = 3.14159265358979323846;
const double kRegularDihedral = std::acos(1.0 / 3.0) * 180 / kPi;

void expect_rel(double expected, double actual, double tol = 1e-9) {
  EXPECT_NEAR(actual, expected, tol * std::max(1.0, std::abs(expected)));
}

// nodes as num_nodes x 3.
std::vector<double> flat(const std::vector<Vec3>& x) {
  std::vector<double> out;
  for (const Vec3& p : x) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

Vec3 random_point(std::mt19937& rng, double spread = 1) {
  std::uniform_real_distribution<double> u(-spread, spread);
  return Vec3(u(rng), u(rng), u(rng));
}

// A random, positively oriented tet.
std::vector<Vec3> random_tet(std::mt19937& rng) {
  for (;;) {
    std::vector<Vec3> x = {random_point(rng), random_point(rng), random_point(rng),
                           random_point(rng)};
    const double det = (x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0]));
    if (std::abs(det) < 1e-2) continue;
    if (det < 0) std::swap(x[1], x[2]);
    return x;
  }
}

const std::vector<Vec3> kRegularTet = {{0, 0, 0},
                                       {1, 0, 0},
                                       {0.5, std::sqrt(3.0) / 2, 0},
                                       {0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3.0)}};

TEST(CellQuality, IdealElementsScoreOne) {
  const double s3 = std::sqrt(3.0);
  struct Case {
    CellType type;
    std::vector<Vec3> x;
  };
  const std::vector<Case> cases = {
      {CellType::kTri3, {{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}}},
      {CellType::kQuad4, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}},
      {CellType::kTet4, kRegularTet},
      {CellType::kHex8,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},
      {CellType::kWedge6,
       {{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, s3 / 2, 1}}},
      {CellType::kPyramid5,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1 / std::sqrt(2.0)}}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(cell_name(c.type));
    // Scaled and moved: every measure is scale and translation invariant except min_det.
    std::vector<Vec3> x = c.x;
    for (Vec3& p : x) p = 3.0 * p + Vec3(1, 2, 3);
    const CellQuality q = cell_quality(c.type, flat(x).data(), nullptr);
    EXPECT_FALSE(q.inverted);
    expect_rel(1, q.scaled_jacobian, 1e-12);
    expect_rel(1, q.condition_number, 1e-12);
    const double volume_scale = cell_dim(c.type) == 2 ? 9 : 27;
    expect_rel(volume_scale, q.min_det, 1e-12);
    expect_rel(3, q.min_edge_length, 1e-12);
    if (c.type == CellType::kTri3 || c.type == CellType::kTet4) expect_rel(1, q.mean_ratio, 1e-12);
    if (c.type == CellType::kTri3) {
      expect_rel(60, q.min_angle_deg, 1e-12);
      expect_rel(60, q.max_angle_deg, 1e-12);
    }
    if (c.type == CellType::kQuad4) {
      expect_rel(90, q.min_angle_deg, 1e-12);
      expect_rel(90, q.max_angle_deg, 1e-12);
    }
    if (c.type == CellType::kTet4) {
      expect_rel(kRegularDihedral, q.min_dihedral_deg, 1e-12);
      expect_rel(kRegularDihedral, q.max_dihedral_deg, 1e-12);
    }
  }
}

TEST(CellQuality, StraightQuadraticSimplicesScoreOne) {
  // Mid-edge nodes at the midpoints of the ideal element: det J constant, certified.
  for (CellType type : {CellType::kTri6, CellType::kTet10}) {
    SCOPED_TRACE(cell_name(type));
    const CellInfo& info = cell_info(type);
    std::vector<Vec3> x;
    for (int i = 0; i < info.num_corners; ++i)
      x.push_back(type == CellType::kTri6 ? Vec3(i == 1, 0, 0) : kRegularTet[i]);
    if (type == CellType::kTri6) x[2] = Vec3(0.5, std::sqrt(3.0) / 2, 0);
    for (int e = 0; e < info.num_edges; ++e)
      x.push_back((x[info.edges[e][0]] + x[info.edges[e][1]]) / 2);
    const CellQuality q = cell_quality(type, flat(x).data(), nullptr);
    EXPECT_FALSE(q.inverted);
    EXPECT_EQ(q.certified, 1);
    expect_rel(1, q.mean_ratio, 1e-12);
    expect_rel(1, q.condition_number, 1e-12);
    expect_rel(1, q.scaled_jacobian, 1e-12);
  }
}

TEST(CellQuality, RandomTetsMatchIndependentFormulas) {
  std::mt19937 rng(7);
  // W: the regular tet's edges from corner 0 as columns.
  Eigen::Matrix3d w;
  for (int k = 0; k < 3; ++k) w.col(k) = kRegularTet[k + 1] - kRegularTet[0];
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Vec3> x = random_tet(rng);
    const CellQuality q = cell_quality(CellType::kTet4, flat(x).data(), nullptr);
    Eigen::Matrix3d a;
    for (int k = 0; k < 3; ++k) a.col(k) = x[k + 1] - x[0];
    const Eigen::Matrix3d t = a * w.inverse();
    // Mean ratio through the Frobenius norm of T instead of edge lengths.
    expect_rel(3 * std::pow(t.determinant(), 2.0 / 3.0) / t.squaredNorm(), q.mean_ratio);
    expect_rel(t.norm() * t.inverse().norm() / 3, q.condition_number);
    expect_rel(t.determinant(), q.min_det);
    // Scaled Jacobian: at corner i the three edges to the others, ordered by the parity of the
    // permutation (i, j, k, l) so that the determinant has the sign of the tet's volume.
    const int perms[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
    double sj = 1e300;
    for (const auto& p : perms) {
      const Vec3 e1 = x[p[1]] - x[p[0]], e2 = x[p[2]] - x[p[0]], e3 = x[p[3]] - x[p[0]];
      sj =
          std::min(sj, std::sqrt(2.0) * e1.dot(e2.cross(e3)) / (e1.norm() * e2.norm() * e3.norm()));
    }
    expect_rel(sj, q.scaled_jacobian);
    // Dihedral angles by the edge formula: the angle between the other two vertices projected
    // onto the plane normal to the edge.
    double lo = 1e300, hi = -1e300, lmin = 1e300, lmax = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        int others[2], n = 0;
        for (int k = 0; k < 4; ++k)
          if (k != i && k != j) others[n++] = k;
        const Vec3 axis = (x[j] - x[i]).normalized();
        Vec3 u = x[others[0]] - x[i], v = x[others[1]] - x[i];
        u -= u.dot(axis) * axis;
        v -= v.dot(axis) * axis;
        const double angle = std::acos(u.dot(v) / (u.norm() * v.norm())) * 180 / kPi;
        lo = std::min(lo, angle);
        hi = std::max(hi, angle);
        lmin = std::min(lmin, (x[j] - x[i]).norm());
        lmax = std::max(lmax, (x[j] - x[i]).norm());
      }
    }
    expect_rel(lo, q.min_dihedral_deg, 1e-8);
    expect_rel(hi, q.max_dihedral_deg, 1e-8);
    expect_rel(lmin, q.min_edge_length);
    expect_rel(lmax, q.max_edge_length);
  }
}

TEST(CellQuality, RandomTrianglesMatchIndependentFormulas) {
  std::mt19937 rng(11);
  Eigen::Matrix2d w;
  w << 1, 0.5, 0, std::sqrt(3.0) / 2;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> x = {random_point(rng), random_point(rng), random_point(rng)};
    for (Vec3& p : x) p.z() = 0;
    const double cross = (x[1] - x[0]).cross(x[2] - x[0]).z();
    if (std::abs(cross) < 1e-2) continue;
    const double up[3] = {0, 0, 1};
    const CellQuality q = cell_quality(CellType::kTri3, flat(x).data(), up);
    Eigen::Matrix2d a;
    a << x[1].x() - x[0].x(), x[2].x() - x[0].x(), x[1].y() - x[0].y(), x[2].y() - x[0].y();
    const Eigen::Matrix2d t = a * w.inverse();
    // Signed: a clockwise triangle is inverted against +z.
    EXPECT_EQ(q.inverted, cross < 0);
    expect_rel(2 * t.determinant() / t.squaredNorm(), q.mean_ratio);
    expect_rel(t.determinant(), q.min_det);
    if (cross > 0) expect_rel(t.norm() * t.inverse().norm() / 2, q.condition_number);
    // Angles by the law of cosines; scaled Jacobian = min sin(angle) * 2 / sqrt3, signed.
    double lo = 1e300, hi = -1e300, sj = 1e300;
    for (int i = 0; i < 3; ++i) {
      const double a2 = (x[(i + 1) % 3] - x[(i + 2) % 3]).squaredNorm();
      const double b2 = (x[i] - x[(i + 1) % 3]).squaredNorm();
      const double c2 = (x[i] - x[(i + 2) % 3]).squaredNorm();
      const double angle = std::acos((b2 + c2 - a2) / (2 * std::sqrt(b2 * c2)));
      lo = std::min(lo, angle * 180 / kPi);
      hi = std::max(hi, angle * 180 / kPi);
      sj = std::min(sj, std::copysign(std::sin(angle), cross) * 2 / std::sqrt(3.0));
    }
    expect_rel(lo, q.min_angle_deg, 1e-8);
    expect_rel(hi, q.max_angle_deg, 1e-8);
    expect_rel(sj, q.scaled_jacobian);
  }
}

// Random perturbations of the ideal element, compared with the Jacobian from the shape functions
// (element/shape.h) at the corners: a different route from the corner edge vectors.
TEST(CellQuality, PerturbedLinearCellsMatchShapeFunctionJacobians) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  const double s3 = std::sqrt(3.0);
  struct Case {
    CellType type;
    std::vector<Vec3> x;
    Eigen::Matrix3d w;  // reference-to-ideal Jacobian
  };
  Eigen::Matrix3d w_hex = Eigen::Matrix3d::Identity() / 2;
  Eigen::Matrix3d w_wedge;
  w_wedge << 1, 0.5, 0, 0, s3 / 2, 0, 0, 0, 0.5;
  const std::vector<Case> cases = {
      {CellType::kHex8,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
       w_hex},
      {CellType::kWedge6,
       {{0, 0, 0}, {1, 0, 0}, {0.5, s3 / 2, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, s3 / 2, 1}},
       w_wedge},
      {CellType::kQuad4, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, w_hex},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(cell_name(c.type));
    const int d = cell_dim(c.type);
    for (int trial = 0; trial < 50; ++trial) {
      std::vector<Vec3> x = c.x;
      for (Vec3& p : x) p += Vec3(u(rng), u(rng), d == 3 ? u(rng) : 0);
      const double up[3] = {0, 0, 1};
      const CellQuality q = cell_quality(c.type, flat(x).data(), up);
      std::vector<double> coords;
      for (const Vec3& p : x)
        for (int k = 0; k < d; ++k) coords.push_back(p[k]);
      double min_det = 1e300, cond = 0;
      for (const SamplePoint& s : sample_points(c.type, SampleRule::kCorners)) {
        double a[9];
        cell_jacobian(c.type, coords.data(), d, s.xi, a);
        if (d == 3) {
          const Eigen::Matrix3d t =
              Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(a) * c.w.inverse();
          min_det = std::min(min_det, t.determinant());
          cond = std::max(cond, t.norm() * t.inverse().norm() / 3);
        } else {
          const Eigen::Matrix2d t = Eigen::Map<Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(a) *
                                    c.w.topLeftCorner<2, 2>().inverse();
          min_det = std::min(min_det, t.determinant());
          cond = std::max(cond, t.norm() * t.inverse().norm() / 2);
        }
      }
      expect_rel(min_det, q.min_det);
      expect_rel(cond, q.condition_number);
      EXPECT_FALSE(q.inverted);
    }
  }
}

TEST(CellQuality, HexScaledJacobianIsMinOverCornersOfNormalisedEdges) {
  // A sheared cube: corner 0's edges (1,0,0), (s,1,0), (0,0,1) give sin of the shear angle.
  const double s = 0.5;
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1 + s, 1, 0}, {s, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1 + s, 1, 1}, {s, 1, 1}};
  const CellQuality q = cell_quality(CellType::kHex8, flat(x).data(), nullptr);
  expect_rel(1 / std::sqrt(1 + s * s), q.scaled_jacobian);
}

// docs/quality.md: a corner's det / prod |e| is in [-1, 1] and is divided by the ideal element's
// value there, so an inverted cell with a right corner reaches -1 / s_ideal: -2/sqrt3 for
// triangles and prisms, -sqrt2 for tets and pyramids, -1 for quads and hexes.
TEST(CellQuality, ScaledJacobianLowerBoundsAreReachedByMirroredRightCorners) {
  struct Case {
    CellType type;
    std::vector<Vec3> x;
    double lower;
  };
  const double s3 = 2 / std::sqrt(3.0), s2 = std::sqrt(2.0);
  const Case cases[] = {
      {CellType::kTri3, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}, -s3},
      {CellType::kQuad4, {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, -1},
      {CellType::kTet4, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, -s2},
      {CellType::kHex8,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, -1}, {1, 0, -1}, {1, 1, -1}, {0, 1, -1}},
       -1},
      {CellType::kWedge6,
       {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {1, 0, -1}, {0, 1, -1}},
       -s3},
      {CellType::kPyramid5, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, -1}}, -s2},
  };
  const double up[3] = {0, 0, 1};
  for (const Case& c : cases) {
    const CellQuality q = cell_quality(c.type, flat(c.x).data(), up);
    EXPECT_TRUE(q.inverted) << cell_name(c.type);
    EXPECT_NEAR(q.scaled_jacobian, c.lower, 1e-12) << cell_name(c.type);
  }
}

TEST(CellQuality, InvertedTetIsDetectedEverywhere) {
  std::vector<Vec3> x = kRegularTet;
  std::swap(x[1], x[2]);
  const CellQuality q = cell_quality(CellType::kTet4, flat(x).data(), nullptr);
  EXPECT_TRUE(q.inverted);
  EXPECT_EQ(q.certified, 0);
  expect_rel(-1, q.mean_ratio, 1e-12);
  expect_rel(-1, q.scaled_jacobian, 1e-12);
  EXPECT_TRUE(std::isinf(q.condition_number));
  expect_rel(kRegularDihedral, q.min_dihedral_deg, 1e-12);  // angles ignore orientation
}

TEST(CellQuality, InvertedHexCornerIsDetected) {
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  x[6] = Vec3(0.2, 0.2, 0.2);  // pushed through the opposite corner
  const CellQuality q = cell_quality(CellType::kHex8, flat(x).data(), nullptr);
  EXPECT_TRUE(q.inverted);
  EXPECT_LT(q.scaled_jacobian, 0);
  EXPECT_LT(q.min_det, 0);
}

TEST(CellQuality, DartQuadShowsAReflexAngle) {
  const std::vector<Vec3> x = {{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}};
  const double up[3] = {0, 0, 1};
  const CellQuality q = cell_quality(CellType::kQuad4, flat(x).data(), up);
  EXPECT_GT(q.max_angle_deg, 180);
  EXPECT_TRUE(q.inverted);  // det J < 0 at the reflex corner
}

TEST(CellQuality, Tri6FoldedInsideIsInvertedByTheBernsteinBound) {
  // det J > 0 at all six nodes (the default sample points) but about -0.32 inside.
  const std::vector<Vec3> x = {{0, 0, 0},        {1, 0, 0},       {0, 1, 0},
                               {0.72, -0.39, 0}, {0.23, 0.86, 0}, {0.27, 0.83, 0}};
  std::vector<double> coords;
  for (const Vec3& p : x) coords.insert(coords.end(), {p.x(), p.y()});
  for (const SamplePoint& s : sample_points(CellType::kTri6, SampleRule::kNodes)) {
    double a[4];
    cell_jacobian(CellType::kTri6, coords.data(), 2, s.xi, a);
    EXPECT_GT(a[0] * a[3] - a[1] * a[2], 0.3);
  }
  const double centroid[2] = {0.4, 0.3};
  double a[4];
  cell_jacobian(CellType::kTri6, coords.data(), 2, centroid, a);
  const double up[3] = {0, 0, 1};
  const CellQuality q = cell_quality(CellType::kTri6, flat(x).data(), up);
  EXPECT_GT(q.min_det, 0);  // no sample point sees it
  EXPECT_EQ(q.certified, 0);
  EXPECT_TRUE(q.inverted);
  QualityOptions sample_only;
  sample_only.bezier_certificate = false;
  EXPECT_FALSE(cell_quality(CellType::kTri6, flat(x).data(), up, sample_only).inverted);
}

TEST(CellQuality, SurfaceTriangleIsMeasuredInItsPlane) {
  // An equilateral triangle tilted in 3D, oriented by its own normal.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}};
  for (Vec3& p : x) p = r * p;
  const CellQuality q = cell_quality(CellType::kTri3, flat(x).data(), nullptr);
  EXPECT_FALSE(q.inverted);
  expect_rel(1, q.mean_ratio, 1e-12);
  expect_rel(1, q.scaled_jacobian, 1e-12);
  expect_rel(60, q.min_angle_deg, 1e-12);
}

TEST(CellQuality, BowTieSurfaceQuadIsInverted) {
  // Corners in crossing order: the Newell normal vanishes, the cell is still measured in its plane.
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.4, Vec3(1, -1, 2).normalized()).toRotationMatrix();
  std::vector<Vec3> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  for (Vec3& p : x) p = r * p;
  const CellQuality q = cell_quality(CellType::kQuad4, flat(x).data(), nullptr);
  EXPECT_TRUE(q.inverted);
  EXPECT_LT(q.scaled_jacobian, 0);
}

TEST(CellQuality, LowerDimensionalCellsAreNotMeasured) {
  const double x[6] = {0, 0, 0, 1, 0, 0};
  const CellQuality q = cell_quality(CellType::kLine2, x, nullptr);
  EXPECT_FALSE(q.inverted);
  EXPECT_TRUE(std::isnan(q.mean_ratio));
}

// The types without a Bernstein certificate (docs/quality.md, docs/formats.md: the serendipity
// types, wedge18, hex27 and the pyramids) report `certified` = NaN, not 1 or 0, even with every
// certificate option on; their validity is judged at their sample points. A valid cell (its
// reference nodes) is not inverted, and a cell with two corners swapped is.
TEST(CellQuality, TypesWithoutCertificateReportNaN) {
  QualityOptions o;
  o.bezier_certificate = true;
  o.certify_all_types = true;
  for (CellType type :
       {CellType::kQuad8, CellType::kHex20, CellType::kWedge15, CellType::kWedge18,
        CellType::kPyramid5, CellType::kPyramid13, CellType::kPyramid14, CellType::kHex27}) {
    SCOPED_TRACE(cell_name(type));
    const int n = cell_num_nodes(type);
    std::vector<double> x(3 * n, 0.0);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < cell_dim(type); ++k) x[3 * i + k] = reference_node(type, i)[k];
    const CellQuality q = cell_quality(type, x.data(), nullptr, o);
    EXPECT_TRUE(std::isnan(q.certified)) << q.certified;
    EXPECT_FALSE(q.inverted);
    std::swap_ranges(x.begin(), x.begin() + 3, x.begin() + 3);  // corners 0 and 1
    const CellQuality bad = cell_quality(type, x.data(), nullptr, o);
    EXPECT_TRUE(std::isnan(bad.certified));
    EXPECT_TRUE(bad.inverted);
  }
}

}  // namespace
}  // namespace tmop
