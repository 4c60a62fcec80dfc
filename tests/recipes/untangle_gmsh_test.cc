// Untangling meshes made by gmsh (tri, tet, hex) whose interior vertices were moved randomly by
// a multiple of their shortest incident edge with no validity check: a few percent and 30-50 %
// of the elements inverted. Afterwards nothing is inverted, counted both by the sign of det J and
// by the orientation-free fold check.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

#include "tests/temp_dir.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/fold_check.h"
#include "tmop/mesh/topology.h"
#include "tmop/recipes/untangle.h"

namespace tmop {
namespace {

bool have_gmsh() { return std::system("gmsh --version > /dev/null 2>&1") == 0; }

// geo: gmsh geometry text; dim: 2 or 3.
Mesh gmsh_mesh(const std::string& name, const std::string& geo, int dim) {
  const std::string dir = testing_tmp::dir() + "untangle_gmsh_" + name;
  std::system(("mkdir -p " + dir).c_str());
  std::ofstream(dir + "/m.geo") << geo;
  const std::string cmd = "gmsh -" + std::to_string(dim) + " " + dir + "/m.geo -format msh41 -o " +
                          dir + "/m.msh > /dev/null 2>&1";
  Mesh m;
  if (std::system(cmd.c_str()) == 0) read_mesh(dir + "/m.msh", &m);
  std::system(("rm -rf " + dir).c_str());
  m.remove_lower_dimensional_cells();
  return m;
}

void tangle(Mesh* m, double amount, unsigned seed) {
  const std::vector<char> boundary = boundary_vertex_mask(*m);
  std::vector<double> shortest(m->num_vertices(), 1e300);
  for (const auto& e : mesh_edges(*m)) {
    double l2 = 0;
    for (int a = 0; a < m->space_dim; ++a)
      l2 += std::pow(m->vertex(e[0])[a] - m->vertex(e[1])[a], 2);
    shortest[e[0]] = std::min(shortest[e[0]], std::sqrt(l2));
    shortest[e[1]] = std::min(shortest[e[1]], std::sqrt(l2));
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, 1);
  for (int v = 0; v < m->num_vertices(); ++v) {
    if (boundary[v]) continue;
    double d[3] = {n(rng), n(rng), n(rng)}, len = 0;
    for (int a = 0; a < m->space_dim; ++a) len += d[a] * d[a];
    len = std::sqrt(len);
    for (int a = 0; a < m->space_dim; ++a) m->vertex(v)[a] += amount * shortest[v] * d[a] / len;
  }
}

struct Case {
  const char* name;
  int dim;
  const char* geo;
  double amount;
  double min_fraction;  // the tangle must invert at least this fraction of the elements
};

const char* kSquare = "Rectangle(1) = {0, 0, 0, 1, 1};\nMesh.CharacteristicLengthMax = 0.04;\n";
const char* kBox = "Box(1) = {0, 0, 0, 1, 1, 1};\nMesh.CharacteristicLengthMax = 0.1;\n";
const char* kHexBox =
    "Box(1) = {0, 0, 0, 1, 1, 1};\nTransfinite Curve{:} = 13;\nTransfinite Surface{:};\n"
    "Recombine Surface{:};\nTransfinite Volume{1};\nRecombine Volume{1};\n";

// Prisms: triangles extruded in layers. Mixed: quads and triangles extruded into hexes and
// prisms, two volumes (their interface is a region interface, kept fixed).
const char* kPrisms =
    "Rectangle(1) = {0, 0, 0, 1, 1};\nMesh.CharacteristicLengthMax = 0.09;\n"
    "Extrude {0, 0, 0.6} { Surface{1}; Layers{7}; Recombine; }\n";
const char* kMixed =
    "Rectangle(1) = {0, 0, 0, 0.5, 1};\nRectangle(2) = {0.5, 0, 0, 0.5, 1};\n"
    "BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }\n"
    "Mesh.CharacteristicLengthMax = 0.09;\nRecombine Surface{1};\n"
    "Extrude {0, 0, 0.6} { Surface{1, 2}; Layers{7}; Recombine; }\n";

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class UntangleGmsh : public ::testing::TestWithParam<Case> {};

TEST_P(UntangleGmsh, NothingInvertedAfter) {
  if (!have_gmsh()) GTEST_SKIP() << "gmsh not installed";
  const Case c = GetParam();
  Mesh mesh = gmsh_mesh(c.name, std::string("SetFactory(\"OpenCASCADE\");\n") + c.geo, c.dim);
  ASSERT_GT(mesh.num_elements(), 500);
  tangle(&mesh, c.amount, 17);
  const int before = measure_mesh(mesh, SampleRule::kCorners).inverted;
  const double fraction = double(before) / mesh.num_elements();
  EXPECT_GE(fraction, c.min_fraction);
  UntangleOptions opt;
  RecipeResult result;
  Status s = untangle(&mesh, opt, &result);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(measure_mesh(mesh, SampleRule::kCorners).inverted, 0);
  EXPECT_EQ(measure_mesh(mesh, SampleRule::kDefault).inverted, 0);
  EXPECT_TRUE(folded_facets(mesh).empty());
  std::printf("%s: %d elements, %.1f %% inverted -> 0 in %.2f s; worst quality %.3f\n", c.name,
              mesh.num_elements(), 100 * fraction, result.seconds, result.after.min_quality);
}

INSTANTIATE_TEST_SUITE_P(Meshes, UntangleGmsh,
                         ::testing::Values(Case{"tri_few", 2, kSquare, 0.55, 0.05},
                                           Case{"tri_many", 2, kSquare, 1.5, 0.30},
                                           Case{"tet_few", 3, kBox, 0.75, 0.05},
                                           Case{"tet_many", 3, kBox, 1.5, 0.30},
                                           Case{"hex_few", 3, kHexBox, 0.42, 0.05},
                                           Case{"hex_many", 3, kHexBox, 0.55, 0.30},
                                           Case{"prism_few", 3, kPrisms, 0.6, 0.05},
                                           Case{"prism_many", 3, kPrisms, 0.9, 0.30},
                                           Case{"mixed_few", 3, kMixed, 0.45, 0.05},
                                           Case{"mixed_many", 3, kMixed, 0.9, 0.30}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace tmop
