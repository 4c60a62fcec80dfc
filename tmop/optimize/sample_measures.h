// tmop/optimize/sample_measures.h
// What a stage computes at sample points outside Ceres (internal to optimize/): small matrix
// helpers, T = F^T X G at a point, the tangent frames of surface cells, the minimum det T of a
// term, shape quality and inverted counts at the points of a validity rule.
#ifndef TMOP_OPTIMIZE_SAMPLE_MEASURES_H_
#define TMOP_OPTIMIZE_SAMPLE_MEASURES_H_

#include <cstdint>
#include <vector>

#include "tmop/element/sample_points.h"
#include "tmop/mesh/mesh.h"
#include "tmop/optimize/g_table.h"
#include "tmop/optimize/solver_options.h"

namespace tmop {

// det and inverse of a d x d row-major matrix (inverse false when singular or not finite).
double det_d(const double* A, int d);
bool inverse_d(const double* A, int d, double* Ainv);
// G_i = W^-T g_i for every node i: G[i*d + b] = sum_c Winv[c*d + b] g[i*d + c].
void make_G(int n, int d, const double* grad, const double* Winv, double* G);
// T = F^T X G: F (space_dim x d, row-major) is the tangent frame of a surface cell, or null
// when space_dim == d.
void compute_T(int n, int d, const Mesh& mesh, const std::int32_t* nodes, const double* G,
               double* T, const double* F = nullptr);

// Per-cell tangent frames of a surface mesh (2D cells in 3D): 6 values per cell, the columns t1,
// t2 of an orthonormal basis with t1 x t2 = n. Empty for planar and volume meshes.
struct Frames {
  std::vector<double> F;
  const double* cell(int c) const { return F.empty() ? nullptr : F.data() + 6 * c; }
};
void frame_from_normal(const double* n_in, double* F);
// Frames from each cell's own corner-polygon (Newell) normal.
Frames own_frames(const Mesh& mesh);
// The frame own_frames gives cell c (a 2D cell of a mesh in 3D), into F (6 values).
void own_frame(const Mesh& mesh, int c, double* F);

// min det T over the sample points (cells point_cell, G of one term), and the cells where it is
// <= 0 (sorted, once each) when bad is not null.
double min_target_det(const Mesh& mesh, const std::vector<std::int32_t>& point_cell,
                      const GTable& G, std::vector<int>* bad, const Frames& frames);

// Shape quality of T: d det(T)^(2/d) / |T|^2, negative when det T < 0.
double shape_quality(const double* T, int d);

// G for the ideal element of each (type, point) of a rule.
struct IdealTable {
  std::vector<double> G[kNumCellTypes];
  IdealTable(SampleRule rule, int d);
};
// Worst shape quality and inverted count at the table's points, and the inverted cells.
IterationRecord measure(const Mesh& mesh, const IdealTable& table, const Frames& frames);
std::vector<int> inverted_cells(const Mesh& mesh, const IdealTable& table, const Frames& frames);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_SAMPLE_MEASURES_H_
