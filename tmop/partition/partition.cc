#include "tmop/partition/partition.h"

#include <metis.h>

#include <algorithm>
#include <string>

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

// Frees METIS's arrays on every path.
struct MetisArrays {
  idx_t* xadj = nullptr;
  idx_t* adjncy = nullptr;
  ~MetisArrays() {
    if (xadj) METIS_Free(xadj);
    if (adjncy) METIS_Free(adjncy);
  }
};

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

Status element_graph(const Mesh& mesh, ElementGraph* graph) {
  const int d = mesh.dim();
  *graph = ElementGraph();
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) graph->element_cell.push_back(c);
  idx_t ne = static_cast<idx_t>(graph->element_cell.size());
  graph->xadj.assign(1, 0);
  if (ne < 2) {
    graph->xadj.assign(static_cast<std::size_t>(ne) + 1, 0);
    return Status::Ok();
  }
  // Through corners only: a quadratic facet shares its mid-edge nodes too, but d corners
  // decide adjacency alike for every cell type.
  std::vector<idx_t> eptr(graph->element_cell.size() + 1, 0), eind;
  for (std::size_t e = 0; e < graph->element_cell.size(); ++e) {
    const int c = graph->element_cell[e];
    const int k = cell_info(mesh.cell_type(c)).num_corners;
    eind.insert(eind.end(), mesh.cell(c), mesh.cell(c) + k);
    eptr[e + 1] = static_cast<idx_t>(eind.size());
  }
  idx_t nn = mesh.num_vertices(), ncommon = d, numflag = 0;
  MetisArrays dual;
  const int rc = METIS_MeshToDual(&ne, &nn, eptr.data(), eind.data(), &ncommon, &numflag,
                                  &dual.xadj, &dual.adjncy);
  if (rc != METIS_OK) return Status::Failure("partition: METIS_MeshToDual: " + metis_error(rc));
  graph->xadj.assign(dual.xadj, dual.xadj + ne + 1);
  graph->adjncy.assign(dual.adjncy, dual.adjncy + dual.xadj[ne]);
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
