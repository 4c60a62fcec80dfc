// tmop/quality/guarantees.h
// "Never worse", per cell type and region: the measures every element is judged by, a snapshot
// of the input (GuaranteeBaseline), the check of a result against it (check_guarantees) and the
// cells a recipe's guard must hold (guard_violators). docs/quality.md ("Guarantees") states the
// guarantees exactly as these functions test them.
//
// Measures (higher is better; NaN where a measure does not apply to the cell's type):
//   mean_ratio          tri3, tet4: the mean ratio; tri6, tet10: tmop_quality's curved mean ratio
//                       (minimum of the pointwise value over the sample points)
//   scaled_jacobian     quad4, hex8, wedge6, pyramid5, and quad9 / hex27 (of their corners)
//   corner_mean_ratio   tri6, tet10: the mean ratio of the corner (straight-sided) simplex
//   jacobian_ratio      quadratic cells: min det J / max det J over the validity sample points
//                       (corners included); 1 for a straight-sided cell of affine map
//   min_dihedral        tet10 (its corner tet): the smallest dihedral angle, degrees (a linear
//                       tet is judged by its mean ratio and the sliver flag)
//   max_dihedral        the same cells: the largest dihedral angle, stored negated so that
//                       higher is better (reported as the angle)
// and per tet (tet10: its corner tet) whether it is a sliver (quality_report.h's definition).
//
// Guarantees of a result against its input, tolerance t (absolute; measures are in [-1, 1] or
// degrees); worst and mean are over the cells valid in the input (an inverted input cell may end
// at any valid shape):
//   worst     for every (cell type, region, measure), the minimum over those cells does not
//             fall by more than t (region = Mesh::cell_region);
//   mean      for every (cell type, measure) among mean_ratio, scaled_jacobian,
//             corner_mean_ratio and jacobian_ratio, the mean does not fall by more than t;
//   slivers   no tet that was not a sliver becomes one;
//   inverted  no cell that was valid becomes inverted (det <= 0 at a corner or sample point).
#ifndef TMOP_QUALITY_GUARANTEES_H_
#define TMOP_QUALITY_GUARANTEES_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "tmop/element/cell_type.h"
#include "tmop/mesh/mesh.h"

namespace tmop {

enum class GuaranteeMeasure {
  kMeanRatio,
  kScaledJacobian,
  kCornerMeanRatio,
  kJacobianRatio,
  kMinDihedral,
  kMaxDihedral,
};
constexpr int kNumGuaranteeMeasures = 6;

// "mean_ratio", "scaled_jacobian", ... (JSON keys) and "mean ratio", ... (for messages).
const char* guarantee_measure_key(GuaranteeMeasure m);
const char* guarantee_measure_label(GuaranteeMeasure m);
// True for the measures whose mean is guaranteed (the first four).
bool guarantee_measure_has_mean(GuaranteeMeasure m);

// The measures of every cell of a mesh (num_cells() rows; NaN rows for non-elements).
struct GuaranteeValues {
  std::vector<std::array<double, kNumGuaranteeMeasures>> cell;
  std::vector<std::uint8_t> sliver;    // per cell
  std::vector<std::uint8_t> inverted;  // per cell: det <= 0 at a corner frame or sample point
};
// threads: 0 = all cores; the values do not depend on it.
GuaranteeValues guarantee_values(const Mesh& mesh, int threads = 0);
// Measures one element c of `mesh` (a cell of dimension dim()) into row c of *values (sized for
// the mesh), as guarantee_values does; planar = is_planar_2d(mesh), computed once by the caller.
void measure_guarantee_cell(const Mesh& mesh, int c, bool planar, GuaranteeValues* values);

// The input's worst per (type, region, measure) and mean per (type, measure).
struct GuaranteeBaseline {
  GuaranteeValues input;
  struct Group {
    CellType type;
    int region;  // -1 for a per-type group (means)
    GuaranteeMeasure measure;
    double worst;  // minimum over the group's cells
    double mean;   // mean over them (per-type groups)
    int worst_cell;
    std::int64_t count;
  };
  std::vector<Group> worst_groups;  // per (type, region, measure)
  std::vector<Group> mean_groups;   // per (type, measure), measures with a mean
  // Index into worst_groups of each cell's group, per measure (-1 where not applicable).
  std::vector<std::array<std::int32_t, kNumGuaranteeMeasures>> cell_group;
  std::vector<CellType> cell_type;  // per cell
};
GuaranteeBaseline guarantee_baseline(const Mesh& input, int threads = 0);

struct GuaranteeOptions {
  double tolerance = 1e-6;
  bool means = true;    // the mean of each type must not fall
  bool slivers = true;  // no new slivers
  // guard_violators: a fallen mean holds the cells that lost most until their losses add up to
  // mean_cover times the mean's deficit (times the cell count).
  double mean_cover = 2;
  // check_guarantees: when the input has inverted cells, only new inversions count (the input
  // is untangled, and what that costs the valid cells is its price). tmop_optimize's check.
  bool tangled_inversions_only = false;
};

// One broken guarantee: what got worse, where, by how much, and a cell that shows it.
struct GuaranteeViolation {
  enum class Kind { kWorst, kMean, kSlivers, kInverted } kind;
  CellType type;
  int region = 0;  // kWorst: the region (0 = none)
  GuaranteeMeasure measure = GuaranteeMeasure::kMeanRatio;
  double before = 0, after = 0;  // the group's worst / mean; slivers, inverted: counts
  int cell = -1;                 // a cell that shows it (the worst after; a new sliver ...)
  // One line, e.g. "wedge6 worst scaled Jacobian 0.677 -> 0.554 (cell 123)".
  std::string message() const;
};

// Every broken guarantee of `result` (the mesh after) against the baseline: worst groups first,
// then means, slivers and inversions; empty when every guarantee holds. `result` must have the
// input's cells.
std::vector<GuaranteeViolation> check_guarantees(const GuaranteeBaseline& baseline,
                                                 const GuaranteeValues& result,
                                                 const GuaranteeOptions& options = {});

// The cells a guard must hold at their input shape so that the guarantees can hold: cells below
// their worst group's input minimum, new slivers and new inversions, and, for a (type, measure)
// whose mean fell, that type's cells that lost most, until their losses add up to
// GuaranteeOptions::mean_cover times the mean's deficit times the cell count. Each held
// cell satisfies every guarantee at its input shape, so holding cells only moves the result
// towards the input. Sorted cell indices.
std::vector<int> guard_violators(const GuaranteeBaseline& baseline, const GuaranteeValues& result,
                                 const GuaranteeOptions& options = {});

}  // namespace tmop

#endif  // TMOP_QUALITY_GUARANTEES_H_
