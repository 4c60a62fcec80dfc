#include "io_test_util.h"

#include <gtest/gtest.h>
#include <stdio.h>
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "tmop/element/shape.h"
#include "tmop/io/mesh_io.h"
#include "tmop/io/node_order.h"

namespace tmop {
namespace test {

std::vector<CellType> all_types() {
  std::vector<CellType> t;
  for (int i = 0; i < kNumCellTypes; ++i) t.push_back(static_cast<CellType>(i));
  return t;
}

std::vector<CellType> vtk_types() {
  std::vector<CellType> t;
  for (CellType c : all_types())
    if (io::vtk_cell_type(c) >= 0) t.push_back(c);
  return t;
}

Mesh make_mesh(const std::vector<CellType>& types, int space_dim) {
  Mesh m;
  m.space_dim = space_dim;
  const int nv = 60;
  for (int v = 0; v < nv; ++v) {
    // Irrational-looking values exercise the full 17 significant digits.
    double x[3] = {std::sin(1.0 + v) * 1e3 / 7.0, std::cos(0.5 * v) / 3.0,
                   space_dim == 3 ? std::sqrt(2.0 + v) * 1e-5 : 0.0};
    if (v == 3) x[0] = -0.0;
    m.add_vertex(x);
  }
  int next = 0;
  for (std::size_t i = 0; i < types.size(); ++i) {
    const CellType t = types[i];
    std::int32_t nodes[kMaxCellNodes];
    for (int k = 0; k < cell_num_nodes(t); ++k) nodes[k] = (next + 7 * k) % nv;
    next += 5;
    // region and entity derived from the type: one region per (dim, entity).
    const int region = 10 + static_cast<int>(t);
    const int entity = 100 + static_cast<int>(t);
    m.add_cell(t, nodes, region, entity);
  }
  return m;
}

Mesh straight_cells_mesh(const std::vector<CellType>& types) {
  Mesh m;
  m.space_dim = 3;
  const double A[3][3] = {{2.0, 0.25, 0.5}, {0.125, 1.5, 0.375}, {0.25, 0.5, 3.0}};
  for (std::size_t c = 0; c < types.size(); ++c) {
    const CellType t = types[c];
    std::int32_t nodes[kMaxCellNodes];
    for (int i = 0; i < cell_num_nodes(t); ++i) {
      const double* r = reference_node(t, i);
      double x[3];
      for (int j = 0; j < 3; ++j)
        x[j] = 10.0 * static_cast<double>(c) + A[j][0] * r[0] + A[j][1] * r[1] + A[j][2] * r[2];
      nodes[i] = m.add_vertex(x);
    }
    m.add_cell(t, nodes, 1 + static_cast<int>(c), 0);  // one region per cell: one block each
  }
  return m;
}

std::string check_patran_node_order(const std::string& name, const std::string& kind) {
  const std::vector<CellType> types = {
      CellType::kTri6,  CellType::kQuad8,   CellType::kQuad9,     CellType::kTet10,
      CellType::kHex20, CellType::kWedge15, CellType::kPyramid13, CellType::kPyramid14,
      CellType::kHex27, CellType::kWedge18};
  const Mesh mesh = straight_cells_mesh(types);
  std::string failure = round_trip(mesh, {"r_" + name});
  if (!failure.empty()) return failure;
  const std::string path = temp_dir() + "/" + name;
  const Status s = write_mesh(path, mesh);
  if (!s.ok()) return s.message();
  std::string out;
  const std::string cmd = std::string("/usr/bin/python3 ") + TMOP_SOURCE_DIR +
                          "/tests/io/patran_order_check.py " + kind + " '" + path + "'";
  if (run(cmd, &out) != 0) return out;
  for (CellType t : types)
    if (out.find(std::string("checked ") + cell_name(t) + " 1") == std::string::npos)
      return std::string(cell_name(t)) + " not checked: " + out;
  return "";
}

std::string diff_meshes(const Mesh& a, const Mesh& b, bool compare_entity, double tol) {
  std::ostringstream s;
  if (a.space_dim != b.space_dim) {
    s << "space_dim " << a.space_dim << " vs " << b.space_dim;
    return s.str();
  }
  if (a.coords.size() != b.coords.size()) {
    s << "coords size " << a.coords.size() << " vs " << b.coords.size();
    return s.str();
  }
  for (std::size_t i = 0; i < a.coords.size(); ++i) {
    const bool eq = tol == 0.0 ? std::memcmp(&a.coords[i], &b.coords[i], sizeof(double)) == 0 ||
                                     a.coords[i] == b.coords[i]
                               : std::fabs(a.coords[i] - b.coords[i]) <= tol;
    if (!eq) {
      s.precision(17);
      s << "coord " << i << ": " << a.coords[i] << " vs " << b.coords[i];
      return s.str();
    }
  }
  if (a.num_cells() != b.num_cells()) {
    s << "cells " << a.num_cells() << " vs " << b.num_cells();
    return s.str();
  }
  for (int c = 0; c < a.num_cells(); ++c) {
    if (a.cell_types[c] != b.cell_types[c]) {
      s << "cell " << c << " type " << cell_name(a.cell_types[c]) << " vs "
        << cell_name(b.cell_types[c]);
      return s.str();
    }
    for (int k = 0; k < a.cell_size(c); ++k)
      if (a.cell(c)[k] != b.cell(c)[k]) {
        s << "cell " << c << " node " << k << ": " << a.cell(c)[k] << " vs " << b.cell(c)[k];
        return s.str();
      }
    if (a.cell_region[c] != b.cell_region[c]) {
      s << "cell " << c << " region " << a.cell_region[c] << " vs " << b.cell_region[c];
      return s.str();
    }
    if (compare_entity && a.cell_entity[c] != b.cell_entity[c]) {
      s << "cell " << c << " entity " << a.cell_entity[c] << " vs " << b.cell_entity[c];
      return s.str();
    }
  }
  return "";
}

std::string temp_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string dir = std::string(TMOP_BINARY_DIR) + "/io_test_tmp";
  mkdir(dir.c_str(), 0755);
  dir += "/" + std::string(info->test_suite_name()) + "." + info->name();
  std::string out;
  run("rm -rf '" + dir + "'", &out);
  mkdir(dir.c_str(), 0755);
  return dir;
}

int run(const std::string& command, std::string* out) {
  out->clear();
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof(buf), p)) > 0) out->append(buf, n);
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool have_program(const std::string& name) {
  std::string out;
  return run("command -v " + name, &out) == 0;
}

bool have_python_module(const std::string& module) {
  std::string out;
  return run("/usr/bin/python3 -c 'import " + module + "'", &out) == 0;
}

std::string python_helper() { return std::string(TMOP_SOURCE_DIR) + "/tests/io/mesh_dump.py"; }

namespace {

std::string cell_line(CellType t, int region, const std::int32_t* nodes) {
  std::string s = std::string(cell_name(t)) + " " + std::to_string(region);
  for (int k = 0; k < cell_num_nodes(t); ++k) s += " " + std::to_string(nodes[k]);
  return s;
}

}  // namespace

bool parse_dump(const std::string& text, Dump* dump, std::string* error) {
  std::istringstream in(text);
  std::string word, order;
  std::size_t np = 0, nc = 0;
  // Skip anything before "order" (e.g. library warnings).
  while (in >> word && word != "order") {
  }
  if (!(in >> order) || (order != "gmsh" && order != "meshio" && order != "vtk")) {
    *error = "no 'order' line in dump: " + text.substr(0, 400);
    return false;
  }
  if (!(in >> word >> np) || word != "points") {
    *error = "bad points header";
    return false;
  }
  dump->xyz.resize(3 * np);
  for (std::size_t i = 0; i < 3 * np; ++i) {
    if (!(in >> word)) {
      *error = "truncated points";
      return false;
    }
    dump->xyz[i] = std::strtod(word.c_str(), nullptr);
  }
  if (!(in >> word >> nc) || word != "cells") {
    *error = "bad cells header";
    return false;
  }
  dump->cells.clear();
  for (std::size_t c = 0; c < nc; ++c) {
    std::string name;
    int region;
    if (!(in >> name >> region)) {
      *error = "truncated cells";
      return false;
    }
    CellType t;
    if (!cell_type_from_name(name, &t)) {
      *error = "unknown type in dump: " + name;
      return false;
    }
    std::int32_t file_nodes[kMaxCellNodes], nodes[kMaxCellNodes];
    for (int k = 0; k < cell_num_nodes(t); ++k) in >> file_nodes[k];
    // meshio's own order is VTK's, except wedges, which meshio keeps in Gmsh order; "vtk" is
    // VTK's for every type (SU2 files).
    const int* p = io::gmsh_index_of_vtk_node(t);
    for (int k = 0; k < cell_num_nodes(t); ++k) {
      if (order == "vtk" || (order == "meshio" && t != CellType::kWedge6))
        nodes[p[k]] = file_nodes[k];
      else
        nodes[k] = file_nodes[k];
    }
    dump->cells.push_back(cell_line(t, region, nodes));
  }
  return true;
}

bool parse_dump_file(const std::string& path, Dump* dump, std::string* error) {
  std::ifstream f(path);
  if (!f) {
    *error = "cannot open " + path;
    return false;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_dump(ss.str(), dump, error);
}

Dump dump_of(const Mesh& mesh) {
  Dump d;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k) d.xyz.push_back(k < mesh.space_dim ? mesh.vertex(v)[k] : 0.0);
  for (int c = 0; c < mesh.num_cells(); ++c)
    d.cells.push_back(cell_line(mesh.cell_types[c], mesh.cell_region[c], mesh.cell(c)));
  return d;
}

void strip_regions(Dump* d) {
  for (std::string& line : d->cells) {
    const std::size_t s1 = line.find(' '), s2 = line.find(' ', s1 + 1);
    line = line.substr(0, s1) + " 0" + line.substr(s2);
  }
}

std::string diff_dumps(const Dump& a, const Dump& b, double rel_tol) {
  std::ostringstream s;
  s.precision(17);
  if (a.xyz.size() != b.xyz.size()) {
    s << "points " << a.xyz.size() / 3 << " vs " << b.xyz.size() / 3;
    return s.str();
  }
  for (std::size_t i = 0; i < a.xyz.size(); ++i)
    if (rel_tol == 0.0
            ? a.xyz[i] != b.xyz[i]
            : std::fabs(a.xyz[i] - b.xyz[i]) > rel_tol * std::max(1.0, std::fabs(a.xyz[i]))) {
      s << "coordinate " << i << ": " << a.xyz[i] << " vs " << b.xyz[i];
      return s.str();
    }
  std::vector<std::string> ca = a.cells, cb = b.cells;
  std::sort(ca.begin(), ca.end());
  std::sort(cb.begin(), cb.end());
  if (ca.size() != cb.size()) {
    s << "cells " << ca.size() << " vs " << cb.size();
    return s.str();
  }
  for (std::size_t i = 0; i < ca.size(); ++i)
    if (ca[i] != cb[i]) return "cell '" + ca[i] + "' vs '" + cb[i] + "'";
  return "";
}

// mesh with its cells reordered as a CGNS file holds them: the elements (dimension dim()) first,
// each group in its order.
Mesh elements_first(const Mesh& mesh) {
  Mesh out = mesh;
  out.cell_types.clear();
  out.cell_offsets.assign(1, 0);
  out.cell_nodes.clear();
  out.cell_region.clear();
  out.cell_entity.clear();
  const int top = mesh.dim();
  for (int pass = 0; pass < 2; ++pass)
    for (int c = 0; c < mesh.num_cells(); ++c)
      if ((cell_dim(mesh.cell_types[c]) == top) == (pass == 0))
        out.add_cell(mesh.cell_types[c], mesh.cell(c), mesh.cell_region[c],
                     mesh.cell_entity.empty() ? 0 : mesh.cell_entity[c]);
  return out;
}

std::string round_trip(const Mesh& mesh, const std::vector<std::string>& names) {
  const std::string dir = temp_dir();
  const Mesh cgns_order = elements_first(mesh);
  for (const std::string& name : names) {
    const std::string path = dir + "/" + name;
    const Status w = write_mesh(path, mesh);
    if (!w.ok()) return name + ": " + w.message();
    Mesh back;
    const Status r = read_mesh(path, &back);
    if (!r.ok()) return name + ": " + r.message();
    std::string ext = name.substr(name.rfind('.') + 1);
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const bool cgns = ext == "cgns";
    const std::string d = diff_meshes(cgns ? cgns_order : mesh, back, false);
    if (!d.empty()) return name + ": " + d;
  }
  return "";
}

}  // namespace test
}  // namespace tmop
