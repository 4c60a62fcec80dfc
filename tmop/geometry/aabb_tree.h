// tmop/geometry/aabb_tree.h
// AabbTree: a bounding-volume hierarchy of axis-aligned boxes over n primitives (segments,
// triangles) in 2D or 3D, for closest-primitive queries.
//
// Build(dim, lo, hi): lo / hi hold n * dim box bounds (primitive-major). Median split on the
// longest axis of the box centres, leaves of up to 4 primitives; O(n log n), the only allocation.
// Nearest(q, max_dist2, dist2): the primitive closest to q among those whose squared distance is
// <= max_dist2 (pass infinity for an unbounded search), where dist2(prim) is the caller's exact
// squared distance of q from that primitive. Returns the primitive index (-1 when none is within
// max_dist2) and its squared distance in *best_dist2. Nearer boxes are opened first and boxes
// farther than the best so far are skipped, so a query costs O(log n) for well-shaped meshes. A
// fixed-size stack keeps queries allocation-free and thread-safe (the tree is read-only).
#ifndef TMOP_GEOMETRY_AABB_TREE_H_
#define TMOP_GEOMETRY_AABB_TREE_H_

#include <cstdint>
#include <limits>
#include <vector>

namespace tmop {

class AabbTree {
 public:
  void Build(int dim, const std::vector<double>& lo, const std::vector<double>& hi);

  template <class Dist2>
  int Nearest(const double* q, double max_dist2, const Dist2& dist2, double* best_dist2) const;

  int size() const { return static_cast<int>(order_.size()); }

 private:
  struct Node {
    double lo[3], hi[3];
    std::int32_t left;        // child index, or -1 for a leaf
    std::int32_t right;       // child index (inner node)
    std::int32_t begin, end;  // primitives order_[begin, end) (leaf)
  };
  int build_node(int begin, int end, const std::vector<double>& lo, const std::vector<double>& hi,
                 int depth);
  double box_dist2(const Node& node, const double* q) const {
    double s = 0;
    for (int i = 0; i < dim_; ++i) {
      const double d =
          q[i] < node.lo[i] ? node.lo[i] - q[i] : (q[i] > node.hi[i] ? q[i] - node.hi[i] : 0.0);
      s += d * d;
    }
    return s;
  }

  // Median splits keep the depth near log2(n / 4); 96 levels cover any mesh that fits in memory
  // with room for the one pending sibling per level the traversal keeps.
  static constexpr int kMaxStack = 96;
  int dim_ = 3;
  std::vector<Node> nodes_;
  std::vector<std::int32_t> order_;
};

template <class Dist2>
int AabbTree::Nearest(const double* q, double max_dist2, const Dist2& dist2,
                      double* best_dist2) const {
  int best = -1;
  double best_d2 = max_dist2;
  if (nodes_.empty()) {
    *best_dist2 = std::numeric_limits<double>::infinity();
    return -1;
  }
  std::int32_t stack[kMaxStack];
  double stack_d2[kMaxStack];
  int top = 0;
  stack[top] = 0;
  stack_d2[top++] = box_dist2(nodes_[0], q);
  while (top > 0) {
    --top;
    if (stack_d2[top] > best_d2) continue;
    const Node& node = nodes_[stack[top]];
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) {
        const double d2 = dist2(order_[k]);
        if (d2 <= best_d2 && (best < 0 || d2 < best_d2 || order_[k] < best)) {
          best_d2 = d2;
          best = order_[k];
        }
      }
      continue;
    }
    const double dl = box_dist2(nodes_[node.left], q);
    const double dr = box_dist2(nodes_[node.right], q);
    // Push the farther child first so the nearer one is opened next.
    const bool left_first = dl <= dr;
    const int far_child = left_first ? node.right : node.left;
    const int near_child = left_first ? node.left : node.right;
    const double far_d2 = left_first ? dr : dl;
    const double near_d2 = left_first ? dl : dr;
    if (far_d2 <= best_d2 && top < kMaxStack) {
      stack[top] = far_child;
      stack_d2[top++] = far_d2;
    }
    if (near_d2 <= best_d2 && top < kMaxStack) {
      stack[top] = near_child;
      stack_d2[top++] = near_d2;
    }
  }
  *best_dist2 = best < 0 ? std::numeric_limits<double>::infinity() : best_d2;
  return best;
}

}  // namespace tmop

#endif  // TMOP_GEOMETRY_AABB_TREE_H_
