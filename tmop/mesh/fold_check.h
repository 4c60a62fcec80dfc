// tmop/mesh/fold_check.h
// An orientation-free validity check: an interior facet (shared by two elements) is folded when
// the two elements' corner centroids lie on the same side of it (or on it). A mesh with folded
// facets overlaps itself whatever orientation convention its cells use, so this check
// complements the sign of det J (which depends on the node order).
//
// Input: a planar 2D mesh (space_dim 2) or a volume mesh (space_dim 3) of linear or quadratic
// elements; the facet's plane is the one through its first three corners (its line in 2D).
// Output: the pairs of cells across each folded facet. Cost O(N log N).
#ifndef TMOP_MESH_FOLD_CHECK_H_
#define TMOP_MESH_FOLD_CHECK_H_

#include <array>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

std::vector<std::array<int, 2>> folded_facets(const Mesh& mesh);

}  // namespace tmop

#endif  // TMOP_MESH_FOLD_CHECK_H_
