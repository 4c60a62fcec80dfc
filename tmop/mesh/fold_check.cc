#include "tmop/mesh/fold_check.h"

#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

void centroid(const Mesh& m, int c, double* out) {
  const CellInfo& info = cell_info(m.cell_type(c));
  for (int a = 0; a < 3; ++a) out[a] = 0;
  for (int i = 0; i < info.num_corners; ++i)
    for (int a = 0; a < m.space_dim; ++a) out[a] += m.vertex(m.cell(c)[i])[a] / info.num_corners;
}

// Signed side of point q relative to the facet's line (2D) or plane (3D).
double side(const Mesh& m, const std::int32_t* corners, const double* q) {
  const double* p0 = m.vertex(corners[0]);
  const double* p1 = m.vertex(corners[1]);
  if (m.space_dim == 2) {
    return (p1[0] - p0[0]) * (q[1] - p0[1]) - (p1[1] - p0[1]) * (q[0] - p0[0]);
  }
  const double* p2 = m.vertex(corners[2]);
  const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
  const double w[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
  const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                       u[0] * w[1] - u[1] * w[0]};
  return n[0] * (q[0] - p0[0]) + n[1] * (q[1] - p0[1]) + n[2] * (q[2] - p0[2]);
}

}  // namespace

std::vector<std::array<int, 2>> folded_facets(const Mesh& mesh) {
  std::vector<std::array<int, 2>> folded;
  for (const InteriorFacet& f : interior_facets(mesh)) {
    const CellFacet& facet = cell_info(mesh.cell_type(f.cell[0])).facets[f.local[0]];
    std::int32_t corners[4];
    for (int k = 0; k < facet.num_corners; ++k) corners[k] = mesh.cell(f.cell[0])[facet.corners[k]];
    double c0[3], c1[3];
    centroid(mesh, f.cell[0], c0);
    centroid(mesh, f.cell[1], c1);
    if (side(mesh, corners, c0) * side(mesh, corners, c1) >= 0)
      folded.push_back({f.cell[0], f.cell[1]});
  }
  return folded;
}

}  // namespace tmop
