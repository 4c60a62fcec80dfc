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

namespace tmop {

enum class TargetType {
  kIdealUnitSize,   // "ideal_unit": ideal shape with unit edge length
  kIdealEqualSize,  // "equal_size": ideal shape, h = mean equivalent edge length of the elements
  kIdealLocalSize,  // "local_size": ideal shape, h = the cell's own equivalent edge length
  kIdealSizeField,  // "size_field": ideal shape, h interpolated from a per-vertex point_data field
  kReference,       // "reference": W = the Jacobian of a reference mesh at the point
  kMeanEdgeLength,  // "lambda_identity": ideal shape, h = lambda = mean edge length of the mesh
};

struct TargetSpec {
  TargetType type = TargetType::kIdealEqualSize;
  // kReference: a mesh with the same vertices/cells numbering whose Jacobians are the targets
  // ("keep what is there" when it is the initial mesh). nullptr means the mesh itself. Not owned.
  const Mesh* reference = nullptr;
  // kIdealSizeField: the name of a 1-component point_data array of target edge lengths.
  std::string size_field;
};

// "ideal_unit", "equal_size", "local_size", "size_field", "reference", "lambda_identity".
bool target_type_from_name(const std::string& name, TargetType* type);
const char* target_type_name(TargetType type);

// Equivalent edge length of a cell: (volume / ideal_volume(type))^(1/d); volume integrated with
// the Gauss rule; negative volumes give a negative length.
double cell_equivalent_edge(const Mesh& mesh, int cell);

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
// non-positive size, or a reference Jacobian that is singular (reference targets need W^-1).
Status build_targets(const Mesh& mesh, SampleRule rule, const TargetSpec& spec,
                     std::vector<double>* W);
// The same for an explicit sample set.
Status build_targets(const Mesh& mesh, const SampleSet& points, const TargetSpec& spec,
                     std::vector<double>* W);

}  // namespace tmop

#endif  // TMOP_TARGET_TARGET_H_
