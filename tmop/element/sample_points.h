// tmop/element/sample_points.h
// Sample-point rules: where in each reference element the metric is evaluated.
// Defaults (DESIGN.md section 4): vertex/line2/tri3/tet4 one point at the centroid (A is constant
// there); quad4/hex8/wedge6 their corners; pyramid5 its base corners; quadratic types every node
// (corners + mid-edge nodes + the face/centre nodes quad9/hex27 have).
// The pyramid's apex is never a sample point: its rational basis has no gradient there.
// Gauss rules: line 2 points, tri 3 (Strang-Fix), quad 2x2, tet 4 (Keast), hex 2x2x2,
// wedge 3x2, pyramid 2x2x3 on the collapsed cube; quadratic types use their corners' rule.
// Weights of one rule sum to 1, so a cell's contribution is the average of its metric over its
// points (Gauss weights are the quadrature weights divided by the reference volume).
#ifndef TMOP_ELEMENT_SAMPLE_POINTS_H_
#define TMOP_ELEMENT_SAMPLE_POINTS_H_

#include <string>
#include <vector>

#include "tmop/element/cell_type.h"

namespace tmop {

enum class SampleRule {
  kDefault,   // per type, as above
  kCorners,   // the corner nodes (pyramid: base corners)
  kNodes,     // every node of the cell
  kCentroid,  // one point at the reference centroid
  kGauss,     // a Gauss rule exact for degree 2 (pyramid: a degree-2 rule on its collapsed cube)
};

struct SamplePoint {
  double xi[3];
  double weight;
};

// The rule's points for one cell type. The returned reference stays valid for the program's life.
const std::vector<SamplePoint>& sample_points(CellType type, SampleRule rule);

// The rule whose points decide validity (det J > 0) for cells sampled with `rule`: the rule
// itself when its points include every corner (default, corners, nodes), else the default rule.
// A barrier stage or an inverted count that looked only at a centroid or at Gauss points would
// miss a hex folded at a corner.
SampleRule validity_rule(SampleRule rule);

// "default", "corners", "nodes", "centroid", "gauss"; false when unknown.
bool sample_rule_from_name(const std::string& name, SampleRule* rule);
const char* sample_rule_name(SampleRule rule);

}  // namespace tmop

#endif  // TMOP_ELEMENT_SAMPLE_POINTS_H_
