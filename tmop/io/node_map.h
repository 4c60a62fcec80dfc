// tmop/io/node_map.h
// NodeMap: file node tags (Gmsh ids, 1-based, possibly sparse) -> 0-based vertex indices. Dense
// storage when tags are compact (the usual case), a hash map when they are sparse, so a file
// with a huge tag cannot make the reader allocate a huge table.
#ifndef TMOP_IO_NODE_MAP_H_
#define TMOP_IO_NODE_MAP_H_

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace tmop {
namespace io {

class NodeMap {
 public:
  // tags[i] is the tag of vertex i. Returns false (and *duplicate) if a tag repeats.
  bool build(const std::vector<std::int64_t>& tags, std::int64_t* duplicate);
  // Vertex index of a tag, -1 when the file did not define it.
  std::int32_t find(std::int64_t tag) const {
    if (dense_mode_) {
      if (tag < 0 || static_cast<std::uint64_t>(tag) >= dense_.size()) return -1;
      return dense_[static_cast<std::size_t>(tag)];
    }
    auto it = sparse_.find(tag);
    return it == sparse_.end() ? -1 : it->second;
  }

 private:
  bool dense_mode_ = true;
  std::vector<std::int32_t> dense_;
  std::unordered_map<std::int64_t, std::int32_t> sparse_;
};

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_NODE_MAP_H_
