// Meshes and measurements shared by the recipe tests: an unstructured all-quad mesh with a
// strong size gradation made by the gmsh CLI at test time, and edge-length statistics over the
// edges that a recipe can change (those touching a free vertex).
#ifndef TMOP_TESTS_RECIPES_RECIPE_TEST_MESHES_H_
#define TMOP_TESTS_RECIPES_RECIPE_TEST_MESHES_H_

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"
#include "tmop/mesh/topology.h"
#include "tmop/optimize/stage.h"

namespace tmop {
namespace testing_recipes {

inline int exit_code(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline bool have_gmsh() { return exit_code("gmsh --version > /dev/null 2>&1") == 0; }

// Where gmsh-doc (a Debian package tools/install_deps.sh installs) puts Gmsh's tutorials and demos.
constexpr const char* kGmshDoc = "/usr/share/doc/gmsh-doc/doc/gmsh/";

// Meshes FOLDER/NAME.geo of gmsh-doc (e.g. "tutorial", "t16") with `gmsh ARGS NAME.geo`, run in a
// fresh directory holding a copy of every .geo of FOLDER (gmsh-doc gzips some, which the
// tutorials include), and reads the result without its lower-dimensional cells. 1: gmsh or the
// file is missing (skip), 2: gmsh or the reader failed, 0: *mesh holds it.
inline int gmsh_doc_mesh(const std::string& folder, const std::string& name,
                         const std::string& args, Mesh* mesh) {
  const std::string src = std::string(kGmshDoc) + folder + "/";
  if (!have_gmsh() ||
      exit_code("test -f " + src + name + ".geo -o -f " + src + name + ".geo.gz") != 0)
    return 1;
  char dir[] = "/tmp/tmop_gmsh_doc_XXXXXX";
  if (!mkdtemp(dir)) return 2;
  const std::string d = dir;
  const int rc =
      exit_code("cd " + d + " && for f in " + src + "*.geo " + src +
                "*.geo.gz; do case $f in *.gz) zcat $f > $(basename $f .gz);; *) cp $f "
                ".;; esac; done 2>/dev/null; gmsh " +
                args + " -nt 1 -v 0 -format msh41 " + name + ".geo -o out.msh > /dev/null 2>&1");
  const bool ok = rc == 0 && read_mesh(d + "/out.msh", mesh).ok();
  exit_code("rm -rf " + d);
  if (!ok) return 2;
  mesh->remove_lower_dimensional_cells();
  return 0;
}

// The unit square meshed by gmsh with a point attractor at its centre: target size 0.014 within
// 0.02 of the centre growing to 0.12 at distance 0.35, Frontal-Delaunay triangles (Algorithm 6);
// with quads = true recombined by the blossom full-quad algorithm, which also splits every
// element once, so all elements are quads. Edge lengths span ~13x.
// (Mesh.Algorithm = 8, "Frontal-Delaunay for quads", crashes gmsh 4.8.4 on size fields.)
// Returns false when gmsh failed.
inline bool graded_mesh(const std::string& dir, bool quads, Mesh* mesh) {
  // Per process: ctest -j runs the tests that use this mesh at the same time (laplace_test and
  // size_adapt_test read each other's half-written file once).
  const std::string name =
      std::string(quads ? "graded_quads_" : "graded_tris_") + std::to_string(::getpid());
  const std::string geo = dir + name + ".geo", msh = dir + name + ".msh";
  std::ofstream(geo) << "Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0};\n"
                        "Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};\n"
                        "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                        "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                        "Point(10) = {0.5, 0.5, 0};\n"
                        "Field[1] = Distance; Field[1].PointsList = {10};\n"
                        "Field[2] = Threshold; Field[2].InField = 1;\n"
                        "Field[2].SizeMin = 0.014; Field[2].SizeMax = 0.12;\n"
                        "Field[2].DistMin = 0.02; Field[2].DistMax = 0.35;\n"
                        "Background Field = 2;\n"
                        "Mesh.MeshSizeExtendFromBoundary = 0;\n"
                        "Mesh.MeshSizeFromPoints = 0;\n"
                        "Mesh.MeshSizeFromCurvature = 0;\n"
                        "Mesh.Algorithm = 6;\n"
                     << (quads ? "Mesh.RecombineAll = 1;\nMesh.RecombinationAlgorithm = 3;\n" : "");
  if (exit_code("gmsh -2 " + geo + " -o " + msh + " -format msh41 > /dev/null 2>&1") != 0)
    return false;
  if (!read_mesh(msh, mesh).ok()) return false;
  mesh->remove_lower_dimensional_cells();
  return true;
}

// The unit square meshed by gmsh with near-equilateral triangles of size h (Frontal-Delaunay).
inline bool uniform_tri_mesh(const std::string& dir, double h, Mesh* mesh) {
  const std::string geo = dir + "uniform_tris.geo", msh = dir + "uniform_tris.msh";
  std::ofstream(geo) << "Point(1) = {0, 0, 0, " << h << "}; Point(2) = {1, 0, 0, " << h << "};\n"
                     << "Point(3) = {1, 1, 0, " << h << "}; Point(4) = {0, 1, 0, " << h << "};\n"
                     << "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                        "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                        "Mesh.Algorithm = 6;\n";
  if (exit_code("gmsh -2 " + geo + " -o " + msh + " -format msh41 > /dev/null 2>&1") != 0)
    return false;
  if (!read_mesh(msh, mesh).ok()) return false;
  mesh->remove_lower_dimensional_cells();
  return true;
}

inline bool graded_quad_mesh(const std::string& dir, Mesh* mesh) {
  return graded_mesh(dir, true, mesh);
}

struct EdgeStats {
  int count = 0;
  double min = 0, max = 0, mean = 0, std = 0;
  double cv() const { return std / mean; }  // coefficient of variation std / mean
};

// Lengths of the element edges with at least one endpoint not fixed.
inline EdgeStats free_edge_stats(const Mesh& mesh, const std::vector<char>& fixed) {
  EdgeStats s;
  std::vector<double> lengths;
  for (const auto& e : mesh_edges(mesh)) {
    if (fixed[e[0]] && fixed[e[1]]) continue;
    double l2 = 0;
    for (int a = 0; a < mesh.space_dim; ++a) {
      const double t = mesh.vertex(e[1])[a] - mesh.vertex(e[0])[a];
      l2 += t * t;
    }
    lengths.push_back(std::sqrt(l2));
  }
  s.count = static_cast<int>(lengths.size());
  if (lengths.empty()) return s;
  s.min = s.max = lengths[0];
  double sum = 0;
  for (double l : lengths) {
    s.min = std::min(s.min, l);
    s.max = std::max(s.max, l);
    sum += l;
  }
  s.mean = sum / s.count;
  double var = 0;
  for (double l : lengths) var += (l - s.mean) * (l - s.mean);
  s.std = std::sqrt(var / s.count);
  return s;
}

// Moves every free vertex by a random vector of up to `amount` x its shortest incident edge in
// each coordinate, retrying (up to 20 times, else leaving it) until nothing is inverted.
inline void perturb_valid(Mesh* mesh, const std::vector<char>& fixed, double amount,
                          std::mt19937* rng) {
  const int nv = mesh->num_vertices();
  std::vector<double> shortest(nv, std::numeric_limits<double>::infinity());
  for (const auto& e : mesh_edges(*mesh)) {
    double l2 = 0;
    for (int a = 0; a < mesh->space_dim; ++a) {
      const double t = mesh->vertex(e[1])[a] - mesh->vertex(e[0])[a];
      l2 += t * t;
    }
    for (int v : e) shortest[v] = std::min(shortest[v], std::sqrt(l2));
  }
  std::uniform_real_distribution<double> u(-amount, amount);
  for (int v = 0; v < nv; ++v) {
    if (fixed[v] || !std::isfinite(shortest[v])) continue;
    double saved[3];
    for (int a = 0; a < mesh->space_dim; ++a) saved[a] = mesh->vertex(v)[a];
    for (int attempt = 0; attempt < 20; ++attempt) {
      for (int a = 0; a < mesh->space_dim; ++a)
        mesh->vertex(v)[a] = saved[a] + u(*rng) * shortest[v];
      if (measure_mesh(*mesh, SampleRule::kDefault).inverted == 0) break;
      for (int a = 0; a < mesh->space_dim; ++a) mesh->vertex(v)[a] = saved[a];
    }
  }
}

}  // namespace testing_recipes
}  // namespace tmop

#endif  // TMOP_TESTS_RECIPES_RECIPE_TEST_MESHES_H_
