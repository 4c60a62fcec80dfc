#include "tmop/element/shape_families.h"

#include "tmop/element/cell_type.h"

namespace tmop {
namespace internal {
namespace {

// Triangle barycentrics L0 = 1 - xi - eta, L1 = xi, L2 = eta and their constant gradients.
inline void Barycentric2(const double* xi, double* L) {
  L[0] = 1 - xi[0] - xi[1];
  L[1] = xi[0];
  L[2] = xi[1];
}
inline double BaryGrad(int k, int j) { return k == 0 ? -1.0 : (k - 1 == j ? 1.0 : 0.0); }

// The tri6 basis (corners L (2L - 1), edge (a, b) 4 L_a L_b in tri6's edge order) and its
// gradients, 6 x 2.
void Tri6(const double* xi, double* v, double* d) {
  static constexpr int kEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  double L[3];
  Barycentric2(xi, L);
  for (int k = 0; k < 3; ++k) {
    v[k] = L[k] * (2 * L[k] - 1);
    for (int j = 0; j < 2; ++j) d[k * 2 + j] = (4 * L[k] - 1) * BaryGrad(k, j);
  }
  for (int e = 0; e < 3; ++e) {
    const int a = kEdges[e][0], b = kEdges[e][1];
    v[3 + e] = 4 * L[a] * L[b];
    for (int j = 0; j < 2; ++j)
      d[(3 + e) * 2 + j] = 4 * (BaryGrad(a, j) * L[b] + L[a] * BaryGrad(b, j));
  }
}

// The line3 basis on [-1, 1] with nodes -1, 1, 0.
void Line3(double x, double* v, double* d) {
  v[0] = 0.5 * x * (x - 1);
  v[1] = 0.5 * x * (x + 1);
  v[2] = 1 - x * x;
  d[0] = x - 0.5;
  d[1] = x + 0.5;
  d[2] = -2 * x;
}

}  // namespace

void serendipity_tensor(int dim, int num_nodes, const double (*nodes)[3], const double* xi,
                        double* N, double* dN) {
  for (int i = 0; i < num_nodes; ++i) {
    const double* s = nodes[i];
    int axis = -1;  // the mid-edge node's zero coordinate; -1 for a corner
    for (int j = 0; j < dim; ++j)
      if (s[j] == 0) axis = j;
    // p[j] = 1 + s_j x_j, the linear factors; products are formed without dividing by them.
    double p[3];
    for (int j = 0; j < dim; ++j) p[j] = 1 + s[j] * xi[j];
    auto product_except = [&](int a, int b) {
      double r = 1;
      for (int j = 0; j < dim; ++j)
        if (j != a && j != b) r *= p[j];
      return r;
    };
    if (axis < 0) {
      const double scale = dim == 2 ? 0.25 : 0.125;
      double c = -(dim - 1);
      for (int j = 0; j < dim; ++j) c += s[j] * xi[j];
      const double P = product_except(-1, -1);
      N[i] = scale * P * c;
      for (int a = 0; a < dim; ++a)
        dN[i * dim + a] = scale * s[a] * (product_except(a, -1) * c + P);
    } else {
      const double scale = dim == 2 ? 0.5 : 0.25;
      const double bubble = 1 - xi[axis] * xi[axis];
      N[i] = scale * bubble * product_except(axis, -1);
      for (int a = 0; a < dim; ++a) {
        dN[i * dim + a] = a == axis ? scale * (-2 * xi[axis]) * product_except(axis, -1)
                                    : scale * bubble * s[a] * product_except(axis, a);
      }
    }
  }
}

void wedge15(const double* xi, double* N, double* dN) {
  double L[3];
  Barycentric2(xi, L);
  const double z = xi[2];
  for (int i = 0; i < 6; ++i) {
    const int k = i % 3;
    const double zk = i < 3 ? -1.0 : 1.0, h = 1 + zk * z, q = 2 * L[k] + zk * z - 2;
    N[i] = 0.5 * L[k] * h * q;
    for (int j = 0; j < 2; ++j) dN[i * 3 + j] = 0.5 * BaryGrad(k, j) * h * (q + 2 * L[k]);
    dN[i * 3 + 2] = 0.5 * L[k] * zk * (q + h);
  }
  const CellInfo& info = cell_info(CellType::kWedge15);
  for (int e = 0; e < info.num_edges; ++e) {
    const int a = info.edges[e][0], b = info.edges[e][1], i = 6 + e;
    if (b == a + 3) {  // vertical edge at corner a
      N[i] = L[a] * (1 - z * z);
      for (int j = 0; j < 2; ++j) dN[i * 3 + j] = BaryGrad(a, j) * (1 - z * z);
      dN[i * 3 + 2] = -2 * z * L[a];
    } else {  // an edge of the bottom (corners < 3) or top triangle
      const int ta = a % 3, tb = b % 3;
      const double zk = a < 3 ? -1.0 : 1.0, h = 1 + zk * z;
      N[i] = 2 * L[ta] * L[tb] * h;
      for (int j = 0; j < 2; ++j)
        dN[i * 3 + j] = 2 * (BaryGrad(ta, j) * L[tb] + L[ta] * BaryGrad(tb, j)) * h;
      dN[i * 3 + 2] = 2 * L[ta] * L[tb] * zk;
    }
  }
}

void wedge18(const double* xi, double* N, double* dN) {
  // Node i = tri6 node kTri[i] (in xi, eta) x line3 node kLine[i] (in zeta), read off Gmsh's
  // reference coordinates (shape.cc); the Kronecker test checks the pairing.
  static constexpr int kTri[18] = {0, 1, 2, 0, 1, 2, 3, 5, 0, 4, 1, 2, 3, 5, 4, 3, 5, 4};
  static constexpr int kLine[18] = {0, 0, 0, 1, 1, 1, 0, 0, 2, 0, 2, 2, 1, 1, 1, 2, 2, 2};
  double tv[6], td[12], lv[3], ld[3];
  Tri6(xi, tv, td);
  Line3(xi[2], lv, ld);
  for (int i = 0; i < 18; ++i) {
    const int t = kTri[i], l = kLine[i];
    N[i] = tv[t] * lv[l];
    dN[i * 3 + 0] = td[t * 2 + 0] * lv[l];
    dN[i * 3 + 1] = td[t * 2 + 1] * lv[l];
    dN[i * 3 + 2] = tv[t] * ld[l];
  }
}

}  // namespace internal
}  // namespace tmop
