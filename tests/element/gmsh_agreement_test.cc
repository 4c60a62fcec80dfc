// Checks the cell table (cell_type.cc) and the reference nodes (shape.cc) against gmsh itself:
// tests/element/gmsh_dump.py asks the gmsh Python module for its reference elements and for the
// nodes of straight-sided second-order meshes; this test reads its output. Skipped when
// /usr/bin/python3 has no gmsh module.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tmop/element/shape.h"

namespace tmop {
namespace {

struct GmshRecord {
  std::string kind;  // "ref", "elem" or "basis"
  int gmsh_type;
  int num_nodes;
  std::vector<double> xyz;  // num_nodes x 3
};

std::vector<GmshRecord> RunGmshDump() {
  const std::string cmd = std::string("/usr/bin/python3 ") + TMOP_SOURCE_DIR +
                          "/tests/element/gmsh_dump.py 2>/dev/null";
  std::vector<GmshRecord> out;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return out;
  std::string text;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof(buf), pipe)) text.append(buf, n);
  if (pclose(pipe) != 0) return {};
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream in(line);
    GmshRecord r;
    in >> r.kind >> r.gmsh_type >> r.num_nodes;
    // "basis": the point, then the value of each node's function there.
    r.xyz.resize(r.kind == "basis" ? 3 + r.num_nodes : 3 * r.num_nodes);
    for (double& x : r.xyz) in >> x;
    if (in) out.push_back(r);
  }
  return out;
}

const std::vector<GmshRecord>& Records() {
  static const std::vector<GmshRecord> records = RunGmshDump();
  return records;
}

TEST(GmshAgreement, ReferenceNodesEqualGmsh) {
  if (Records().empty()) GTEST_SKIP() << "gmsh Python module not available";
  int types_seen = 0;
  for (const GmshRecord& r : Records()) {
    if (r.kind != "ref") continue;
    CellType t;
    ASSERT_TRUE(cell_type_from_gmsh(r.gmsh_type, &t)) << r.gmsh_type;
    ASSERT_EQ(r.num_nodes, cell_num_nodes(t)) << cell_name(t);
    for (int i = 0; i < r.num_nodes; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_EQ(reference_node(t, i)[j], r.xyz[3 * i + j]) << cell_name(t) << " node " << i;
    ++types_seen;
  }
  EXPECT_EQ(types_seen, kNumCellTypes);
}

// In gmsh's straight-sided meshes every mid-edge node is the average of the corners of the table
// edge with the same index, every face node (hex27, wedge18) the average of the table facet's
// corners, and
// det J is positive at the centroid (gmsh's orientation is tmop's).
TEST(GmshAgreement, MeshNodesFollowTheTable) {
  if (Records().empty()) GTEST_SKIP() << "gmsh Python module not available";
  std::map<std::string, int> checked;
  for (const GmshRecord& r : Records()) {
    if (r.kind != "elem") continue;
    CellType t;
    ASSERT_TRUE(cell_type_from_gmsh(r.gmsh_type, &t));
    const CellInfo& info = cell_info(t);
    const double* x = r.xyz.data();
    auto expect_average = [&](int node, const int* corners, int count, const char* what) {
      for (int j = 0; j < 3; ++j) {
        double c = 0;
        for (int k = 0; k < count; ++k) c += x[3 * corners[k] + j] / count;
        EXPECT_NEAR(x[3 * node + j], c, 1e-12) << info.name << " " << what << " node " << node;
      }
    };
    if (info.order == 2) {
      for (int e = 0; e < info.num_edges; ++e)
        expect_average(info.num_corners + e, info.edges[e], 2, "mid-edge");
    }
    if (t == CellType::kQuad9) {
      const int corners[4] = {0, 1, 2, 3};
      expect_average(8, corners, 4, "centre");
    }
    for (int f = 0; f < info.num_facets; ++f) {
      if (facet_node(info, f) >= 0)
        expect_average(facet_node(info, f), info.facets[f].corners, info.facets[f].num_corners,
                       "face");
    }
    if (t == CellType::kHex27) {
      const int corners[8] = {0, 1, 2, 3, 4, 5, 6, 7};
      expect_average(26, corners, 8, "centre");
    }
    if (info.dim == 3) {
      const CellType lin = info.linear;
      double centroid[3] = {0.25, 0.25, 0.25};  // tet
      if (lin == CellType::kHex8) centroid[0] = centroid[1] = centroid[2] = 0;
      if (lin == CellType::kWedge6) centroid[0] = centroid[1] = 1.0 / 3, centroid[2] = 0;
      if (lin == CellType::kPyramid5) centroid[0] = centroid[1] = 0;
      double A[9];
      cell_jacobian(t, x, 3, centroid, A);
      const double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                         A[2] * (A[3] * A[7] - A[4] * A[6]);
      EXPECT_GT(det, 0) << info.name;
    }
    ++checked[info.name];
  }
  for (const char* name : {"tri6", "quad9", "tet10", "hex27", "wedge6", "tet4", "hex8", "pyramid5",
                           "quad8", "hex20", "wedge15", "wedge18", "pyramid13", "pyramid14"})
    EXPECT_GT(checked[name], 0) << "gmsh produced no " << name;
}

// The pyramids' bases are rational and easy to get subtly wrong: their values must be gmsh's own
// (gmsh.model.mesh.getBasisFunctions) at interior points.
TEST(GmshAgreement, PyramidBasesEqualGmsh) {
  if (Records().empty()) GTEST_SKIP() << "gmsh Python module not available";
  std::map<std::string, int> checked;
  for (const GmshRecord& r : Records()) {
    if (r.kind != "basis") continue;
    CellType t;
    ASSERT_TRUE(cell_type_from_gmsh(r.gmsh_type, &t));
    ASSERT_EQ(r.num_nodes, cell_num_nodes(t));
    double N[kMaxCellNodes];
    shape_values(t, r.xyz.data(), N);
    for (int i = 0; i < r.num_nodes; ++i)
      EXPECT_NEAR(N[i], r.xyz[3 + i], 1e-12) << cell_name(t) << " node " << i;
    ++checked[cell_name(t)];
  }
  for (const char* name : {"pyramid5", "pyramid13", "pyramid14"})
    EXPECT_GT(checked[name], 0) << name;
}

}  // namespace
}  // namespace tmop
