// tests/io/io_test_util.h
// Shared helpers for the io tests: sample meshes covering every cell type, exact mesh
// comparison, a per-test temporary directory, running external programs, and parsing the
// canonical dump printed by tests/io/mesh_dump.py (gmsh / meshio as independent readers).
#ifndef TMOP_TESTS_IO_IO_TEST_UTIL_H_
#define TMOP_TESTS_IO_IO_TEST_UTIL_H_

#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace test {

// A 3D mesh holding one or more cells of each listed type, with distinct non-round coordinates,
// regions and entities (each (dim, entity) pair has a single region, as Gmsh requires).
Mesh make_mesh(const std::vector<CellType>& types, int space_dim = 3);
// One straight-sided cell of each listed type: its reference nodes under a fixed affine map
// (a skew, non-orthogonal one), every node its own vertex, so each mid-edge node is exactly the
// midpoint of its edge's corners. Cell c has region c + 1, entity 0.
Mesh straight_cells_mesh(const std::vector<CellType>& types);
// Writes straight_cells_mesh of every quadratic type Exodus and CGNS hold to dir/NAME and runs
// tests/io/patran_order_check.py KIND on it ("exodus" or "cgns"): "" when every type was checked
// against the documented node order, else the failure. Also round-trips the mesh through tmop.
std::string check_patran_node_order(const std::string& name, const std::string& kind);
// Every type tmop knows, 3D.
std::vector<CellType> all_types();
// Every type that has a VTK cell type (all but pyramid14), for .vtk / .vtu.
std::vector<CellType> vtk_types();

// Empty string when equal, otherwise the first difference. Compares space_dim, coordinates
// bit-exactly (or within tol), types, nodes, regions and (if compare_entity) entities.
std::string diff_meshes(const Mesh& a, const Mesh& b, bool compare_entity = true, double tol = 0.0);

// A fresh empty directory under the build tree, named after the current test.
std::string temp_dir();

// Writes `mesh` to temp_dir()/NAME for each name and reads it back: "" when every round trip
// keeps the mesh (entities not compared: formats without them), else the first failure. .cgns
// files hold the elements' sections first: their cells are compared in that order.
std::string round_trip(const Mesh& mesh, const std::vector<std::string>& names);

// Runs a shell command; returns its exit code, stdout in *out.
int run(const std::string& command, std::string* out);
bool have_program(const std::string& name);
// True when /usr/bin/python3 can import the module.
bool have_python_module(const std::string& module);

// The canonical dump (see mesh_dump.py): points, then cells as "type region nodes...". The
// dump's node order (gmsh, or meshio's) is converted to Gmsh order with tmop's tables, so
// comparing a meshio dump with tmop's reading checks those tables against meshio's.
struct Dump {
  std::vector<double> xyz;         // 3 per point
  std::vector<std::string> cells;  // "type region n0 n1 ..." in Gmsh order, 0-based
};
bool parse_dump(const std::string& text, Dump* dump, std::string* error);
bool parse_dump_file(const std::string& path, Dump* dump, std::string* error);
Dump dump_of(const Mesh& mesh);  // the same canonical form from a tmop Mesh
// Empty when equal; cells compared as sorted lists (readers may regroup cells by type).
// Coordinates equal within rel_tol * max(1, |x|) (0: bit-exact).
std::string diff_dumps(const Dump& a, const Dump& b, double rel_tol = 0.0);
// Sets every cell's region to 0 (for files that do not carry regions for all cells).
void strip_regions(Dump* d);

std::string python_helper();  // path of mesh_dump.py

}  // namespace test
}  // namespace tmop

#endif  // TMOP_TESTS_IO_IO_TEST_UTIL_H_
