// tmop/target/target.h
// Target construction: the user's intent turned into a target matrix W per sample point
// (DESIGN.md section 5). W is d x d row-major with d = the elements' reference dimension.
//
// Sample points are enumerated in the canonical order every part of tmop uses: element cells
// (cells with dimension mesh.dim()) in cell order, and within a cell the points of
// sample_points(type, rule) in order.
#ifndef TMOP_TARGET_TARGET_H_
#define TMOP_TARGET_TARGET_H_

#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/element/sample_points.h"
#include "tmop/mesh/mesh.h"
#include "tmop/target/composed_target.h"

namespace tmop {

enum class TargetType {
  kIdealUnitSize,   // "ideal_unit": ideal shape with unit edge length
  kIdealEqualSize,  // "equal_size": ideal shape, h = mean equivalent edge length of the elements
  kIdealLocalSize,  // "local_size": ideal shape, h = the cell's own equivalent edge length
  kIdealSizeField,  // "size_field": ideal shape, h interpolated from a per-vertex point_data field
  kReference,       // "reference": W = the Jacobian of a reference mesh at the point
  kMeanEdgeLength,  // "lambda_identity": ideal shape, h = lambda = mean edge length of the mesh
  kComposed,        // "composed": size x orientation x skew x aspect, per-factor sources
                    // (composed_target.h)
};

// Where the mesh's coordinates sit relative to the user's: x_mesh = rotation (x_user - centre) /
// length (rotation 3 x 3 row-major; 2D meshes use its top-left 2 x 2 block). optimize/ builds a
// stage's targets on normalised coordinates and says so here; what the user gives in their own
// units and axes is mapped into the mesh's frame: sizes (size_field, composed sizes: divided by
// length), composed orientations (rotated), composed function arguments (mapped back to the
// user's frame). Targets taken from a mesh (equal, local, reference, initial) need no mapping.
struct TargetFrame {
  double centre[3] = {0, 0, 0};
  double length = 1;
  double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
};

struct TargetSpec {
  TargetType type = TargetType::kIdealEqualSize;
  // kReference: a mesh with the same vertices/cells numbering whose Jacobians are the targets
  // ("keep what is there" when it is the initial mesh). nullptr means the mesh itself. Not owned.
  const Mesh* reference = nullptr;
  // kReference: when not empty, one factor per cell (> 0) multiplying W of the cell's points
  // (a reference cell scaled to another size: the curved-node stage of quadratic meshes takes
  // the straight-sided cell scaled to the curved cell's area, recipes/quadratic_curving.h).
  std::vector<double> cell_scale;
  // kIdealSizeField: the name of a 1-component point_data array of target edge lengths (the
  // user's length units, see frame).
  std::string size_field;
  // kComposed: the source of each factor. `reference` (when set) is the initial mesh of the
  // factors taken from it.
  ComposedTarget composed;
  // Identity unless the mesh given to build_targets is a mapped copy of the user's;
  // optimize_stage sets it to the frame it solves in (a caller's value is replaced there).
  TargetFrame frame;
};

// "ideal_unit", "equal_size", "local_size", "size_field", "reference", "lambda_identity",
// "composed".
bool target_type_from_name(const std::string& name, TargetType* type);
const char* target_type_name(TargetType type);

// Equivalent edge length of a cell: (volume / ideal_volume(type))^(1/d); volume integrated with
// the Gauss rule; negative volumes give a negative length.
double cell_equivalent_edge(const Mesh& mesh, int cell);
// Mean of |cell_equivalent_edge| over the element cells (equal_size's h); 1 without elements.
double mean_equivalent_edge(const Mesh& mesh);

// True when `reference` has the vertices (count, space dimension) and cells (types, nodes) of
// `mesh`, so that its Jacobians can be the mesh's targets.
bool reference_matches(const Mesh& mesh, const Mesh& reference);

// The d x d Jacobian of cell `cell` at reference point xi (3 values) as targets take it:
// cell_jacobian for d-dimensional space; for a surface cell (2D in 3D) the 2 x 2 factor U of
// its 3 x 2 Jacobian A = Q U (QR): the same lengths and angles, in the cell's own plane.
void target_jacobian(const Mesh& mesh, int cell, const double* xi, double* A);

// A list of sample points: cell index, reference coordinates and weight of each. The canonical
// set of a rule lists, for every element cell in order, the points of sample_points(type, rule);
// stages may append extra points (e.g. where a validity certificate failed).
struct SampleSet {
  std::vector<std::int32_t> cell;
  std::vector<double> xi;  // 3 per point
  std::vector<double> weight;
  std::size_t size() const { return cell.size(); }
  void add(int c, const double* x, double w) {
    cell.push_back(c);
    xi.insert(xi.end(), x, x + 3);
    weight.push_back(w);
  }
};
SampleSet canonical_sample_set(const Mesh& mesh, SampleRule rule);

// Appends nothing on failure. On success W holds (number of sample points) * d * d values.
// Fails (with a message) for a reference mesh of another topology, a missing size field, a
// non-positive size, or a reference Jacobian that is singular (reference targets need W^-1);
// composed targets: see build_composed_targets.
Status build_targets(const Mesh& mesh, SampleRule rule, const TargetSpec& spec,
                     std::vector<double>* W);
// The same for an explicit sample set.
Status build_targets(const Mesh& mesh, const SampleSet& points, const TargetSpec& spec,
                     std::vector<double>* W);

}  // namespace tmop

#endif  // TMOP_TARGET_TARGET_H_
