#include "tools/bench/perturb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tmop/element/cell_type.h"
#include "tmop/element/sample_points.h"
#include "tmop/element/shape.h"
#include "tmop/mesh/topology.h"
#include "tmop/optimize/sample_measures.h"

namespace tmop_bench {
namespace {

// splitmix64: a portable stream of 64-bit values (std distributions differ between libraries).
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0) * 2 - 1; }  // [-1, 1)
};

bool cell_valid(const tmop::Mesh& mesh, int c) {
  const tmop::CellType type = mesh.cell_type(c);
  const int d = mesh.space_dim, n = mesh.cell_size(c);
  double xs[tmop::kMaxCellNodes * 3], A[9];
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < d; ++a) xs[i * d + a] = mesh.vertex(mesh.cell(c)[i])[a];
  for (const tmop::SamplePoint& sp : tmop::sample_points(type, tmop::SampleRule::kDefault)) {
    tmop::cell_jacobian(type, xs, d, sp.xi, A);
    if (!(tmop::det_d(A, d) > 0)) return false;
  }
  return true;
}

}  // namespace

void perturb(tmop::Mesh* mesh, double amount, std::uint64_t seed, bool keep_valid, int* moved) {
  const int d = mesh->dim(), sd = mesh->space_dim, nv = mesh->num_vertices();
  const std::vector<char> boundary = tmop::boundary_vertex_mask(*mesh);
  const tmop::Adjacency adj = tmop::vertex_to_cells(*mesh);
  std::vector<double> shortest(nv, std::numeric_limits<double>::infinity());
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!mesh->is_element(c, d)) continue;
    const tmop::CellInfo& info = tmop::cell_info(mesh->cell_type(c));
    const std::int32_t* nodes = mesh->cell(c);
    for (int e = 0; e < info.num_edges; ++e) {
      const int a = nodes[info.edges[e][0]], b = nodes[info.edges[e][1]];
      double l2 = 0;
      for (int k = 0; k < sd; ++k) {
        const double t = mesh->vertex(a)[k] - mesh->vertex(b)[k];
        l2 += t * t;
      }
      const double l = std::sqrt(l2);
      shortest[a] = std::min(shortest[a], l);
      shortest[b] = std::min(shortest[b], l);
    }
  }
  *moved = 0;
  for (int v = 0; v < nv; ++v) {
    if (boundary[v] || adj.offsets[v] == adj.offsets[v + 1] || !std::isfinite(shortest[v]))
      continue;
    Rng rng{seed * 1000003ULL + static_cast<std::uint64_t>(v)};
    double* x = mesh->vertex(v);
    double old[3] = {0, 0, 0};
    for (int a = 0; a < sd; ++a) old[a] = x[a];
    for (int attempt = 0; attempt < 20; ++attempt) {
      double dir[3] = {0, 0, 0}, norm2 = 0;
      do {  // uniform direction: rejection-sample the unit ball
        norm2 = 0;
        for (int a = 0; a < sd; ++a) {
          dir[a] = rng.uniform();
          norm2 += dir[a] * dir[a];
        }
      } while (norm2 > 1 || norm2 < 1e-6);
      const double s = amount * shortest[v] / std::sqrt(norm2);
      for (int a = 0; a < sd; ++a) x[a] = old[a] + s * dir[a];
      bool ok = true;
      if (keep_valid)
        for (std::int64_t k = adj.offsets[v]; k < adj.offsets[v + 1] && ok; ++k)
          ok = cell_valid(*mesh, adj.items[k]);
      if (ok) {
        ++*moved;
        break;
      }
      for (int a = 0; a < sd; ++a) x[a] = old[a];
    }
  }
}

}  // namespace tmop_bench
