#include "tmop/geometry/aabb_tree.h"

#include <glog/logging.h>

#include <algorithm>

namespace tmop {

void AabbTree::Build(int dim, const std::vector<double>& lo, const std::vector<double>& hi) {
  CHECK(dim == 2 || dim == 3);
  CHECK_EQ(lo.size(), hi.size());
  dim_ = dim;
  const int n = static_cast<int>(lo.size() / dim);
  order_.resize(n);
  for (int i = 0; i < n; ++i) order_[i] = i;
  nodes_.clear();
  if (n == 0) return;
  nodes_.reserve(2 * (n / 2 + 1));
  build_node(0, n, lo, hi, 0);
}

int AabbTree::build_node(int begin, int end, const std::vector<double>& lo,
                         const std::vector<double>& hi, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back(Node());
  Node node;
  double clo[3] = {0, 0, 0}, chi[3] = {0, 0, 0};  // bounds of the box centres
  for (int i = 0; i < 3; ++i) {
    node.lo[i] = 0;
    node.hi[i] = 0;
  }
  for (int i = 0; i < dim_; ++i) {
    node.lo[i] = clo[i] = std::numeric_limits<double>::infinity();
    node.hi[i] = chi[i] = -std::numeric_limits<double>::infinity();
  }
  for (int k = begin; k < end; ++k) {
    const int p = order_[k];
    for (int i = 0; i < dim_; ++i) {
      node.lo[i] = std::min(node.lo[i], lo[p * dim_ + i]);
      node.hi[i] = std::max(node.hi[i], hi[p * dim_ + i]);
      const double c = 0.5 * (lo[p * dim_ + i] + hi[p * dim_ + i]);
      clo[i] = std::min(clo[i], c);
      chi[i] = std::max(chi[i], c);
    }
  }
  node.left = node.right = -1;
  node.begin = begin;
  node.end = end;
  // The depth guard keeps the traversal stack bounded even for degenerate inputs (many
  // primitives with equal centres): such a node just becomes a larger leaf.
  if (end - begin > 4 && depth < kMaxStack / 2 - 2) {
    int axis = 0;
    for (int i = 1; i < dim_; ++i) {
      if (chi[i] - clo[i] > chi[axis] - clo[axis]) axis = i;
    }
    const int mid = (begin + end) / 2;
    const int d = dim_;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::int32_t a, std::int32_t b) {
                       return lo[a * d + axis] + hi[a * d + axis] <
                              lo[b * d + axis] + hi[b * d + axis];
                     });
    node.left = build_node(begin, mid, lo, hi, depth + 1);
    node.right = build_node(mid, end, lo, hi, depth + 1);
  }
  nodes_[index] = node;
  return index;
}

}  // namespace tmop
