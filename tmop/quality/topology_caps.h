// tmop/quality/topology_caps.h
// Quality capped by topology: the parts of a mesh that node movement alone cannot make ideal,
// so users know when to remesh instead of smoothing. Fills QualityReport's
// capped_valence_vertices / capped_valence_examples / max_valence (interior corner vertices of
// all-triangle or all-quad 2D and surface meshes whose number of incident elements is far from
// the ideal 6 or 4: <= 3 or >= 9 for triangles, <= 2 or >= 6 for quads; a closed surface has
// no boundary, so all its vertices count; mid-edge and face nodes of quadratic cells are not
// vertices of the valence count) and cells_all_boundary / cells_all_boundary_examples (up to 20,
// ascending) / all_boundary (per cell) for the elements whose corners are all boundary vertices,
// for every dimension.
#ifndef TMOP_QUALITY_TOPOLOGY_CAPS_H_
#define TMOP_QUALITY_TOPOLOGY_CAPS_H_

#include "tmop/mesh/mesh.h"
#include "tmop/quality/quality_report.h"

namespace tmop {

void topology_caps(const Mesh& mesh, QualityReport* report);

}  // namespace tmop

#endif  // TMOP_QUALITY_TOPOLOGY_CAPS_H_
