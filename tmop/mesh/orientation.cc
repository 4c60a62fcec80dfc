#include "tmop/mesh/orientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "tmop/element/shape.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

// Corner permutations that mirror each reference element (an odd permutation of a simplex; the
// reversal of the base cycle for quads, hexes, wedges and pyramids).
const int kVertexFlip[] = {0};
const int kLineFlip[] = {1, 0};
const int kTriFlip[] = {0, 2, 1};
const int kQuadFlip[] = {0, 3, 2, 1};
const int kTetFlip[] = {0, 2, 1, 3};
const int kHexFlip[] = {0, 3, 2, 1, 4, 7, 6, 5};
const int kWedgeFlip[] = {0, 2, 1, 3, 5, 4};
const int kPyramidFlip[] = {0, 3, 2, 1, 4};

const int* CornerFlip(CellType linear) {
  switch (linear) {
    case CellType::kLine2:
      return kLineFlip;
    case CellType::kTri3:
      return kTriFlip;
    case CellType::kQuad4:
      return kQuadFlip;
    case CellType::kTet4:
      return kTetFlip;
    case CellType::kHex8:
      return kHexFlip;
    case CellType::kWedge6:
      return kWedgeFlip;
    case CellType::kPyramid5:
      return kPyramidFlip;
    default:
      return kVertexFlip;
  }
}

// Full permutations derived from the corner ones and the cell table: the new mid-edge node of
// edge (a, b) is the old node of edge (p[a], p[b]); the new face node of facet f is the old node
// of the facet with the same corner set (cell_info's facet_nodes); anything else (quad9 /
// hex27 centre, line3 middle) stays.
struct Permutations {
  std::array<std::array<int, kMaxCellNodes>, kNumCellTypes> perm{};
  Permutations() {
    for (int t = 0; t < kNumCellTypes; ++t) {
      const CellInfo& info = cell_info(static_cast<CellType>(t));
      const int* p = CornerFlip(info.linear);
      std::array<int, kMaxCellNodes>& out = perm[t];
      for (int i = 0; i < info.num_nodes; ++i) out[i] = i;
      for (int i = 0; i < info.num_corners; ++i) out[i] = p[i];
      if (info.order != 2) continue;
      int next = info.num_corners;
      if (info.dim >= 2) {
        for (int e = 0; e < info.num_edges; ++e, ++next) {
          const int a = p[info.edges[e][0]], b = p[info.edges[e][1]];
          for (int o = 0; o < info.num_edges; ++o)
            if ((info.edges[o][0] == a && info.edges[o][1] == b) ||
                (info.edges[o][0] == b && info.edges[o][1] == a))
              out[next] = info.num_corners + o;
        }
      }
      if (info.dim == 3 && info.facet_nodes) {
        for (int f = 0; f < info.num_facets; ++f) {
          if (facet_node(info, f) < 0) continue;
          const CellFacet& nf = info.facets[f];
          unsigned mask = 0;
          for (int k = 0; k < nf.num_corners; ++k) mask |= 1u << p[nf.corners[k]];
          for (int o = 0; o < info.num_facets; ++o) {
            unsigned omask = 0;
            for (int k = 0; k < info.facets[o].num_corners; ++k)
              omask |= 1u << info.facets[o].corners[k];
            if (omask == mask) out[facet_node(info, f)] = facet_node(info, o);
          }
        }
      }
    }
  }
};

const Permutations& GetPermutations() {
  static const Permutations p;
  return p;
}

inline double Det3(const double* a, const double* b, const double* c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// Classifies one element: +1 all corner dets positive, -1 all negative, 0 otherwise.
int CellSign(const Mesh& mesh, int c) {
  const CellType lin = cell_info(mesh.cell_type(c)).linear;
  const CellInfo& info = cell_info(lin);
  const int d = info.dim;
  const std::int32_t* nodes = mesh.cell(c);
  double X[8 * 3];
  for (int i = 0; i < info.num_nodes; ++i)
    for (int j = 0; j < d; ++j) X[i * d + j] = mesh.vertex(nodes[i])[j];
  int pos = 0, neg = 0;
  auto count = [&](double det) {
    if (det > 0) ++pos;
    if (det < 0) ++neg;
  };
  for (int i = 0; i < info.num_nodes; ++i) {
    if (lin == CellType::kPyramid5 && i == 4) {
      // Tets (b_k, b_k+1, b_k+2, apex): positive for a valid pyramid, like det J elsewhere.
      for (int k = 0; k < 4; ++k) {
        const double* b0 = X + 3 * k;
        double u[3], v[3], w[3];
        for (int j = 0; j < 3; ++j) {
          u[j] = X[3 * ((k + 1) % 4) + j] - b0[j];
          v[j] = X[3 * ((k + 2) % 4) + j] - b0[j];
          w[j] = X[12 + j] - b0[j];
        }
        count(Det3(u, v, w));
      }
      continue;
    }
    double A[9];
    cell_jacobian(lin, X, d, reference_node(lin, i), A);
    count(d == 2 ? A[0] * A[3] - A[1] * A[2] : Det3(A, A + 3, A + 6));
  }
  const int checks = info.num_nodes + (lin == CellType::kPyramid5 ? 3 : 0);
  if (pos == checks) return 1;
  if (neg == checks) return -1;
  return 0;
}

}  // namespace

const int* reorient_permutation(CellType type) {
  return GetPermutations().perm[static_cast<int>(type)].data();
}

OrientationReport::Evidence OrientationReport::evidence() const {
  if (num_elements() == 0) return Evidence::kNone;
  if (boundary_scale > 0 && std::abs(boundary_measure) >= 1e-6 * boundary_scale)
    return Evidence::kBoundary;
  return Evidence::kCells;
}

bool OrientationReport::opposite_convention() const {
  switch (evidence()) {
    case Evidence::kBoundary:
      return boundary_measure < 0;
    case Evidence::kCells:
      return 2 * negative > num_elements();
    default:
      return false;
  }
}

OrientationReport check_orientation(const Mesh& mesh) {
  OrientationReport r;
  const int d = mesh.dim();
  if (!((d == 2 && mesh.space_dim == 2) || (d == 3 && mesh.space_dim == 3))) return r;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_type(c)) != d) continue;
    switch (CellSign(mesh, c)) {
      case 1:
        ++r.positive;
        break;
      case -1:
        ++r.negative;
        break;
      default:
        ++r.mixed_or_zero;
    }
  }
  if (r.num_elements() == 0) return r;
  r.dim = d;
  // Contributions are taken about the centre of the bounding box, so that coordinates far from
  // the origin do not cancel digits away.
  double lo[3], hi[3], o[3] = {0, 0, 0};
  for (int a = 0; a < d; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int a = 0; a < d; ++a) {
      lo[a] = std::min(lo[a], mesh.vertex(v)[a]);
      hi[a] = std::max(hi[a], mesh.vertex(v)[a]);
    }
  for (int a = 0; a < d; ++a) o[a] = (lo[a] + hi[a]) / 2;
  auto rel = [&](int v, double* x) {
    for (int a = 0; a < d; ++a) x[a] = mesh.vertex(v)[a] - o[a];
  };
  double sum = 0, scale = 0;
  for (const BoundaryFacet& f : boundary_facets(mesh)) {
    if (d == 2) {
      if (f.num_corners != 2) continue;
      double a[3], b[3];
      rel(f.corners[0], a);
      rel(f.corners[1], b);
      const double area = (a[0] * b[1] - a[1] * b[0]) / 2;
      sum += area;
      scale += std::abs(area);
      continue;
    }
    double x[4][3];
    for (int k = 0; k < f.num_corners; ++k) rel(f.corners[k], x[k]);
    if (f.num_corners == 3) {
      const double v = Det3(x[0], x[1], x[2]) / 6;
      sum += v;
      scale += std::abs(v);
    } else if (f.num_corners == 4) {
      double m[3];
      for (int a = 0; a < 3; ++a) m[a] = (x[0][a] + x[1][a] + x[2][a] + x[3][a]) / 4;
      for (int k = 0; k < 4; ++k) {
        const double v = Det3(m, x[k], x[(k + 1) % 4]) / 6;
        sum += v;
        scale += std::abs(v);
      }
    }
  }
  r.boundary_measure = sum;
  r.boundary_scale = scale;
  return r;
}

std::string describe_orientation(const OrientationReport& r) {
  char counts[96];
  std::snprintf(counts, sizeof counts, "%d of %d cells negative", r.negative, r.num_elements());
  char text[320];
  switch (r.evidence()) {
    case OrientationReport::Evidence::kBoundary:
      std::snprintf(text, sizeof text,
                    "%s convention: the boundary, as its cells orient it, encloses a signed "
                    "%s of %.6g (%s; interior tangles do not change the boundary's sign)",
                    r.boundary_measure < 0 ? "opposite" : "Gmsh's", r.dim == 2 ? "area" : "volume",
                    r.boundary_measure, counts);
      break;
    case OrientationReport::Evidence::kCells:
      std::snprintf(text, sizeof text,
                    "%s convention: the boundary encloses no %s as its cells orient it, so "
                    "the cells decide by majority (%s)",
                    r.opposite_convention() ? "opposite" : "Gmsh's", r.dim == 2 ? "area" : "volume",
                    counts);
      break;
    default:
      std::snprintf(text, sizeof text, "no orientation sign (not a planar 2D or a volume mesh)");
  }
  return text;
}

void reorient(Mesh* mesh) {
  const int d = mesh->dim();
  std::int32_t old[kMaxCellNodes];
  for (int c = 0; c < mesh->num_cells(); ++c) {
    const CellType t = mesh->cell_type(c);
    if (cell_dim(t) != d) continue;
    const int* p = reorient_permutation(t);
    std::int32_t* nodes = mesh->cell(c);
    const int n = cell_num_nodes(t);
    for (int i = 0; i < n; ++i) old[i] = nodes[i];
    for (int i = 0; i < n; ++i) nodes[i] = old[p[i]];
  }
}

}  // namespace tmop
