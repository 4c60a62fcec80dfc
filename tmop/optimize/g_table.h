// tmop/optimize/g_table.h
// GTable: the precomputed matrices G_i = W^-T grad N_i(xi) of every sample point of a stage (one
// n x d block per point and metric term, row-major), with bit-identical blocks stored once.
#ifndef TMOP_OPTIMIZE_G_TABLE_H_
#define TMOP_OPTIMIZE_G_TABLE_H_

#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace tmop {

// G = W^-T grad N per sample point and term, each distinct block stored once: uniform targets
// (ideal shapes of one size) give one block per cell type and point of the rule, so the table
// is tiny instead of n x d doubles per point (96 MB for 1M tets), and the blocks stay in cache.
struct GTable {
  std::vector<double> values;
  std::vector<std::int64_t> offset;  // per sample point
  const double* at(std::size_t p) const { return values.data() + offset[p]; }
};

// Builds a GTable from blocks given one at a time (`add`), sharing bit-identical ones.
class GTableBuilder {
 public:
  explicit GTableBuilder(GTable* table, std::size_t points) : table_(table) {
    table_->offset.reserve(points);
  }
  void add(const double* block, int size) {
    std::uint64_t h = 1469598103934665603ULL ^ static_cast<std::uint64_t>(size);
    for (int k = 0; k < size; ++k) {
      std::uint64_t bits;
      std::memcpy(&bits, block + k, sizeof bits);
      h = (h ^ bits) * 1099511628211ULL;
    }
    std::vector<std::int64_t>& bucket = index_[h];
    for (std::int64_t off : bucket)
      if (std::memcmp(table_->values.data() + off, block, size * sizeof(double)) == 0) {
        table_->offset.push_back(off);
        return;
      }
    const std::int64_t off = static_cast<std::int64_t>(table_->values.size());
    table_->values.insert(table_->values.end(), block, block + size);
    bucket.push_back(off);
    table_->offset.push_back(off);
  }

 private:
  GTable* table_;
  std::unordered_map<std::uint64_t, std::vector<std::int64_t>> index_;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_G_TABLE_H_
