// tests/fuzz/same_mesh.cc: the round-trip comparison of same_mesh.h.
#include "tests/fuzz/same_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace tmop_fuzz {
namespace {

using tmop::CellType;
using tmop::Mesh;

double coord(const Mesh& m, int v, int k) {
  return k < m.space_dim ? m.coords[static_cast<std::size_t>(v) * m.space_dim + k] : m.plane_z;
}

std::uint64_t bits(double x) {  // a total order in which NaN equals itself
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The value the format keeps of x (written, read back) and the value read (taken as it is).
std::uint64_t kept(double x, const Holds& h, bool written) {
  if (!written) return bits(x);
  if (h.float32) x = static_cast<double>(static_cast<float>(x));
  if (h.fixed_decimals > 0) {
    char buf[400];
    std::snprintf(buf, sizeof buf, "%.*f", h.fixed_decimals, x);
    x = std::strtod(buf, nullptr);
  }
  return bits(x);
}

int num_coords(const Mesh& a, const Holds& h) { return a.space_dim == 2 && !h.plane_z ? 2 : 3; }

using Key = std::vector<std::uint64_t>;

std::string g17(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// (type, coordinates of the nodes in order), OpenMesh polygons rotated to their least corner.
Key cell_key(const Mesh& m, int c, int nc, const Holds& h, bool written) {
  const CellType t = m.cell_types[c];
  const int n = tmop::cell_num_nodes(t);
  std::vector<Key> nodes(n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < nc; ++k) nodes[i].push_back(kept(coord(m, m.cell(c)[i], k), h, written));
  if (h.rotate_polygons && (t == CellType::kTri3 || t == CellType::kQuad4))
    std::rotate(nodes.begin(), std::min_element(nodes.begin(), nodes.end()), nodes.end());
  Key key = {static_cast<std::uint64_t>(t)};
  for (const Key& p : nodes) key.insert(key.end(), p.begin(), p.end());
  return key;
}

std::vector<Key> keys(const Mesh& m, int nc, const Holds& h, bool written) {
  std::vector<Key> out;
  for (int c = 0; c < m.num_cells(); ++c) out.push_back(cell_key(m, c, nc, h, written));
  return out;
}

std::vector<int> order(const std::vector<Key>& k) {
  std::vector<int> o(k.size());
  std::iota(o.begin(), o.end(), 0);
  std::stable_sort(o.begin(), o.end(), [&](int x, int y) { return k[x] < k[y]; });
  return o;
}

std::string cell_text(const Mesh& m, int c) {
  std::string s = std::string(tmop::cell_name(m.cell_types[c])) + " cell " + std::to_string(c) +
                  " (region " + std::to_string(m.cell_region[c]) + ", nodes";
  for (int i = 0; i < tmop::cell_num_nodes(m.cell_types[c]); ++i)
    s += " " + std::to_string(m.cell(c)[i]);
  return s + ")";
}

std::string name_of(const Mesh& m, int c, const Holds& h) {
  const std::string* n = m.physical_name(tmop::cell_dim(m.cell_types[c]), m.cell_region[c]);
  return n ? "'" + n->substr(0, h.name_max) + "'" : "no name";
}

// Regions renumbered consistently and names kept, over the matched cells (a[i] <-> b[i]).
std::string regions_and_names(const Mesh& a, const Mesh& b,
                              const std::vector<std::pair<int, int>>& match, const Holds& h) {
  int top = 0;
  for (CellType t : a.cell_types) top = std::max(top, tmop::cell_dim(t));
  std::map<std::pair<int, int>, int> ab, ba;
  for (const auto& p : match) {
    const int ca = p.first, cb = p.second;
    const CellType t = a.cell_types[ca];
    if (h.regions == Holds::kBoundary && tmop::cell_dim(t) == top) continue;
    const int ra = a.cell_region[ca], rb = b.cell_region[cb];
    const auto x = ab.emplace(std::make_pair(static_cast<int>(t), ra), rb);
    const auto y = ba.emplace(std::make_pair(static_cast<int>(t), rb), ra);
    if (x.first->second != rb || y.first->second != ra)
      return cell_text(a, ca) + " -> " + cell_text(b, cb) + ": regions not renumbered one to one";
    if (h.names && name_of(a, ca, h) != name_of(b, cb, h))
      return cell_text(a, ca) + " named " + name_of(a, ca, h) + " -> " + cell_text(b, cb) +
             " named " + name_of(b, cb, h);
  }
  return "";
}

// A 3D mesh whose z varies by at most 1e-12 of its extent can read back flattened (finish_read)
// where the format rounds x and y (float32): the z dropped must be within that bound.
std::string flattened_z(const Mesh& a, const Mesh& b, const Holds& h) {
  double extent = 0;
  for (int v = 0; v < b.num_vertices(); ++v)
    extent = std::max({extent, std::abs(coord(b, v, 0)), std::abs(coord(b, v, 1))});
  if (!h.vertices) return "";
  for (int v = 0; v < a.num_vertices(); ++v) {
    const double z = static_cast<double>(static_cast<float>(coord(a, v, 2)));
    if (!(std::abs(z - b.plane_z) <= 1e-12 * extent))
      return "vertex " + std::to_string(v) + ": z " + g17(z) +
             " dropped (plane z = " + g17(b.plane_z) + ", extent " + g17(extent) + ")";
  }
  return "";
}

}  // namespace

Holds holds(const std::string& family, bool binary) {
  Holds h;
  if (family == "obj" || family == "off" || family == "ply") {
    h.float32 = true;
    h.rotate_polygons = true;
  }
  if (family == "obj") h.fixed_decimals = 17;
  if (family == "stl") {
    h.float32 = binary;
    h.vertices = false;
  }
  if (family == "su2") h.plane_z = false;
  if (family == "obj" || family == "off" || family == "ply" || family == "stl")
    h.regions = Holds::kNone;
  if (family == "su2" || family.find("ugrid") != std::string::npos) h.regions = Holds::kBoundary;
  h.names =
      family == "msh" || family == "vtk" || family == "vtu" || family == "exo" || family == "su2";
  if (family == "exo") h.name_max = 255;
  return h;
}

std::string mesh_difference(const Mesh& a, const Mesh& b, const Holds& h) {
  int nc = num_coords(a, h);
  if (h.float32 && a.space_dim == 3 && b.space_dim == 2) {
    const std::string d = flattened_z(a, b, h);
    if (!d.empty()) return d;
    nc = 2;
  }
  if (h.vertices) {
    if (a.num_vertices() != b.num_vertices()) return "vertex counts differ";
    for (int v = 0; v < a.num_vertices(); ++v)
      for (int k = 0; k < nc; ++k)
        if (kept(coord(a, v, k), h, true) != kept(coord(b, v, k), h, false))
          return "vertex " + std::to_string(v) + " coordinate " + std::to_string(k) + ": " +
                 g17(coord(a, v, k)) + " -> " + g17(coord(b, v, k)) + " (space_dim " +
                 std::to_string(a.space_dim) + " -> " + std::to_string(b.space_dim) + ")";
  }
  if (a.num_cells() != b.num_cells()) return "cell counts differ";
  const std::vector<Key> ka = keys(a, nc, h, true), kb = keys(b, nc, h, false);
  const std::vector<int> oa = order(ka), ob = order(kb);
  std::vector<std::pair<int, int>> match;
  for (std::size_t i = 0; i < oa.size(); ++i) {
    if (ka[oa[i]] != kb[ob[i]])
      return "cells differ in type, node order or coordinates: " + cell_text(a, oa[i]) +
             " has no equal in the mesh read back (first unmatched: " + cell_text(b, ob[i]) + ")";
    const bool dup =
        (i > 0 && ka[oa[i - 1]] == ka[oa[i]]) || (i + 1 < oa.size() && ka[oa[i + 1]] == ka[oa[i]]);
    if (!dup) match.emplace_back(oa[i], ob[i]);
  }
  if (h.regions == Holds::kNone) return "";
  return regions_and_names(a, b, match, h);
}

}  // namespace tmop_fuzz
