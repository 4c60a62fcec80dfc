// tmop/optimize/locality_order.h
// locality_order: an order of sample points along a Morton (Z-order) curve through their cells'
// centroids, so that residual blocks added in it touch neighbouring vertices (Ceres numbers
// parameter blocks by first appearance: the CGNR products stay in cache). Points of one cell stay
// together and in their order (stable). cell[p] is the cell of point p.
#ifndef TMOP_OPTIMIZE_LOCALITY_ORDER_H_
#define TMOP_OPTIMIZE_LOCALITY_ORDER_H_

#include <cstdint>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {

std::vector<std::int32_t> locality_order(const Mesh& mesh, const std::vector<std::int32_t>& cell);

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_LOCALITY_ORDER_H_
