#include "tmop/mesh/validate.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace tmop {
namespace {

std::string CellPrefix(int c) { return "cell " + std::to_string(c) + ": "; }

// Node set of a cell, sorted (for duplicate detection).
int SortedNodes(const Mesh& mesh, int c, std::int32_t* out) {
  const int n = mesh.cell_size(c);
  std::copy(mesh.cell(c), mesh.cell(c) + n, out);
  std::sort(out, out + n);
  return n;
}

}  // namespace

Status validate_mesh(const Mesh& mesh) {
  if (mesh.space_dim != 2 && mesh.space_dim != 3)
    return Status::Failure("mesh: space_dim is " + std::to_string(mesh.space_dim) +
                           ", expected 2 or 3");
  if (mesh.coords.size() % mesh.space_dim != 0)
    return Status::Failure("mesh: " + std::to_string(mesh.coords.size()) +
                           " coordinates is not a multiple of space_dim");
  const std::size_t nc = mesh.cell_types.size();
  if (mesh.cell_offsets.size() != nc + 1 || mesh.cell_offsets.front() != 0 ||
      mesh.cell_offsets.back() != static_cast<std::int64_t>(mesh.cell_nodes.size()))
    return Status::Failure("mesh: cell_offsets does not match cell_types / cell_nodes");
  if (mesh.cell_region.size() != nc || mesh.cell_entity.size() != nc)
    return Status::Failure("mesh: cell_region / cell_entity must have one entry per cell");

  const int nv = mesh.num_vertices();
  for (int v = 0; v < nv; ++v)
    for (int j = 0; j < mesh.space_dim; ++j)
      if (!std::isfinite(mesh.vertex(v)[j]))
        return Status::Failure("vertex " + std::to_string(v) + ": coordinate " + std::to_string(j) +
                               " is " + std::to_string(mesh.vertex(v)[j]));

  for (int c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_type(c);
    if (static_cast<int>(t) >= kNumCellTypes)
      return Status::Failure(CellPrefix(c) + "unknown cell type " +
                             std::to_string(static_cast<int>(t)));
    if (cell_dim(t) > mesh.space_dim)
      return Status::Failure(CellPrefix(c) + cell_name(t) + " (dimension " +
                             std::to_string(cell_dim(t)) + ") in a mesh of space dimension " +
                             std::to_string(mesh.space_dim));
    if (mesh.cell_size(c) != cell_num_nodes(t))
      return Status::Failure(CellPrefix(c) + cell_name(t) + " has " +
                             std::to_string(mesh.cell_size(c)) + " nodes, expected " +
                             std::to_string(cell_num_nodes(t)));
    const std::int32_t* nodes = mesh.cell(c);
    for (int k = 0; k < mesh.cell_size(c); ++k)
      if (nodes[k] < 0 || nodes[k] >= nv)
        return Status::Failure(CellPrefix(c) + "node " + std::to_string(nodes[k]) +
                               " out of range 0.." + std::to_string(nv - 1));
    std::int32_t sorted[kMaxCellNodes];
    const int n = SortedNodes(mesh, c, sorted);
    for (int k = 1; k < n; ++k)
      if (sorted[k] == sorted[k - 1])
        return Status::Failure(CellPrefix(c) + "node " + std::to_string(sorted[k]) +
                               " appears more than once");
  }

  // Duplicate elements: sort the elements by a hash of their node set, then compare neighbours
  // with equal hashes exactly.
  const int d = mesh.dim();
  std::vector<std::pair<std::uint64_t, std::int32_t>> keys;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_type(c)) != d) continue;
    std::int32_t sorted[kMaxCellNodes];
    const int n = SortedNodes(mesh, c, sorted);
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the sorted indices
    for (int k = 0; k < n; ++k) {
      h ^= static_cast<std::uint32_t>(sorted[k]);
      h *= 1099511628211ull;
    }
    keys.emplace_back(h, c);
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size(); ++i) {
    for (std::size_t j = i + 1; j < keys.size() && keys[j].first == keys[i].first; ++j) {
      std::int32_t a[kMaxCellNodes], b[kMaxCellNodes];
      const int na = SortedNodes(mesh, keys[i].second, a);
      const int nb = SortedNodes(mesh, keys[j].second, b);
      if (na == nb && std::equal(a, a + na, b))
        return Status::Failure(CellPrefix(keys[j].second) + "same nodes as cell " +
                               std::to_string(keys[i].second));
    }
  }
  return Status::Ok();
}

}  // namespace tmop
