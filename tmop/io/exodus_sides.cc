// tmop/io/exodus_sides.cc
// Exodus II side sets (exodus_sides.h): the side table, building a side's boundary cell, which
// regions can be side sets, and reading / writing them through libexodusii.
#include "tmop/io/exodus_sides.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <unordered_map>

#include "tmop/io/node_order.h"

#ifdef TMOP_WITH_EXODUS
#include <exodusII.h>

#include "tmop/core/status.h"
#endif

namespace tmop {
namespace io {
namespace {

struct Side {
  int n;     // corners
  int c[4];  // 1-based Exodus corner positions, outward
};
const Side kHexSides[] = {{4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 4, 8, 7}},
                          {4, {1, 5, 8, 4}}, {4, {1, 4, 3, 2}}, {4, {5, 6, 7, 8}}};
const Side kTetSides[] = {{3, {1, 2, 4}}, {3, {2, 3, 4}}, {3, {1, 4, 3}}, {3, {1, 3, 2}}};
const Side kWedgeSides[] = {
    {4, {1, 2, 5, 4}}, {4, {2, 3, 6, 5}}, {4, {1, 4, 6, 3}}, {3, {1, 3, 2}}, {3, {4, 5, 6}}};
const Side kPyramidSides[] = {
    {3, {1, 2, 5}}, {3, {2, 3, 5}}, {3, {3, 4, 5}}, {3, {1, 5, 4}}, {4, {1, 4, 3, 2}}};
const Side kTriSides[] = {{2, {1, 2}}, {2, {2, 3}}, {2, {3, 1}}};
const Side kQuadSides[] = {{2, {1, 2}}, {2, {2, 3}}, {2, {3, 4}}, {2, {4, 1}}};

const Side* side_table(CellType t, int num_dim, int* n) {
  *n = 0;
  switch (cell_info(t).linear) {
    case CellType::kHex8:
      return *n = 6, kHexSides;
    case CellType::kTet4:
      return *n = 4, kTetSides;
    case CellType::kWedge6:
      return *n = 5, kWedgeSides;
    case CellType::kPyramid5:
      return *n = 5, kPyramidSides;
    case CellType::kTri3:
      if (num_dim == 2) *n = 3;
      return kTriSides;
    case CellType::kQuad4:
      if (num_dim == 2) *n = 4;
      return kQuadSides;
    default:
      return nullptr;
  }
}

// The Gmsh corner index of 0-based Exodus corner position p.
int gmsh_corner(CellType t, int p) {
  for (int i = 0; i < cell_info(t).num_corners; ++i)
    if (patran_index_of_gmsh_node(t, i, PatranFormat::kExodus) == p) return i;
  return -1;
}

// The mid-edge node (local index) of the edge between corners a and b, -1 when none.
int mid_edge(const CellInfo& info, int a, int b) {
  for (int e = 0; e < info.num_edges; ++e)
    if ((info.edges[e][0] == a && info.edges[e][1] == b) ||
        (info.edges[e][0] == b && info.edges[e][1] == a))
      return info.num_corners + e;
  return -1;
}

// The face node (local index) of the facet with corners g[0..n), -1 when none.
int face_node(const CellInfo& info, const int* g, int n) {
  for (int f = 0; f < info.num_facets; ++f) {
    const CellFacet& fc = info.facets[f];
    if (fc.num_corners != n) continue;
    bool same = true;
    for (int j = 0; j < n && same; ++j) same = std::count(g, g + n, fc.corners[j]) == 1;
    if (same) return facet_node(info, f);
  }
  return -1;
}

// Sorted node set of up to 9 nodes (n <= 9: callers check), padded with -1: equal keys are equal
// node sets.
using Key = std::array<std::int32_t, 9>;
Key key_of(const std::int32_t* nodes, int n) {
  Key k;
  k.fill(-1);
  std::copy(nodes, nodes + n, k.begin());
  std::sort(k.begin(), k.begin() + n);
  return k;
}
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = 1469598103934665603ull;
    for (std::int32_t v : k) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
    return h;
  }
};

}  // namespace

int exodus_num_sides(CellType t, int num_dim) {
  int n = 0;
  side_table(t, num_dim, &n);
  return n;
}

bool exodus_side_cell(const Mesh& mesh, int cell, int side, int num_dim, CellType* type,
                      std::int32_t* nodes) {
  const CellType t = mesh.cell_types[cell];
  int ns = 0;
  const Side* table = side_table(t, num_dim, &ns);
  if (side < 1 || side > ns) return false;
  const Side& s = table[side - 1];
  const CellInfo& info = cell_info(t);
  const std::int32_t* cn = mesh.cell(cell);
  int g[4];
  for (int j = 0; j < s.n; ++j) {
    g[j] = gmsh_corner(t, s.c[j] - 1);
    nodes[j] = cn[g[j]];
  }
  if (info.order == 1) {
    *type = s.n == 2 ? CellType::kLine2 : s.n == 3 ? CellType::kTri3 : CellType::kQuad4;
    return true;
  }
  const int edges = s.n == 2 ? 1 : s.n;
  for (int j = 0; j < edges; ++j) nodes[s.n + j] = cn[mid_edge(info, g[j], g[(j + 1) % s.n])];
  *type = s.n == 2 ? CellType::kLine3 : s.n == 3 ? CellType::kTri6 : CellType::kQuad8;
  const int fnode = s.n == 4 ? face_node(info, g, 4) : -1;
  if (fnode >= 0) {
    nodes[8] = cn[fnode];
    *type = CellType::kQuad9;
  }
  return true;
}

std::vector<ExoSideSet> plan_exodus_side_sets(const Mesh& mesh, const std::vector<int>& elem_number,
                                              int num_dim) {
  std::vector<ExoSideSet> sets;
  const int top = mesh.dim();
  if (top < 2 || top != num_dim) return sets;
  // Every side of every element, by its corner set; the first element wins for shared faces.
  struct Ref {
    Key key;
    int cell, side;
  };
  std::vector<Ref> refs;
  std::int32_t nodes[kMaxCellNodes];
  CellType st;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (cell_dim(mesh.cell_types[c]) != top) continue;
    const int ns = exodus_num_sides(mesh.cell_types[c], num_dim);
    for (int s = 1; s <= ns; ++s)
      if (exodus_side_cell(mesh, c, s, num_dim, &st, nodes))
        refs.push_back({key_of(nodes, cell_info(st).num_corners), c, s});
  }
  std::stable_sort(refs.begin(), refs.end(),
                   [](const Ref& a, const Ref& b) { return a.key < b.key; });
  std::map<int, std::vector<int> > regions;  // region -> its boundary cells
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (cell_dim(mesh.cell_types[c]) == top - 1) regions[mesh.cell_region[c]].push_back(c);
  for (const auto& r : regions) {
    if (r.first <= 0) continue;
    ExoSideSet set;
    set.id = r.first;
    bool all = true;
    for (std::size_t k = 0; k < r.second.size() && all; ++k) {
      const int c = r.second[k];
      const CellType t = mesh.cell_types[c];
      const Key corners = key_of(mesh.cell(c), cell_info(t).num_corners);
      const Key full = key_of(mesh.cell(c), cell_num_nodes(t));
      Ref probe{corners, -1, 0};
      auto it = std::lower_bound(refs.begin(), refs.end(), probe,
                                 [](const Ref& a, const Ref& b) { return a.key < b.key; });
      all = false;
      for (; it != refs.end() && it->key == corners && !all; ++it) {
        exodus_side_cell(mesh, it->cell, it->side, num_dim, &st, nodes);
        if (st != t || key_of(nodes, cell_num_nodes(st)) != full) continue;
        set.elems.push_back(elem_number[it->cell]);
        set.sides.push_back(it->side);
        all = true;
      }
    }
    if (!all) continue;
    const std::string* name = mesh.physical_name(top - 1, r.first);
    if (name) set.name = name->substr(0, 255);
    sets.push_back(set);
  }
  return sets;
}

#ifdef TMOP_WITH_EXODUS

std::vector<std::string> exodus_names(int exo, int type, int n) {
  std::vector<std::string> out(n);
  const int len = static_cast<int>(ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  if (n == 0 || len <= 0 || len > 255) return out;
  ex_set_max_name_length(exo, len);
  std::vector<std::vector<char> > buf(n, std::vector<char>(len + 1, '\0'));
  std::vector<char*> ptr(n);
  for (int b = 0; b < n; ++b) ptr[b] = buf[b].data();
  if (ex_get_names(exo, static_cast<ex_entity_type>(type), ptr.data()) < 0) return out;
  for (int b = 0; b < n; ++b) out[b] = std::string(buf[b].data());
  return out;
}

void write_exodus_side_sets(const std::string& path, int exo, const std::vector<ExoSideSet>& sets) {
  for (const ExoSideSet& s : sets) {
    const std::string what = path + ": cannot write side set " + std::to_string(s.id);
    if (ex_put_set_param(exo, EX_SIDE_SET, s.id, static_cast<std::int64_t>(s.elems.size()), 0) < 0)
      throw Error(what);
    if (!s.elems.empty() && ex_put_set(exo, EX_SIDE_SET, s.id, s.elems.data(), s.sides.data()) < 0)
      throw Error(what);
  }
  std::vector<std::string> names;
  for (const ExoSideSet& s : sets) names.push_back(s.name);
  if (std::all_of(names.begin(), names.end(), [](const std::string& n) { return n.empty(); }))
    return;
  std::vector<char*> ptr;
  for (std::string& n : names) ptr.push_back(&n[0]);
  if (ex_put_names(exo, EX_SIDE_SET, ptr.data()) < 0)
    throw Error(path + ": cannot write the Exodus II side set names");
}

void read_exodus_side_sets(const std::string& path, int exo, std::uint64_t file_size, int nss,
                           int num_dim, int first, int num_elems, Mesh* mesh) {
  if (nss <= 0) return;
  if (static_cast<std::uint64_t>(nss) * 4 > file_size)
    throw Error(path + ": the header declares " + std::to_string(nss) +
                " side sets, more than the file holds");
  std::vector<int> ids(nss);
  if (ex_get_ids(exo, EX_SIDE_SET, ids.data()) < 0)
    throw Error(path + ": cannot read the Exodus II side set ids");
  const std::vector<std::string> names = exodus_names(exo, EX_SIDE_SET, nss);
  std::unordered_map<Key, int, KeyHash> have;  // node set -> cell
  have.reserve(static_cast<std::size_t>(mesh->num_cells()));
  for (int c = 0; c < mesh->num_cells(); ++c)  // sides: dimension < num_dim, at most 9 nodes
    if (cell_dim(mesh->cell_types[c]) < num_dim &&
        mesh->cell_size(c) <= static_cast<int>(Key().size()))
      have.emplace(key_of(mesh->cell(c), mesh->cell_size(c)), c);
  std::int32_t nodes[kMaxCellNodes];
  for (int k = 0; k < nss; ++k) {
    const int id = ids[k];
    const std::string set = path + ": side set " + std::to_string(id);
    if (id <= 0) throw Error(set + ": the id is not positive");
    int n = 0, ndf = 0;
    if (ex_get_set_param(exo, EX_SIDE_SET, id, &n, &ndf) < 0)
      throw Error(set + ": cannot read its size");
    if (n < 0 || static_cast<std::uint64_t>(n) * 8 > file_size)
      throw Error(set + " declares " + std::to_string(n) + " sides, more than the file holds");
    std::vector<int> elems(n), sides(n);
    if (n > 0 && ex_get_set(exo, EX_SIDE_SET, id, elems.data(), sides.data()) < 0)
      throw Error(set + ": cannot read its elements and sides");
    for (int j = 0; j < n; ++j) {
      const int e = elems[j];
      if (e < 1 || e > num_elems)
        throw Error(set + ", entry " + std::to_string(j + 1) + ": element " + std::to_string(e) +
                    " is out of range 1.." + std::to_string(num_elems));
      const int cell = first + e - 1;
      const CellType et = mesh->cell_types[cell];
      const int ns = exodus_num_sides(et, num_dim);
      if (ns == 0) continue;  // sides of 1D elements and shells: not read (exodus_sides.h)
      CellType t;
      if (!exodus_side_cell(*mesh, cell, sides[j], num_dim, &t, nodes))
        throw Error(set + ", entry " + std::to_string(j + 1) + ": side " +
                    std::to_string(sides[j]) + " is out of range 1.." + std::to_string(ns) +
                    " of element " + std::to_string(e) + " (" + cell_name(et) + ")");
      const Key key = key_of(nodes, cell_num_nodes(t));
      auto it = have.find(key);
      int dim = cell_dim(t), region = id;
      if (it != have.end()) {
        dim = cell_dim(mesh->cell_types[it->second]);
        region = mesh->cell_region[it->second];
      } else {
        have.emplace(key, mesh->add_cell(t, nodes, id, 0));
      }
      if (!names[k].empty() && !mesh->physical_name(dim, region))
        mesh->set_physical_name(dim, region, names[k]);
    }
  }
}

#endif  // TMOP_WITH_EXODUS

}  // namespace io
}  // namespace tmop
