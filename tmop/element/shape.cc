#include "tmop/element/shape.h"

#include <array>

#include "tmop/element/shape_families.h"

namespace tmop {
namespace {

// Reference node coordinates, as gmsh.model.mesh.getElementProperties reports them (the element
// tests compare against a copy of gmsh's output).
constexpr double kVertexNodes[][3] = {{0, 0, 0}};
constexpr double kLine2Nodes[][3] = {{-1, 0, 0}, {1, 0, 0}};
constexpr double kLine3Nodes[][3] = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
constexpr double kTri3Nodes[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
constexpr double kQuad4Nodes[][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
constexpr double kTet4Nodes[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr double kHex8Nodes[][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr double kWedge6Nodes[][3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1},
                                      {0, 0, 1},  {1, 0, 1},  {0, 1, 1}};
constexpr double kPyramid5Nodes[][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
constexpr double kTri6Nodes[][3] = {{0, 0, 0},   {1, 0, 0},     {0, 1, 0},
                                    {0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
constexpr double kQuad9Nodes[][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0}, {0, -1, 0},
                                     {1, 0, 0},   {0, 1, 0},  {-1, 0, 0}, {0, 0, 0}};
constexpr double kTet10Nodes[][3] = {{0, 0, 0},     {1, 0, 0},     {0, 1, 0},   {0, 0, 1},
                                     {0.5, 0, 0},   {0.5, 0.5, 0}, {0, 0.5, 0}, {0, 0, 0.5},
                                     {0, 0.5, 0.5}, {0.5, 0, 0.5}};
constexpr double kHex27Nodes[][3] = {
    {-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1},
    {-1, 1, 1},   {0, -1, -1}, {-1, 0, -1}, {-1, -1, 0}, {1, 0, -1},  {1, -1, 0}, {0, 1, -1},
    {1, 1, 0},    {-1, 1, 0},  {0, -1, 1},  {-1, 0, 1},  {1, 0, 1},   {0, 1, 1},  {0, 0, -1},
    {0, -1, 0},   {-1, 0, 0},  {1, 0, 0},   {0, 1, 0},   {0, 0, 1},   {0, 0, 0}};

// The serendipity quad8 / hex20 are quad9 / hex27 without their face and centre nodes.
constexpr const double (*kQuad8Nodes)[3] = kQuad9Nodes;
constexpr const double (*kHex20Nodes)[3] = kHex27Nodes;
// wedge15: corners, then the mid-edge nodes in the cell table's edge order; wedge18 adds the
// centres of the quad faces 0-1-4-3, 0-2-5-3, 1-2-5-4.
constexpr double kWedge18Nodes[][3] = {
    {0, 0, -1},   {1, 0, -1},   {0, 1, -1},    {0, 0, 1},      {1, 0, 1},   {0, 1, 1},
    {0.5, 0, -1}, {0, 0.5, -1}, {0, 0, 0},     {0.5, 0.5, -1}, {1, 0, 0},   {0, 1, 0},
    {0.5, 0, 1},  {0, 0.5, 1},  {0.5, 0.5, 1}, {0.5, 0, 0},    {0, 0.5, 0}, {0.5, 0.5, 0}};
constexpr const double (*kWedge15Nodes)[3] = kWedge18Nodes;
// pyramid13: corners, then the mid-edge nodes in the cell table's edge order; pyramid14 adds the
// base centre.
constexpr double kPyramid14Nodes[][3] = {
    {-1, -1, 0}, {1, -1, 0},      {1, 1, 0},         {-1, 1, 0}, {0, 0, 1},
    {0, -1, 0},  {-1, 0, 0},      {-0.5, -0.5, 0.5}, {1, 0, 0},  {0.5, -0.5, 0.5},
    {0, 1, 0},   {0.5, 0.5, 0.5}, {-0.5, 0.5, 0.5},  {0, 0, 0}};
constexpr const double (*kPyramid13Nodes)[3] = kPyramid14Nodes;

// Indexed by static_cast<int>(CellType); the order of the enum.
constexpr const double (*kNodes[kNumCellTypes])[3] = {
    kVertexNodes,  kLine2Nodes,   kLine3Nodes,     kTri3Nodes,     kQuad4Nodes,
    kTet4Nodes,    kHex8Nodes,    kWedge6Nodes,    kPyramid5Nodes, kTri6Nodes,
    kQuad9Nodes,   kTet10Nodes,   kHex27Nodes,     kQuad8Nodes,    kHex20Nodes,
    kWedge15Nodes, kWedge18Nodes, kPyramid13Nodes, kPyramid14Nodes};

// Tensor-product types: the 1D factor of node i along axis j is picked by the node's reference
// coordinate (-1 -> 0, +1 -> 1, 0 -> 2, the line3 node order). Derived from the node table at
// compile time so the two can never disagree.
struct TensorIndex {
  std::array<std::array<int, 3>, kMaxCellNodes> idx{};
};
constexpr TensorIndex MakeTensorIndex(const double (*nodes)[3], int n) {
  TensorIndex t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j) t.idx[i][j] = nodes[i][j] < -0.5 ? 0 : (nodes[i][j] > 0.5 ? 1 : 2);
  return t;
}
constexpr TensorIndex kQuad4Index = MakeTensorIndex(kQuad4Nodes, 4);
constexpr TensorIndex kHex8Index = MakeTensorIndex(kHex8Nodes, 8);
constexpr TensorIndex kQuad9Index = MakeTensorIndex(kQuad9Nodes, 9);
constexpr TensorIndex kHex27Index = MakeTensorIndex(kHex27Nodes, 27);

// 1D Lagrange bases on [-1, 1]: linear (nodes -1, 1) and quadratic (nodes -1, 1, 0).
inline void Linear1d(double x, double* v, double* d) {
  v[0] = 0.5 * (1 - x);
  v[1] = 0.5 * (1 + x);
  d[0] = -0.5;
  d[1] = 0.5;
}
inline void Quadratic1d(double x, double* v, double* d) {
  v[0] = 0.5 * x * (x - 1);
  v[1] = 0.5 * x * (x + 1);
  v[2] = 1 - x * x;
  d[0] = x - 0.5;
  d[1] = x + 0.5;
  d[2] = -2 * x;
}

// Tensor products of a 1D basis over `dim` axes. N and dN (n x dim) are both written.
void Tensor(const TensorIndex& t, int n, int dim, bool quadratic, const double* xi, double* N,
            double* dN) {
  double v[3][3], d[3][3];
  for (int j = 0; j < dim; ++j) {
    if (quadratic) {
      Quadratic1d(xi[j], v[j], d[j]);
    } else {
      Linear1d(xi[j], v[j], d[j]);
    }
  }
  for (int i = 0; i < n; ++i) {
    const std::array<int, 3>& k = t.idx[i];
    double prod = 1;
    for (int j = 0; j < dim; ++j) prod *= v[j][k[j]];
    N[i] = prod;
    for (int j = 0; j < dim; ++j) {
      double g = d[j][k[j]];
      for (int m = 0; m < dim; ++m)
        if (m != j) g *= v[m][k[m]];
      dN[i * dim + j] = g;
    }
  }
}

// Barycentric coordinates of the unit simplex of dimension dim: L0 = 1 - sum xi, L_k = xi_{k-1}.
// Their gradients are constant: grad L0 = -(1,..,1), grad L_k = e_{k-1}.
inline void Barycentric(int dim, const double* xi, double* L) {
  L[0] = 1;
  for (int j = 0; j < dim; ++j) {
    L[j + 1] = xi[j];
    L[0] -= xi[j];
  }
}
inline double BarycentricGrad(int k, int j) { return k == 0 ? -1.0 : (k - 1 == j ? 1.0 : 0.0); }

void LinearSimplex(int dim, const double* xi, double* N, double* dN) {
  Barycentric(dim, xi, N);
  for (int k = 0; k <= dim; ++k)
    for (int j = 0; j < dim; ++j) dN[k * dim + j] = BarycentricGrad(k, j);
}

// Quadratic simplex: corners L(2L - 1), the node on edge (a, b) 4 L_a L_b, edges in the order of
// the cell table (which is the order of the mid-edge nodes).
void QuadraticSimplex(CellType type, int dim, const double* xi, double* N, double* dN) {
  double L[4];
  Barycentric(dim, xi, L);
  const int nc = dim + 1;
  for (int k = 0; k < nc; ++k) {
    N[k] = L[k] * (2 * L[k] - 1);
    for (int j = 0; j < dim; ++j) dN[k * dim + j] = (4 * L[k] - 1) * BarycentricGrad(k, j);
  }
  const CellInfo& info = cell_info(type);
  for (int e = 0; e < info.num_edges; ++e) {
    const int a = info.edges[e][0], b = info.edges[e][1], i = nc + e;
    N[i] = 4 * L[a] * L[b];
    for (int j = 0; j < dim; ++j)
      dN[i * dim + j] = 4 * (BarycentricGrad(a, j) * L[b] + L[a] * BarycentricGrad(b, j));
  }
}

// Wedge: triangle barycentrics times the linear 1D basis in zeta (nodes 0-2 at zeta = -1).
void Wedge(const double* xi, double* N, double* dN) {
  double L[3], v[2], d[2];
  Barycentric(2, xi, L);
  Linear1d(xi[2], v, d);
  for (int i = 0; i < 6; ++i) {
    const int k = i % 3, z = i / 3;
    N[i] = L[k] * v[z];
    dN[i * 3 + 0] = BarycentricGrad(k, 0) * v[z];
    dN[i * 3 + 1] = BarycentricGrad(k, 1) * v[z];
    dN[i * 3 + 2] = L[k] * d[z];
  }
}

// Pyramid (Gmsh's rational basis): base node with signs (sx, sy) has
// N = (s + sx xi)(s + sy eta) / (4 s), s = 1 - zeta; the apex has N = zeta. The sum of the base
// functions is s, so the basis is a partition of unity and reproduces linear fields.
void Pyramid(const double* xi, double* N, double* dN) {
  const double s = 1 - xi[2];
  for (int i = 0; i < 4; ++i) {
    const double sx = kPyramid5Nodes[i][0], sy = kPyramid5Nodes[i][1];
    const double p = s + sx * xi[0], q = s + sy * xi[1];
    if (s > 1e-14) {
      N[i] = p * q / (4 * s);
      dN[i * 3 + 0] = sx * q / (4 * s);
      dN[i * 3 + 1] = sy * p / (4 * s);
      dN[i * 3 + 2] = (p * q - (p + q) * s) / (4 * s * s);
    } else {  // The apex: values have a limit (0), gradients do not (header says so).
      N[i] = 0;
      dN[i * 3 + 0] = dN[i * 3 + 1] = dN[i * 3 + 2] = 0;
    }
  }
  N[4] = xi[2];
  dN[12] = 0;
  dN[13] = 0;
  dN[14] = 1;
}

// Writes both N (num_nodes) and dN (num_nodes x dim).
void Evaluate(CellType type, const double* xi, double* N, double* dN) {
  switch (type) {
    case CellType::kVertex:
      N[0] = 1;
      return;
    case CellType::kLine2:
      Linear1d(xi[0], N, dN);
      return;
    case CellType::kLine3:
      Quadratic1d(xi[0], N, dN);
      return;
    case CellType::kTri3:
      LinearSimplex(2, xi, N, dN);
      return;
    case CellType::kTet4:
      LinearSimplex(3, xi, N, dN);
      return;
    case CellType::kQuad4:
      Tensor(kQuad4Index, 4, 2, false, xi, N, dN);
      return;
    case CellType::kHex8:
      Tensor(kHex8Index, 8, 3, false, xi, N, dN);
      return;
    case CellType::kQuad9:
      Tensor(kQuad9Index, 9, 2, true, xi, N, dN);
      return;
    case CellType::kHex27:
      Tensor(kHex27Index, 27, 3, true, xi, N, dN);
      return;
    case CellType::kTri6:
      QuadraticSimplex(type, 2, xi, N, dN);
      return;
    case CellType::kTet10:
      QuadraticSimplex(type, 3, xi, N, dN);
      return;
    case CellType::kWedge6:
      Wedge(xi, N, dN);
      return;
    case CellType::kPyramid5:
      Pyramid(xi, N, dN);
      return;
    case CellType::kQuad8:
      internal::serendipity_tensor(2, 8, kQuad8Nodes, xi, N, dN);
      return;
    case CellType::kHex20:
      internal::serendipity_tensor(3, 20, kHex20Nodes, xi, N, dN);
      return;
    case CellType::kWedge15:
      internal::wedge15(xi, N, dN);
      return;
    case CellType::kWedge18:
      internal::wedge18(xi, N, dN);
      return;
    case CellType::kPyramid13:
      internal::quadratic_pyramid(false, xi, N, dN);
      return;
    case CellType::kPyramid14:
      internal::quadratic_pyramid(true, xi, N, dN);
      return;
  }
}

}  // namespace

const double* reference_node(CellType type, int node) {
  return kNodes[static_cast<int>(type)][node];
}

void shape_values(CellType type, const double* xi, double* N) {
  double dN[kMaxCellNodes * 3];
  Evaluate(type, xi, N, dN);
}

void shape_gradients(CellType type, const double* xi, double* dN) {
  double N[kMaxCellNodes];
  Evaluate(type, xi, N, dN);
}

void cell_jacobian(CellType type, const double* node_coords, int space_dim, const double* xi,
                   double* A) {
  const int n = cell_num_nodes(type), d = cell_dim(type);
  double dN[kMaxCellNodes * 3];
  shape_gradients(type, xi, dN);
  for (int k = 0; k < space_dim * d; ++k) A[k] = 0;
  for (int i = 0; i < n; ++i) {
    const double* x = node_coords + i * space_dim;
    const double* g = dN + i * d;
    for (int r = 0; r < space_dim; ++r)
      for (int j = 0; j < d; ++j) A[r * d + j] += x[r] * g[j];
  }
}

}  // namespace tmop
