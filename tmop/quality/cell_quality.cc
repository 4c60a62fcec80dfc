#include "tmop/quality/cell_quality.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

#include "tmop/element/bezier.h"
#include "tmop/element/ideal_element.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/quality/corner_frames.h"
#include "tmop/quality/jacobian_certificate.h"

namespace tmop {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDegPerRad = 57.295779513082320876798154814105;
constexpr double kSqrt3 = 1.7320508075688772;

Vec3 node(const double* nodes, int i) { return Vec3(nodes + 3 * i); }

// The Jacobian measures of one T = A W^-1.
struct TMeasures {
  double det;
  double cond;        // |T| |T^-1| / d, +inf when det <= 0
  double mean_ratio;  // d det^(2/d) / |T|^2 with the sign of det
};

// with_mean_ratio: only the quadratic simplices need the pointwise mean ratio (a cbrt in 3D).
TMeasures measure_t(const Eigen::Matrix2d& t, bool with_mean_ratio) {
  TMeasures m;
  m.det = t.determinant();
  const double f2 = t.squaredNorm();
  // In 2D |adj T| = |T|, so |T| |T^-1| = |T|^2 / |det T|.
  // Both are bounded (AM-GM on the singular values); clamping removes round-off past the bound,
  // which would otherwise push ideal cells out of the top histogram bin.
  m.cond = m.det > 0 ? std::max(1.0, f2 / (2 * m.det)) : kInf;
  m.mean_ratio = with_mean_ratio && f2 > 0 ? std::min(1.0, 2 * m.det / f2) : 0;
  return m;
}

TMeasures measure_t(const Eigen::Matrix3d& t, bool with_mean_ratio) {
  // The rows of adj(T) are the cross products of T's columns: no division before the sign test.
  const Vec3 c0 = t.col(1).cross(t.col(2));
  const Vec3 c1 = t.col(2).cross(t.col(0));
  const Vec3 c2 = t.col(0).cross(t.col(1));
  TMeasures m;
  m.det = t.col(0).dot(c0);
  const double f2 = t.squaredNorm();
  const double a2 = c0.squaredNorm() + c1.squaredNorm() + c2.squaredNorm();
  m.cond = m.det > 0 ? std::max(1.0, std::sqrt(f2 * a2) / (3 * m.det)) : kInf;
  m.mean_ratio = with_mean_ratio && f2 > 0
                     ? std::min(1.0, 3 * std::copysign(std::cbrt(m.det * m.det), m.det) / f2)
                     : 0;
  return m;
}

// The two faces (indices into cell_info(kTet4).facets) that meet at each tet edge.
using TetEdgeFaces = std::array<std::array<int, 2>, 6>;
TetEdgeFaces build_tet_edge_faces() {
  const CellInfo& tet = cell_info(CellType::kTet4);
  TetEdgeFaces out{};
  for (int e = 0; e < 6; ++e) {
    int n = 0;
    for (int f = 0; f < 4; ++f) {
      int hits = 0;
      for (int k = 0; k < 3; ++k)
        hits += tet.facets[f].corners[k] == tet.edges[e][0] ||
                tet.facets[f].corners[k] == tet.edges[e][1];
      if (hits == 2) out[e][n++] = f;
    }
  }
  return out;
}

void tet_dihedral_angles(const double* nodes, CellQuality* q) {
  static const TetEdgeFaces edge_faces = build_tet_edge_faces();
  const CellFacet* facets = cell_info(CellType::kTet4).facets;
  Vec3 normal[4];
  for (int f = 0; f < 4; ++f) {
    const Vec3 a = node(nodes, facets[f].corners[0]);
    normal[f] =
        (node(nodes, facets[f].corners[1]) - a).cross(node(nodes, facets[f].corners[2]) - a);
  }
  // The interior angle rises with n1.n2 / (|n1| |n2|) (the facets' normals all point outward,
  // or all inward when inverted), so only the two extreme edges need an angle. atan2 keeps full
  // precision near 0 and 180 degrees, where acos would not.
  double inv_norm[4];
  for (int f = 0; f < 4; ++f) inv_norm[f] = 1 / normal[f].norm();
  int e_lo = 0, e_hi = 0;
  double c_lo = kInf, c_hi = -kInf;
  for (int e = 0; e < 6; ++e) {
    const int f1 = edge_faces[e][0], f2 = edge_faces[e][1];
    const double c = normal[f1].dot(normal[f2]) * inv_norm[f1] * inv_norm[f2];
    if (c < c_lo) c_lo = c, e_lo = e;
    if (c > c_hi) c_hi = c, e_hi = e;
  }
  auto angle = [&](int e) {
    const Vec3& n1 = normal[edge_faces[e][0]];
    const Vec3& n2 = normal[edge_faces[e][1]];
    return std::atan2(n1.cross(n2).norm(), -n1.dot(n2)) * kDegPerRad;
  };
  const double lo = angle(e_lo), hi = angle(e_hi);
  q->min_dihedral_deg = lo;
  q->max_dihedral_deg = hi;
}

// Newell normal of the corner polygon of a 2D cell (twice its area vector).
Vec3 polygon_normal(int num_corners, const double* nodes) {
  return num_corners == 3
             ? (node(nodes, 1) - node(nodes, 0)).cross(node(nodes, 2) - node(nodes, 0))
             : (node(nodes, 2) - node(nodes, 0)).cross(node(nodes, 3) - node(nodes, 1));
}

// Interior angles of the corner polygon; a corner turning against `normal` is reflex.
void polygon_angles(int num_corners, const double* nodes, const Vec3& normal, CellQuality* q) {
  double lo = kInf, hi = -kInf;
  for (int i = 0; i < num_corners; ++i) {
    const Vec3 x = node(nodes, i);
    const Vec3 e1 = node(nodes, (i + 1) % num_corners) - x;
    const Vec3 e2 = node(nodes, (i + num_corners - 1) % num_corners) - x;
    const Vec3 c = e1.cross(e2);
    double angle = std::atan2(std::copysign(c.norm(), c.dot(normal)), e1.dot(e2)) * kDegPerRad;
    if (angle < 0) angle += 360;
    lo = std::min(lo, angle);
    hi = std::max(hi, angle);
  }
  q->min_angle_deg = lo;
  q->max_angle_deg = hi;
}

// Projects a 2D cell onto its plane: p gets 2 coordinates per node in the right-handed frame
// (t1, t2, n).
void project_to_plane(int num_nodes, const double* nodes, const Vec3& n, double* p) {
  const Vec3 x0 = node(nodes, 0);
  const Vec3 t1 = n.unitOrthogonal();
  const Vec3 t2 = n.cross(t1);
  for (int i = 0; i < num_nodes; ++i) {
    const Vec3 r = node(nodes, i) - x0;
    p[2 * i] = r.dot(t1);
    p[2 * i + 1] = r.dot(t2);
  }
}

// The normal that orients a 2D cell: `up` when given, else the corners' Newell normal; a
// bow-tie quad has a zero Newell normal and is oriented by its first corner instead, so that it
// is measured in its own plane and shows up as inverted.
Vec3 plane_normal(int num_corners, const double* nodes, const double* up) {
  if (up != nullptr) return Vec3(up);
  double sum_l2 = 0;
  for (int i = 0; i < num_corners; ++i)
    sum_l2 += (node(nodes, (i + 1) % num_corners) - node(nodes, i)).squaredNorm();
  const Vec3 own = polygon_normal(num_corners, nodes);
  if (own.squaredNorm() > 1e-24 * sum_l2 * sum_l2) return own.normalized();
  const Vec3 corner =
      (node(nodes, 1) - node(nodes, 0)).cross(node(nodes, num_corners - 1) - node(nodes, 0));
  return corner.squaredNorm() > 0 ? Vec3(corner.normalized()) : Vec3(0, 0, 1);
}

template <int D>
using Mat = Eigen::Matrix<double, D, D>;
template <int D>
using RowMajorMap = Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>>;

// Corner-frame measures: scaled Jacobian always; det / condition number for linear types (once
// for simplices, whose T is the same at every corner).
template <int D>
void measure_corners(CellType type, const double* p, bool linear, bool simplex, CellQuality* q) {
  const CornerFrames& frames = corner_frames(type);
  double sj = kInf, min_det = kInf, cond = 0;
  for (int k = 0; k < frames.count; ++k) {
    const CornerFrame& f = frames.frame[k];
    Mat<D> e;
    double lengths2 = 1;  // product of squared lengths: one sqrt per frame
    for (int j = 0; j < D; ++j) {
      for (int i = 0; i < D; ++i) e(i, j) = p[D * f.ends[j] + i] - p[D * f.corner + i];
      lengths2 *= e.col(j).squaredNorm();
    }
    const double det = e.determinant();
    sj = std::min(sj, lengths2 > 0 ? det / (std::sqrt(lengths2) * f.ideal_scaled) : 0.0);
    if (linear && (k == 0 || !simplex)) {
      const TMeasures m = measure_t(Mat<D>(e * RowMajorMap<D>(f.ideal_inverse)), false);
      min_det = std::min(min_det, m.det);
      cond = std::max(cond, m.cond);
    }
  }
  q->scaled_jacobian = sj;
  if (linear) {
    q->min_det = min_det;
    q->condition_number = cond;
  }
}

// W^-1 of every type that has ideal_jacobian (row-major, d x d), computed once.
struct IdealInverses {
  double w_inv[kNumCellTypes][9];
};
IdealInverses build_ideal_inverses() {
  IdealInverses out{};
  for (int t = 0; t < kNumCellTypes; ++t) {
    const CellType type = static_cast<CellType>(t);
    const CellInfo& info = cell_info(type);
    if (info.order != 2 || info.dim < 2) continue;
    const double* w = ideal_jacobian(type);
    if (info.dim == 2) {
      Eigen::Map<Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(out.w_inv[t]) =
          RowMajorMap<2>(w).inverse();
    } else {
      Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(out.w_inv[t]) =
          RowMajorMap<3>(w).inverse();
    }
  }
  return out;
}

// Jacobian measures of a quadratic cell at its sample points and corners.
template <int D>
void measure_samples(CellType type, const double* p, const QualityOptions& options,
                     CellQuality* q) {
  static const IdealInverses inverses = build_ideal_inverses();
  const RowMajorMap<D> w_inv(inverses.w_inv[static_cast<int>(type)]);
  const bool simplex =
      cell_info(type).linear == CellType::kTri3 || cell_info(type).linear == CellType::kTet4;
  const std::vector<SamplePoint>& rule = sample_points(type, options.sample_rule);
  const bool rule_has_corners = options.sample_rule == SampleRule::kDefault ||
                                options.sample_rule == SampleRule::kCorners ||
                                options.sample_rule == SampleRule::kNodes;
  double min_det = kInf, cond = 0, mean_ratio = kInf;
  auto visit = [&](const std::vector<SamplePoint>& points) {
    for (const SamplePoint& s : points) {
      double a[D * D];
      cell_jacobian(type, p, D, s.xi, a);
      const TMeasures m = measure_t(Mat<D>(RowMajorMap<D>(a) * w_inv), simplex);
      min_det = std::min(min_det, m.det);
      cond = std::max(cond, m.cond);
      mean_ratio = std::min(mean_ratio, m.mean_ratio);
    }
  };
  visit(rule);
  if (!rule_has_corners) visit(sample_points(type, SampleRule::kCorners));
  q->min_det = min_det;
  q->condition_number = cond;
  if (simplex) q->mean_ratio = mean_ratio;
}

}  // namespace

CellQuality cell_quality(CellType type, const double* nodes, const double* up,
                         const QualityOptions& options) {
  CellQuality q;
  const CellInfo& info = cell_info(type);
  const int d = info.dim;
  if (d < 2) return q;
  // Extreme but valid scales: a cell 1e-310 across has squared edge lengths and det T below the
  // smallest double (it read as inverted with edge length 0), one 1e300 across overflows them
  // (inf edge lengths, infinite scaled Jacobians). Such a cell is measured scaled by a power of
  // two, which is exact, to about unit size; the size measures are scaled back. Cells within
  // 2^-100..2^100 are measured as they are, bit for bit.
  double scaled[kMaxCellNodes * 3];
  int exponent = 0;  // nodes = scaled * 2^exponent
  {
    double extent = 0;
    for (int i = 0; i < 3 * info.num_nodes; ++i) extent = std::max(extent, std::abs(nodes[i]));
    if (std::isfinite(extent) && extent > 0 && (extent < 0x1p-100 || extent > 0x1p100)) {
      exponent = std::ilogb(extent);
      for (int i = 0; i < 3 * info.num_nodes; ++i) scaled[i] = std::ldexp(nodes[i], -exponent);
      nodes = scaled;
    }
  }

  double lmin2 = kInf, lmax2 = 0, sum_l2 = 0;
  for (int e = 0; e < info.num_edges; ++e) {
    const double l2 = (node(nodes, info.edges[e][1]) - node(nodes, info.edges[e][0])).squaredNorm();
    lmin2 = std::min(lmin2, l2);
    lmax2 = std::max(lmax2, l2);
    sum_l2 += l2;
  }
  q.min_edge_length = std::sqrt(lmin2);
  q.max_edge_length = std::sqrt(lmax2);

  // Coordinates in the cell's own dimension: 3D cells as they are, 2D cells in their plane.
  double projected[kMaxCellNodes * 2];
  const double* p = nodes;
  if (d == 2) {
    const Vec3 own = polygon_normal(info.num_corners, nodes);
    if (options.angles) polygon_angles(info.num_corners, nodes, own, &q);
    project_to_plane(info.num_nodes, nodes, plane_normal(info.num_corners, nodes, up), projected);
    p = projected;
  } else if (info.linear == CellType::kTet4 && options.angles) {
    tet_dihedral_angles(nodes, &q);
  }

  const bool linear = info.order == 1;
  const bool simplex = info.linear == CellType::kTri3 || info.linear == CellType::kTet4;
  if (d == 2) {
    measure_corners<2>(type, p, linear, simplex, &q);
    if (!linear) measure_samples<2>(type, p, options, &q);
  } else {
    measure_corners<3>(type, p, linear, simplex, &q);
    if (!linear) measure_samples<3>(type, p, options, &q);
  }

  // Mean ratio of linear simplices by the edge formulas (T is constant; det T relative to the
  // ideal unit-edge element): tri 4 sqrt3 A / sum l^2, tet 12 (3V)^(2/3) / sum l^2, signed.
  if (type == CellType::kTri3) {
    const double area = q.min_det * (kSqrt3 / 4);  // ideal triangle area sqrt3/4
    q.mean_ratio = sum_l2 > 0 ? std::min(1.0, 4 * kSqrt3 * area / sum_l2) : 0;
  } else if (type == CellType::kTet4) {
    const double three_v = q.min_det * (1 / (2 * 1.4142135623730951));  // 3V, ideal V = 1/(6 sqrt2)
    q.mean_ratio =
        sum_l2 > 0
            ? std::min(1.0, 12 * std::copysign(std::cbrt(three_v * three_v), three_v) / sum_l2)
            : 0;
  }

  q.inverted = !(q.min_det > 0);
  if (exponent != 0) {  // back to the cell's size (0 or inf where a double cannot hold it)
    q.min_edge_length = std::ldexp(q.min_edge_length, exponent);
    q.max_edge_length = std::ldexp(q.max_edge_length, exponent);
  }
  if (type == CellType::kTri3 || type == CellType::kTet4 || type == CellType::kQuad4) {
    // det J is constant (simplices) or affine in xi (the bilinear quad): the corners decide.
    q.certified = q.inverted ? 0 : 1;
  } else if (options.bezier_certificate && (type == CellType::kTri6 || type == CellType::kTet10)) {
    // The quadratic simplices count an unproven cell as inverted: their det J can dip below 0
    // between sample points, which is what the optimizer must never leave behind.
    // (A sample point already showing det <= 0 settles it without the certificate.)
    const JacobianSign sign = q.inverted ? JacobianSign::kNonPositive
                                         : certify_jacobian(type, p, options.bezier_subdivision);
    q.certified = sign == JacobianSign::kPositive ? 1 : 0;
    q.inverted = q.inverted || sign != JacobianSign::kPositive;
  } else if (options.bezier_certificate && options.certify_all_types &&
             jacobian_bezier_count(type) > 0) {
    // quad9 / hex8 / wedge6: the plain bound is reported but is too pessimistic to call cells
    // inverted.
    double coefficients[kMaxBezierCoefficients];
    const int n = jacobian_bezier_coefficients(type, p, coefficients);
    q.certified = std::all_of(coefficients, coefficients + n, [](double c) { return c > 0; });
  }
  if (exponent != 0) q.min_det = std::ldexp(q.min_det, d * exponent);
  return q;
}

void cell_plane_coordinates(CellType type, const double* nodes, const double* up, double* p) {
  const CellInfo& info = cell_info(type);
  project_to_plane(info.num_nodes, nodes, plane_normal(info.num_corners, nodes, up), p);
}

}  // namespace tmop
