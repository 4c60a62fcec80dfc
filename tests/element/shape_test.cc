// Tests of tmop/element/shape.h: the shape functions of every cell type against properties any
// correct Lagrange basis must have, checked numerically.
#include "tmop/element/shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace tmop {
namespace {

constexpr CellType kAllTypes[] = {
    CellType::kVertex,   CellType::kLine2,     CellType::kLine3,    CellType::kTri3,
    CellType::kQuad4,    CellType::kTet4,      CellType::kHex8,     CellType::kWedge6,
    CellType::kPyramid5, CellType::kTri6,      CellType::kQuad9,    CellType::kTet10,
    CellType::kHex27,    CellType::kQuad8,     CellType::kHex20,    CellType::kWedge15,
    CellType::kWedge18,  CellType::kPyramid13, CellType::kPyramid14};

// A random point strictly inside the reference element (Gmsh's, see shape.h).
void RandomInterior(CellType type, std::mt19937* rng, double* xi) {
  std::uniform_real_distribution<double> u(0.05, 0.95), s(-0.9, 0.9);
  xi[0] = xi[1] = xi[2] = 0;
  switch (cell_info(type).linear) {
    case CellType::kVertex:
      return;
    case CellType::kLine2:
      xi[0] = s(*rng);
      return;
    case CellType::kQuad4:
      xi[0] = s(*rng), xi[1] = s(*rng);
      return;
    case CellType::kHex8:
      xi[0] = s(*rng), xi[1] = s(*rng), xi[2] = s(*rng);
      return;
    case CellType::kTri3:
    case CellType::kTet4:
    case CellType::kWedge6: {
      const int d = type == CellType::kTet4 || type == CellType::kTet10 ? 3 : 2;
      do {
        for (int j = 0; j < d; ++j) xi[j] = u(*rng);
      } while (xi[0] + xi[1] + xi[2] > 0.95);
      if (cell_info(type).linear == CellType::kWedge6) xi[2] = s(*rng);
      return;
    }
    case CellType::kPyramid5: {
      xi[2] = 0.9 * u(*rng);
      xi[0] = s(*rng) * (1 - xi[2]);
      xi[1] = s(*rng) * (1 - xi[2]);
      return;
    }
    default:
      FAIL() << "unexpected linear type";
  }
}

TEST(Shape, GradientMatchesCentralDifferences) {
  std::mt19937 rng(7);
  for (CellType t : kAllTypes) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    for (int trial = 0; trial < 20; ++trial) {
      double xi[3];
      RandomInterior(t, &rng, xi);
      double dN[kMaxCellNodes * 3];
      shape_gradients(t, xi, dN);
      const double h = 1e-6;
      for (int j = 0; j < d; ++j) {
        double xp[3] = {xi[0], xi[1], xi[2]}, xm[3] = {xi[0], xi[1], xi[2]};
        xp[j] += h;
        xm[j] -= h;
        double Np[kMaxCellNodes], Nm[kMaxCellNodes];
        shape_values(t, xp, Np);
        shape_values(t, xm, Nm);
        for (int i = 0; i < n; ++i)
          EXPECT_NEAR(dN[i * d + j], (Np[i] - Nm[i]) / (2 * h), 1e-7)
              << cell_name(t) << " node " << i << " direction " << j;
      }
    }
  }
}

TEST(Shape, PartitionOfUnity) {
  std::mt19937 rng(11);
  for (CellType t : kAllTypes) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    for (int trial = 0; trial < 20; ++trial) {
      double xi[3], N[kMaxCellNodes], dN[kMaxCellNodes * 3];
      RandomInterior(t, &rng, xi);
      shape_values(t, xi, N);
      shape_gradients(t, xi, dN);
      double sum = 0, gsum[3] = {0, 0, 0};
      for (int i = 0; i < n; ++i) {
        sum += N[i];
        for (int j = 0; j < d; ++j) gsum[j] += dN[i * d + j];
      }
      EXPECT_NEAR(sum, 1.0, 1e-13) << cell_name(t);
      for (int j = 0; j < d; ++j) EXPECT_NEAR(gsum[j], 0.0, 1e-12) << cell_name(t);
    }
  }
}

TEST(Shape, KroneckerAtNodes) {
  for (CellType t : kAllTypes) {
    const int n = cell_num_nodes(t);
    for (int j = 0; j < n; ++j) {
      double N[kMaxCellNodes];
      shape_values(t, reference_node(t, j), N);
      for (int i = 0; i < n; ++i)
        EXPECT_NEAR(N[i], i == j ? 1.0 : 0.0, 1e-14) << cell_name(t) << " N" << i << " at " << j;
    }
  }
}

// Every basis here contains the linear polynomials: sum_i f(node_i) N_i = f for f linear, and the
// gradient of the interpolant is f's gradient.
TEST(Shape, ReproducesLinearFields) {
  std::mt19937 rng(3);
  const double c0 = 0.7, c[3] = {1.3, -2.1, 0.4};
  for (CellType t : kAllTypes) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    for (int trial = 0; trial < 10; ++trial) {
      double xi[3], N[kMaxCellNodes], dN[kMaxCellNodes * 3];
      RandomInterior(t, &rng, xi);
      shape_values(t, xi, N);
      shape_gradients(t, xi, dN);
      double f = 0, g[3] = {0, 0, 0};
      for (int i = 0; i < n; ++i) {
        const double* x = reference_node(t, i);
        const double fi = c0 + c[0] * x[0] + c[1] * x[1] + c[2] * x[2];
        f += fi * N[i];
        for (int j = 0; j < d; ++j) g[j] += fi * dN[i * d + j];
      }
      EXPECT_NEAR(f, c0 + c[0] * xi[0] + c[1] * xi[1] + c[2] * xi[2], 1e-12) << cell_name(t);
      for (int j = 0; j < d; ++j) EXPECT_NEAR(g[j], c[j], 1e-12) << cell_name(t);
    }
  }
}

// Quadratic types must also reproduce quadratic fields (that is what the mid nodes are for).
TEST(Shape, QuadraticTypesReproduceQuadraticFields) {
  std::mt19937 rng(5);
  for (CellType t : {CellType::kLine3, CellType::kTri6, CellType::kQuad9, CellType::kTet10,
                     CellType::kHex27, CellType::kQuad8, CellType::kHex20, CellType::kWedge15,
                     CellType::kWedge18, CellType::kPyramid13, CellType::kPyramid14}) {
    const int n = cell_num_nodes(t);
    auto f = [](const double* x) {
      return 0.3 + x[0] - 0.5 * x[1] * x[1] + 2 * x[0] * x[2] - x[1] * x[2] + 0.25 * x[0] * x[0];
    };
    for (int trial = 0; trial < 10; ++trial) {
      double xi[3], N[kMaxCellNodes];
      RandomInterior(t, &rng, xi);
      shape_values(t, xi, N);
      double v = 0;
      for (int i = 0; i < n; ++i) v += f(reference_node(t, i)) * N[i];
      EXPECT_NEAR(v, f(xi), 1e-12) << cell_name(t);
    }
  }
}

TEST(Shape, JacobianOfAffineMapIsItsMatrix) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-1, 1);
  for (CellType t : kAllTypes) {
    const int n = cell_num_nodes(t), d = cell_dim(t);
    if (d == 0) continue;
    for (int space_dim = std::max(d, 2); space_dim <= 3; ++space_dim) {
      double M[9], b[3];
      for (double& m : M) m = u(rng);
      for (double& v : b) v = u(rng);
      // x = M xi + b, M is space_dim x d row-major.
      double X[kMaxCellNodes * 3];
      for (int i = 0; i < n; ++i) {
        const double* r = reference_node(t, i);
        for (int k = 0; k < space_dim; ++k) {
          X[i * space_dim + k] = b[k];
          for (int j = 0; j < d; ++j) X[i * space_dim + k] += M[k * d + j] * r[j];
        }
      }
      double xi[3], A[9];
      RandomInterior(t, &rng, xi);
      cell_jacobian(t, X, space_dim, xi, A);
      for (int k = 0; k < space_dim * d; ++k) EXPECT_NEAR(A[k], M[k], 1e-12) << cell_name(t);
    }
  }
}

// Beyond the complete quadratics each basis spans its own space: the serendipity quad8 / hex20
// add x^2 y-type terms (hex20 also xyz), wedge15 = P2(tri) x P1(zeta) + P1(tri) zeta^2 and wedge18
// = P2(tri) x P2(zeta). Each listed monomial is interpolated exactly (values and gradients);
// a monomial outside the space is not (so the test can tell the bases apart).
TEST(Shape, BasesReproduceTheirOwnPolynomialSpace) {
  struct Case {
    CellType type;
    std::vector<std::array<int, 3>> inside;  // exponents of xi, eta, zeta
    std::array<int, 3> outside;
  };
  const Case cases[] = {
      {CellType::kQuad8, {{2, 1, 0}, {1, 2, 0}, {1, 1, 0}}, {2, 2, 0}},
      {CellType::kHex20,
       {{2, 1, 0}, {1, 2, 0}, {0, 2, 1}, {1, 0, 2}, {1, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2}},
       {2, 2, 0}},
      {CellType::kWedge15, {{2, 0, 1}, {1, 1, 1}, {0, 2, 1}, {1, 0, 2}, {0, 1, 2}}, {2, 0, 2}},
      {CellType::kWedge18, {{2, 0, 2}, {1, 1, 2}, {0, 2, 2}, {1, 0, 2}, {0, 0, 2}}, {3, 0, 0}},
      {CellType::kQuad9, {{2, 2, 0}}, {3, 0, 0}},
  };
  auto mono = [](const std::array<int, 3>& e, const double* x) {
    return std::pow(x[0], e[0]) * std::pow(x[1], e[1]) * std::pow(x[2], e[2]);
  };
  auto mono_grad = [](const std::array<int, 3>& e, const double* x, int j) {
    if (e[j] == 0) return 0.0;
    double g = e[j] * std::pow(x[j], e[j] - 1);
    for (int k = 0; k < 3; ++k)
      if (k != j) g *= std::pow(x[k], e[k]);
    return g;
  };
  std::mt19937 rng(23);
  for (const Case& c : cases) {
    const int n = cell_num_nodes(c.type), d = cell_dim(c.type);
    double worst_outside = 0;
    for (int trial = 0; trial < 10; ++trial) {
      double xi[3], N[kMaxCellNodes], dN[kMaxCellNodes * 3];
      RandomInterior(c.type, &rng, xi);
      shape_values(c.type, xi, N);
      shape_gradients(c.type, xi, dN);
      for (const auto& e : c.inside) {
        double v = 0, g[3] = {0, 0, 0};
        for (int i = 0; i < n; ++i) {
          const double fi = mono(e, reference_node(c.type, i));
          v += fi * N[i];
          for (int j = 0; j < d; ++j) g[j] += fi * dN[i * d + j];
        }
        EXPECT_NEAR(v, mono(e, xi), 1e-12) << cell_name(c.type) << " " << e[0] << e[1] << e[2];
        for (int j = 0; j < d; ++j)
          EXPECT_NEAR(g[j], mono_grad(e, xi, j), 1e-11) << cell_name(c.type) << " d" << j;
      }
      double v = 0;
      for (int i = 0; i < n; ++i) v += mono(c.outside, reference_node(c.type, i)) * N[i];
      worst_outside = std::max(worst_outside, std::abs(v - mono(c.outside, xi)));
    }
    EXPECT_GT(worst_outside, 1e-3) << cell_name(c.type) << " reproduces a monomial outside it";
  }
}

// The facets of the table are outward in the reference element: the right-hand normal of each
// facet points away from the cell's centroid (2D: the edge (a, b) has outward normal (dy, -dx)).
TEST(CellTypeTable, FacetsPointOutOfTheReferenceElement) {
  for (CellType t : kAllTypes) {
    const CellInfo& info = cell_info(t);
    if (info.dim < 2) continue;
    double centre[3] = {0, 0, 0};
    for (int i = 0; i < info.num_corners; ++i)
      for (int j = 0; j < 3; ++j) centre[j] += reference_node(t, i)[j] / info.num_corners;
    for (int f = 0; f < info.num_facets; ++f) {
      const CellFacet& facet = info.facets[f];
      double fc[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
      for (int k = 0; k < facet.num_corners; ++k) {
        const double* p = reference_node(t, facet.corners[k]);
        const double* q = reference_node(t, facet.corners[(k + 1) % facet.num_corners]);
        for (int j = 0; j < 3; ++j) fc[j] += p[j] / facet.num_corners;
        // Newell's normal (exact for planar polygons; edges of 2D cells handled below).
        normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
        normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
        normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
      }
      if (info.dim == 2) {
        const double* p = reference_node(t, facet.corners[0]);
        const double* q = reference_node(t, facet.corners[1]);
        normal[0] = q[1] - p[1];
        normal[1] = -(q[0] - p[0]);
        normal[2] = 0;
      }
      double dot = 0;
      for (int j = 0; j < 3; ++j) dot += normal[j] * (fc[j] - centre[j]);
      EXPECT_GT(dot, 1e-3) << cell_name(t) << " facet " << f;
    }
  }
}

// Mid-edge nodes of quadratic types sit at the middle of the table's edges, in table order;
// face nodes (hex27, wedge18, pyramid14) at the centre of their facets (cell_info's facet_nodes).
TEST(CellTypeTable, MidNodesFollowEdgeAndFacetOrder) {
  for (CellType t : kAllTypes) {
    const CellInfo& info = cell_info(t);
    if (info.order != 2) continue;
    for (int e = 0; e < info.num_edges; ++e) {
      const double* a = reference_node(t, info.edges[e][0]);
      const double* b = reference_node(t, info.edges[e][1]);
      const double* m = reference_node(t, info.num_corners + e);
      for (int j = 0; j < 3; ++j) EXPECT_EQ(m[j], 0.5 * (a[j] + b[j])) << cell_name(t) << e;
    }
    int face_nodes = 0;
    for (int f = 0; f < info.num_facets; ++f) {
      const int node = facet_node(info, f);
      if (node < 0) continue;
      ++face_nodes;
      // Face nodes come after the corners and the mid-edge nodes.
      EXPECT_GE(node, info.num_corners + info.num_edges) << cell_name(t);
      const double* m = reference_node(t, node);
      const int nc = info.facets[f].num_corners;
      for (int j = 0; j < 3; ++j) {
        double c = 0;
        for (int k = 0; k < nc; ++k) c += reference_node(t, info.facets[f].corners[k])[j] / nc;
        EXPECT_EQ(m[j], c) << cell_name(t) << " face " << f;
      }
    }
    const int expected_faces = t == CellType::kHex27       ? 6
                               : t == CellType::kWedge18   ? 3
                               : t == CellType::kPyramid14 ? 1
                                                           : 0;
    EXPECT_EQ(face_nodes, expected_faces) << cell_name(t);
  }
}

// The quadratic pyramids' spaces are rational (shape_families.h): both hold xi eta / s and
// xi^2 eta / s (s = 1 - zeta), only pyramid14 holds xi^2 eta^2 / s^2, and a pyramid13 function
// reproduces it at its nodes only.
TEST(Shape, PyramidsReproduceTheirRationalSpaces) {
  // The rational terms' limit at the apex (s = 0) is 0.
  auto over = [](double num, const double* x, int power) {
    const double s = 1 - x[2];
    return s < 1e-14 ? 0.0 : num / std::pow(s, power);
  };
  auto f1 = [&](const double* x) { return over(x[0] * x[1], x, 1); };
  auto f2 = [&](const double* x) { return over(x[0] * x[0] * x[1], x, 1) + x[2] * x[2]; };
  auto f3 = [&](const double* x) { return over(x[0] * x[0] * x[1] * x[1], x, 2); };
  auto at = [](CellType t, const double* xi, const std::function<double(const double*)>& f) {
    double N[kMaxCellNodes];
    shape_values(t, xi, N);
    double v = 0;
    for (int i = 0; i < cell_num_nodes(t); ++i) v += f(reference_node(t, i)) * N[i];
    return v;
  };
  std::mt19937 rng(29);
  double worst13 = 0;
  for (int trial = 0; trial < 20; ++trial) {
    double xi[3];
    RandomInterior(CellType::kPyramid14, &rng, xi);
    for (CellType t : {CellType::kPyramid13, CellType::kPyramid14}) {
      EXPECT_NEAR(at(t, xi, f1), f1(xi), 1e-12) << cell_name(t);
      EXPECT_NEAR(at(t, xi, f2), f2(xi), 1e-12) << cell_name(t);
    }
    EXPECT_NEAR(at(CellType::kPyramid14, xi, f3), f3(xi), 1e-12);
    worst13 = std::max(worst13, std::abs(at(CellType::kPyramid13, xi, f3) - f3(xi)));
  }
  EXPECT_GT(worst13, 1e-3);
}

}  // namespace
}  // namespace tmop
