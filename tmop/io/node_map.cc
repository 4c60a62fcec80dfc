#include "tmop/io/node_map.h"

#include <algorithm>

namespace tmop {
namespace io {

bool NodeMap::build(const std::vector<std::int64_t>& tags, std::int64_t* duplicate) {
  std::int64_t max_tag = 0;
  bool negative = false;
  for (std::int64_t t : tags) {
    max_tag = std::max(max_tag, t);
    negative |= t < 0;
  }
  // Dense while the table is at most ~4x the node count: bounded by the file size.
  dense_mode_ = !negative && max_tag <= 4 * static_cast<std::int64_t>(tags.size()) + 1024;
  dense_.clear();
  sparse_.clear();
  if (dense_mode_) {
    dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      std::int32_t& slot = dense_[static_cast<std::size_t>(tags[i])];
      if (slot >= 0) {
        *duplicate = tags[i];
        return false;
      }
      slot = static_cast<std::int32_t>(i);
    }
  } else {
    sparse_.reserve(tags.size());
    for (std::size_t i = 0; i < tags.size(); ++i) {
      if (!sparse_.emplace(tags[i], static_cast<std::int32_t>(i)).second) {
        *duplicate = tags[i];
        return false;
      }
    }
  }
  return true;
}

}  // namespace io
}  // namespace tmop
