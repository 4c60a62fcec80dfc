#include "tmop/quality/element_scan.h"

#include "tmop/quality/parallel_for.h"

namespace tmop {
namespace {

bool planar(const Mesh& mesh, int dim) {
  if (dim != 2) return false;
  if (mesh.space_dim == 2) return true;
  for (int v = 1; v < mesh.num_vertices(); ++v)
    if (mesh.vertex(v)[2] != mesh.vertex(0)[2]) return false;
  return true;
}

}  // namespace

bool is_planar_2d(const Mesh& mesh) { return planar(mesh, mesh.dim()); }

int scan_elements(const Mesh& mesh, const QualityOptions& options,
                  const std::function<void(std::int64_t, std::int64_t, const CellQuality&)>& visit,
                  bool* is_planar) {
  const int d = mesh.dim();
  const bool flat = planar(mesh, d);
  if (is_planar != nullptr) *is_planar = flat;
  if (d < 2) return d;
  const double z_up[3] = {0, 0, 1};
  const double* up = flat ? z_up : nullptr;
  const int sd = mesh.space_dim;
  parallel_chunks(mesh.num_cells(), kScanChunk, options.threads,
                  [&](std::int64_t chunk, std::int64_t begin, std::int64_t end) {
                    double nodes[kMaxCellNodes * 3] = {};
                    for (std::int64_t c = begin; c < end; ++c) {
                      const CellType type = mesh.cell_types[c];
                      if (cell_dim(type) != d) continue;
                      const std::int32_t* cell = mesh.cell(static_cast<int>(c));
                      const int nn = cell_num_nodes(type);
                      for (int i = 0; i < nn; ++i) {
                        const double* x = mesh.vertex(cell[i]);
                        for (int k = 0; k < sd; ++k) nodes[3 * i + k] = x[k];
                      }
                      visit(chunk, c, cell_quality(type, nodes, up, options));
                    }
                  });
  return d;
}

}  // namespace tmop
