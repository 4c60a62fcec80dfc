// tmop/quality/quality_fields.h
// add_quality_fields: puts the report's per-cell arrays into Mesh::cell_data (one component
// each, one value per cell) so that .vtu / .vtk output shows them: "inverted" (0/1),
// "certified" (1/0, NaN without certificate), "all_boundary" (1 for an element with every corner
// on the boundary, which a fixed boundary freezes, else 0; topology_caps.h) and every measure
// under its JSON key
// ("mean_ratio", "scaled_jacobian", "condition_number", "min_det", "min_angle_deg",
// "max_angle_deg", "min_dihedral_deg", "max_dihedral_deg", "min_edge_length", "max_edge_length",
// "edge_ratio"). Arrays that apply to no element are left out (angles of a volume mesh); in the
// others NaN marks cells the measure does not apply to (lower-dimensional cells, other types of a
// mixed mesh) and the condition number of an inverted cell is +inf. Arrays with these names
// already in cell_data are replaced.
#ifndef TMOP_QUALITY_QUALITY_FIELDS_H_
#define TMOP_QUALITY_QUALITY_FIELDS_H_

#include "tmop/mesh/mesh.h"
#include "tmop/quality/quality_report.h"

namespace tmop {

// report must come from compute_quality(*mesh) (same cells); CHECK-style abort otherwise.
void add_quality_fields(const QualityReport& report, Mesh* mesh);

// For a mesh that already carries quality fields (arrays with the names above, e.g. written by
// tmop_quality --output) whose nodes have moved since: removes every such array and, when there
// was one, adds the report's (which must describe the mesh as it is now). Returns whether it
// did, so an optimized mesh never carries the input's stale per-cell quality.
bool refresh_quality_fields(const QualityReport& report, Mesh* mesh);

}  // namespace tmop

#endif  // TMOP_QUALITY_QUALITY_FIELDS_H_
