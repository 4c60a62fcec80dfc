#include "tmop/partition/partition.h"

#include <metis.h>

#include <algorithm>
#include <string>
#include <thread>

#include "tmop/element/cell_type.h"

namespace tmop {

VertexCells vertex_cells(const Mesh& mesh) {
  const int d = mesh.dim();
  VertexCells vc;
  vc.offset.assign(static_cast<std::size_t>(mesh.num_vertices()) + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d))
      for (int i = 0; i < mesh.cell_size(c); ++i) ++vc.offset[mesh.cell(c)[i] + 1];
  for (int v = 0; v < mesh.num_vertices(); ++v) vc.offset[v + 1] += vc.offset[v];
  vc.cell.resize(static_cast<std::size_t>(vc.offset.back()));
  std::vector<std::int64_t> next(vc.offset.begin(), vc.offset.end() - 1);
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d))
      for (int i = 0; i < mesh.cell_size(c); ++i) vc.cell[next[mesh.cell(c)[i]]++] = c;
  return vc;  // cells ascend per vertex: they were visited in order
}

namespace {

std::string metis_error(int code) {
  switch (code) {
    case METIS_ERROR_INPUT:
      return "input error";
    case METIS_ERROR_MEMORY:
      return "out of memory";
    default:
      return "error " + std::to_string(code);
  }
}

// Whether elements a and b (corner lists) share a corner flagged in `avoid`.
bool share_avoided(const Mesh& mesh, int a, int b, const std::vector<char>& avoid) {
  const int na = cell_info(mesh.cell_type(a)).num_corners;
  const int nb = cell_info(mesh.cell_type(b)).num_corners;
  for (int i = 0; i < na; ++i) {
    const int v = mesh.cell(a)[i];
    if (!avoid[v]) continue;
    for (int j = 0; j < nb; ++j)
      if (mesh.cell(b)[j] == v) return true;
  }
  return false;
}

}  // namespace

static_assert(sizeof(idx_t) == sizeof(std::int32_t), "METIS built with 32-bit indices expected");

// Elements e and f are adjacent when they share at least d corners (METIS_MeshToDual's
// "ncommon" = d, computed here through corner -> element lists: 1M tets 1.3 s -> 0.2 s,
// docs/partitioning.md). Through corners only: a quadratic facet shares its mid-edge nodes
// too, but d corners decide adjacency alike for every cell type. Neighbours ascend.
Status element_graph(const Mesh& mesh, ElementGraph* graph, int threads) {
  const int d = mesh.dim();
  *graph = ElementGraph();
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) graph->element_cell.push_back(c);
  const std::size_t ne = graph->element_cell.size();
  graph->xadj.assign(ne + 1, 0);
  if (ne < 2) return Status::Ok();
  const auto corners = [&](std::size_t e) {
    return cell_info(mesh.cell_type(graph->element_cell[e])).num_corners;
  };
  const int nv = mesh.num_vertices();
  std::vector<std::int64_t> vptr(static_cast<std::size_t>(nv) + 1, 0);
  for (std::size_t e = 0; e < ne; ++e) {
    const int* n = mesh.cell(graph->element_cell[e]);
    for (int i = 0; i < corners(e); ++i) ++vptr[n[i] + 1];
  }
  for (int v = 0; v < nv; ++v) vptr[v + 1] += vptr[v];
  std::vector<std::int32_t> velem(static_cast<std::size_t>(vptr[nv]));
  {
    std::vector<std::int64_t> next(vptr.begin(), vptr.end() - 1);
    for (std::size_t e = 0; e < ne; ++e) {
      const int* n = mesh.cell(graph->element_cell[e]);
      for (int i = 0; i < corners(e); ++i) velem[next[n[i]]++] = static_cast<std::int32_t>(e);
    }
  }
  // Neighbours of the elements [begin, end) into adj (concatenated) and deg (one count each).
  // A worker's own (mark, shared) slots per element: one cache line per touched candidate.
  const int ncommon = std::max(1, d);
  struct Slot {
    std::int32_t mark = -1, shared = 0;
  };
  const auto neighbours_of = [&](std::size_t begin, std::size_t end, std::vector<std::int32_t>* adj,
                                 std::vector<std::int32_t>* deg) {
    std::vector<Slot> slot(ne);
    std::vector<std::int32_t> touched, found;
    for (std::size_t e = begin; e < end; ++e) {
      const std::int32_t self = static_cast<std::int32_t>(e);
      touched.clear();
      const int* n = mesh.cell(graph->element_cell[e]);
      for (int i = 0; i < corners(e); ++i)
        for (std::int64_t k = vptr[n[i]]; k < vptr[n[i] + 1]; ++k) {
          const std::int32_t f = velem[static_cast<std::size_t>(k)];
          if (f == self) continue;
          Slot& t = slot[static_cast<std::size_t>(f)];
          if (t.mark != self) {
            t.mark = self;
            t.shared = 1;
            touched.push_back(f);
          } else {
            ++t.shared;
          }
        }
      found.clear();
      for (const std::int32_t f : touched)
        if (slot[static_cast<std::size_t>(f)].shared >= ncommon) found.push_back(f);
      std::sort(found.begin(), found.end());
      adj->insert(adj->end(), found.begin(), found.end());
      deg->push_back(static_cast<std::int32_t>(found.size()));
    }
  };
  // Contiguous ranges, concatenated in order: the graph does not depend on the threads.
  const int workers = static_cast<int>(
      std::max<std::size_t>(1, std::min<std::size_t>(std::max(1, threads), ne / 4096 + 1)));
  std::vector<std::vector<std::int32_t>> adj(workers), deg(workers);
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w)
    pool.emplace_back(neighbours_of, ne * w / workers, ne * (w + 1) / workers, &adj[w], &deg[w]);
  neighbours_of(0, ne / workers, &adj[0], &deg[0]);
  for (std::thread& t : pool) t.join();
  std::size_t edges = 0;
  for (const auto& a : adj) edges += a.size();
  if (edges > 0x7fffffffu)
    return Status::Failure("partition: the element graph has more than 2^31 edges");
  graph->adjncy.reserve(edges);
  std::size_t e = 0;
  for (int w = 0; w < workers; ++w) {
    graph->adjncy.insert(graph->adjncy.end(), adj[w].begin(), adj[w].end());
    std::vector<std::int32_t>().swap(adj[w]);
    for (const std::int32_t k : deg[w]) {
      graph->xadj[e + 1] = graph->xadj[e] + k;
      ++e;
    }
  }
  return Status::Ok();
}

Status partition_elements(const Mesh& mesh, const ElementGraph& graph,
                          const PartitionOptions& options, std::vector<int>* part) {
  const std::vector<int>& element_cell = graph.element_cell;
  part->assign(mesh.num_cells(), -1);
  idx_t ne = static_cast<idx_t>(element_cell.size());
  if (ne == 0) return Status::Ok();
  if (options.num_parts <= 1 || ne < options.num_parts) {
    for (const int c : element_cell) (*part)[c] = 0;
    return Status::Ok();
  }
  std::vector<idx_t> vwgt, adjwgt;
  if (options.cell_weight) {
    vwgt.resize(element_cell.size());
    for (std::size_t e = 0; e < element_cell.size(); ++e)
      vwgt[e] = std::max(1, (*options.cell_weight)[element_cell[e]]);
  }
  if (options.avoid) {
    adjwgt.resize(graph.adjncy.size());
    for (idx_t e = 0; e < ne; ++e)
      for (idx_t k = graph.xadj[e]; k < graph.xadj[e + 1]; ++k)
        adjwgt[k] =
            share_avoided(mesh, element_cell[e], element_cell[graph.adjncy[k]], *options.avoid)
                ? options.avoid_weight
                : 1;
  }
  idx_t metis_options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(metis_options);
  metis_options[METIS_OPTION_SEED] = options.seed;
  metis_options[METIS_OPTION_NUMBERING] = 0;
  idx_t ncon = 1, nparts = options.num_parts, objval = 0;
  std::vector<idx_t> element_part(element_cell.size(), 0);
  // METIS takes non-const pointers but does not change the graph.
  const int rc = METIS_PartGraphKway(
      &ne, &ncon, const_cast<idx_t*>(graph.xadj.data()), const_cast<idx_t*>(graph.adjncy.data()),
      vwgt.empty() ? nullptr : vwgt.data(), nullptr, adjwgt.empty() ? nullptr : adjwgt.data(),
      &nparts, nullptr, nullptr, metis_options, &objval, element_part.data());
  if (rc != METIS_OK) return Status::Failure("partition: METIS_PartGraphKway: " + metis_error(rc));
  for (std::size_t e = 0; e < element_cell.size(); ++e) (*part)[element_cell[e]] = element_part[e];
  return Status::Ok();
}

std::vector<char> cut_vertices(const Mesh& mesh, const VertexCells& vc,
                               const std::vector<int>& part) {
  std::vector<char> cut(mesh.num_vertices(), 0);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const std::int32_t* b = vc.begin(v);
    for (const std::int32_t* c = b; c != vc.end(v); ++c)
      if (part[*c] != part[*b]) {
        cut[v] = 1;
        break;
      }
  }
  return cut;
}

}  // namespace tmop
