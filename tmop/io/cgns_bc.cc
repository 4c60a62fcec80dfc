// tmop/io/cgns_bc.cc
// CGNS ZoneBC_t / BC_t <-> boundary region names (cgns_bc.h).
#ifdef TMOP_WITH_CGNS

#include "tmop/io/cgns_bc.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "tmop/core/status.h"
#include "tmop/io/scanner.h"  // printable

namespace tmop {
namespace io {
namespace {

[[noreturn]] void bc_fail(const std::string& what) {
  std::string msg = cg_get_error();
  for (char& c : msg)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  if (msg.size() > 200) msg = msg.substr(0, 200) + "...";
  throw Error(what + (msg.empty() ? "" : " (" + msg + ")"));
}

bool valid_name(const std::string& name, const std::vector<std::string>& used) {
  return !name.empty() && name.size() <= 32 && name.find('/') == std::string::npos &&
         std::find(used.begin(), used.end(), name) == used.end();
}

}  // namespace

void write_cgns_bcs(const std::string& path, int fn, int B, int Z, const Mesh& mesh,
                    const std::vector<cgsize_t>& elem_number) {
  const int top = mesh.dim();
  if (top < 2) return;
  std::map<int, std::vector<cgsize_t> > regions;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (cell_dim(mesh.cell_types[c]) == top - 1 && mesh.cell_region[c] > 0)
      regions[mesh.cell_region[c]].push_back(elem_number[c]);
  std::vector<std::string> used;
  for (auto& r : regions) {
    std::vector<cgsize_t>& e = r.second;
    std::sort(e.begin(), e.end());
    const std::string* pname = mesh.physical_name(top - 1, r.first);
    std::string name = pname ? *pname : std::string();
    if (!valid_name(name, used)) name = "Region_" + std::to_string(r.first);
    if (!valid_name(name, used)) name = "Region_" + std::to_string(r.first) + "_bc";
    used.push_back(name);
    const bool range = e.back() - e.front() + 1 == static_cast<cgsize_t>(e.size());
    const cgsize_t lohi[2] = {e.front(), e.back()};
    int BC = 0, F = 0;
    const std::string what = path + ": cannot write boundary condition " + name;
    if (cg_boco_write(fn, B, Z, name.c_str(), CGNS_ENUMV(FamilySpecified),
                      range ? CGNS_ENUMV(PointRange) : CGNS_ENUMV(PointList),
                      range ? 2 : static_cast<cgsize_t>(e.size()), range ? lohi : e.data(),
                      &BC) != CG_OK ||
        cg_boco_gridlocation_write(
            fn, B, Z, BC, top == 3 ? CGNS_ENUMV(FaceCenter) : CGNS_ENUMV(EdgeCenter)) != CG_OK ||
        cg_family_write(fn, B, name.c_str(), &F) != CG_OK ||
        cg_goto(fn, B, "Zone_t", Z, "ZoneBC_t", 1, "BC_t", BC, "end") != CG_OK ||
        cg_famname_write(name.c_str()) != CG_OK)
      bc_fail(what);
  }
}

namespace {

// The mesh cell of element number n, -1 when no section holds it.
int cell_of(const std::vector<CgSectionCells>& sections, cgsize_t n) {
  for (const CgSectionCells& s : sections)
    if (n >= s.start && n - s.start < s.count) return s.first + static_cast<int>(n - s.start);
  return -1;
}

// Names (or re-regions) the cells of one BC (cgns_bc.h).
void name_cells(const std::string& name, int dim, std::vector<int>* cells, Mesh* mesh) {
  std::sort(cells->begin(), cells->end());
  cells->erase(std::unique(cells->begin(), cells->end()), cells->end());
  if (cells->empty()) return;
  int r = 0;
  char rest = 0;
  if (std::sscanf(name.c_str(), "Region_%d%c", &r, &rest) == 1) return;
  const int region = mesh->cell_region[cells->front()];
  bool one = true;
  for (int c : *cells) one = one && mesh->cell_region[c] == region;
  std::size_t in_region = 0;
  int max_region = 0;
  for (int c = 0; c < mesh->num_cells(); ++c) {
    in_region += cell_dim(mesh->cell_types[c]) == dim && mesh->cell_region[c] == region;
    max_region = std::max(max_region, mesh->cell_region[c]);
  }
  if (one && in_region == cells->size()) {
    mesh->set_physical_name(dim, region, name);
    return;
  }
  for (int c : *cells) mesh->cell_region[c] = max_region + 1;
  mesh->set_physical_name(dim, max_region + 1, name);
}

}  // namespace

void read_cgns_bcs(const std::string& path, int fn, int Z, int cell_dim_, std::uint64_t file_size,
                   const std::vector<CgSectionCells>& sections, Mesh* mesh) {
  int nbc = 0;
  if (cg_nbocos(fn, 1, Z, &nbc) != CG_OK) bc_fail(path + ": cannot count the boundary conditions");
  cgsize_t total = 0;
  for (const CgSectionCells& s : sections) total += s.count;
  for (int BC = 1; BC <= nbc; ++BC) {
    char name[64] = {0};
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) pt;
    CGNS_ENUMT(DataType_t) ndt;
    cgsize_t np = 0, nlist = 0;
    int nidx[3] = {0, 0, 0}, nds = 0;
    const std::string at =
        path + ": zone " + std::to_string(Z) + ", boundary condition " + std::to_string(BC);
    if (cg_boco_info(fn, 1, Z, BC, name, &type, &pt, &np, nidx, &nlist, &ndt, &nds) != CG_OK)
      bc_fail(at + ": cannot read it");
    const std::string where = at + " '" + printable(name) + "'";
    CGNS_ENUMT(GridLocation_t) loc = CGNS_ENUMV(Vertex);
    if (cg_boco_gridlocation_read(fn, 1, Z, BC, &loc) != CG_OK)
      bc_fail(where + ": cannot read its GridLocation");
    const bool elem_set = pt == CGNS_ENUMV(ElementRange) || pt == CGNS_ENUMV(ElementList);
    if (!elem_set && loc != CGNS_ENUMV(FaceCenter) && loc != CGNS_ENUMV(EdgeCenter)) continue;
    const bool range = pt == CGNS_ENUMV(PointRange) || pt == CGNS_ENUMV(ElementRange);
    if (!range && pt != CGNS_ENUMV(PointList) && pt != CGNS_ENUMV(ElementList))
      throw Error(where + ": unsupported point set type " + std::to_string(static_cast<int>(pt)));
    if (np < 0 || (range && np != 2) || static_cast<std::uint64_t>(np) * 4 > file_size)
      throw Error(where + ": bad point count " + std::to_string(np));
    std::vector<cgsize_t> pts(static_cast<std::size_t>(np));
    if (np > 0 && cg_boco_read(fn, 1, Z, BC, pts.data(), nullptr) != CG_OK)
      bc_fail(where + ": cannot read its points");
    if (range) {
      if (pts[1] < pts[0] ||
          static_cast<double>(pts[1]) - static_cast<double>(pts[0]) >= static_cast<double>(total))
        throw Error(where + ": bad element range " + std::to_string(pts[0]) + ".." +
                    std::to_string(pts[1]));
      const cgsize_t lo = pts[0], hi = pts[1];
      pts.clear();
      for (cgsize_t n = lo; n <= hi; ++n) pts.push_back(n);
    }
    std::vector<int> cells;
    for (cgsize_t n : pts) {
      const int c = cell_of(sections, n);
      if (c < 0)
        throw Error(where + ": element " + std::to_string(n) + " is in no element section");
      if (cell_dim(mesh->cell_types[c]) != cell_dim_ - 1)
        throw Error(where + ": element " + std::to_string(n) + " is a " +
                    cell_name(mesh->cell_types[c]) + ", not a boundary cell");
      cells.push_back(c);
    }
    name_cells(name, cell_dim_ - 1, &cells, mesh);
  }
}

}  // namespace io
}  // namespace tmop

#endif  // TMOP_WITH_CGNS
