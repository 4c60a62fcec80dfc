#include "tmop/quality/topology_caps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "tmop/quality/quality_fields.h"
#include "tmop/quality/quality_json.h"
#include "tmop/quality/quality_summary.h"

namespace tmop {
namespace {

// A lat-long sphere: two poles of valence nlon, every other vertex of valence 6.
Mesh sphere(int nlat, int nlon) {
  Mesh m;
  const double north[3] = {0, 0, 1}, south[3] = {0, 0, -1};
  m.add_vertex(north);
  for (int i = 1; i < nlat; ++i)
    for (int j = 0; j < nlon; ++j) {
      const double th = M_PI * i / nlat, ph = 2 * M_PI * j / nlon;
      const double x[3] = {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
      m.add_vertex(x);
    }
  const int s = m.add_vertex(south);
  auto id = [&](int i, int j) { return 1 + (i - 1) * nlon + (j % nlon); };
  for (int j = 0; j < nlon; ++j) {
    const std::int32_t a[3] = {0, id(1, j), id(1, j + 1)};
    const std::int32_t b[3] = {s, id(nlat - 1, j + 1), id(nlat - 1, j)};
    m.add_cell(CellType::kTri3, a);
    m.add_cell(CellType::kTri3, b);
  }
  for (int i = 1; i < nlat - 1; ++i)
    for (int j = 0; j < nlon; ++j) {
      const std::int32_t a[3] = {id(i, j), id(i + 1, j), id(i + 1, j + 1)};
      const std::int32_t b[3] = {id(i, j), id(i + 1, j + 1), id(i, j + 1)};
      m.add_cell(CellType::kTri3, a);
      m.add_cell(CellType::kTri3, b);
    }
  return m;
}

TEST(TopologyCaps, NamesThePolesOfALatLongSphere) {
  const Mesh m = sphere(8, 64);
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.capped_valence_vertices, 2);
  ASSERT_EQ(r.capped_valence_examples.size(), 2u);
  EXPECT_EQ(r.capped_valence_examples[0], 0);
  EXPECT_EQ(r.capped_valence_examples[1], m.num_vertices() - 1);
  EXPECT_EQ(r.max_valence, 64);
  EXPECT_EQ(r.cells_all_boundary, 0);  // closed surface
  EXPECT_NE(quality_json(r).find("\"capped_valence_vertices\": 2"), std::string::npos);
  EXPECT_NE(quality_summary(r).find("2 vertices of extreme valence (max 64; ids 0 "),
            std::string::npos)
      << quality_summary(r);
}

TEST(TopologyCaps, CountsTetsWithEveryCornerOnTheBoundary) {
  Mesh m;
  const double p[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  m.add_cell(CellType::kTet4, a);
  m.add_cell(CellType::kTet4, b);
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.cells_all_boundary, 2);  // every vertex of a 2-tet mesh is on its boundary
  EXPECT_EQ(r.capped_valence_vertices, 0);
}

// A strip of n x 1 quads split into triangles: every vertex is on the boundary, so every
// element is frozen by a fixed boundary; plus one boundary line that is not an element.
Mesh strip(int n) {
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x[2] = {1.0 * i, 1.0 * j};
      m.add_vertex(x);
    }
  for (int i = 0; i < n; ++i) {
    const std::int32_t a[3] = {i, i + 1, i + n + 2}, b[3] = {i, i + n + 2, i + n + 1};
    m.add_cell(CellType::kTri3, a);
    m.add_cell(CellType::kTri3, b);
  }
  const std::int32_t line[2] = {0, 1};
  m.add_cell(CellType::kLine2, line, 3);
  return m;
}

TEST(TopologyCaps, ListsExampleCellsWithEveryCornerOnTheBoundary) {
  Mesh m;
  const double p[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (auto& x : p) m.add_vertex(x);
  const std::int32_t a[4] = {0, 1, 2, 3}, b[4] = {1, 2, 3, 4};
  m.add_cell(CellType::kTet4, a);
  m.add_cell(CellType::kTet4, b);
  QualityReport r = compute_quality(m);
  EXPECT_EQ(r.cells_all_boundary_examples, (std::vector<std::int64_t>{0, 1}));
  EXPECT_NE(quality_json(r).find("\"cells_all_boundary_examples\": [0, 1]"), std::string::npos)
      << quality_json(r);
  EXPECT_NE(quality_summary(r).find("2 elements with every corner on the boundary (ids 0 1)\n"),
            std::string::npos)
      << quality_summary(r);
  add_quality_fields(r, &m);
  const DataArray* field = nullptr;
  for (const DataArray& d : m.cell_data)
    if (d.name == "all_boundary") field = &d;
  ASSERT_NE(field, nullptr);
  EXPECT_EQ(field->values, (std::vector<double>{1, 1}));

  // More than 20: the first 20 ids, "..." in the summary; the boundary line is not an element.
  Mesh s = strip(15);
  r = compute_quality(s);
  EXPECT_EQ(r.cells_all_boundary, 30);
  ASSERT_EQ(r.cells_all_boundary_examples.size(), 20u);
  EXPECT_EQ(r.cells_all_boundary_examples.back(), 19);
  EXPECT_NE(quality_summary(r).find("30 elements with every corner on the boundary (ids 0 1 2 "),
            std::string::npos);
  EXPECT_NE(quality_summary(r).find(" 19 ...)"), std::string::npos) << quality_summary(r);
  add_quality_fields(r, &s);
  for (const DataArray& d : s.cell_data)
    if (d.name == "all_boundary") {
      ASSERT_EQ(d.values.size(), 31u);
      EXPECT_EQ(d.values[0], 1);
      EXPECT_TRUE(std::isnan(d.values[30]));  // the line
    }
}

TEST(TopologyCaps, InteriorElementsAreNotAllBoundary) {
  // A 3 x 3 grid of quads: every quad has at least one interior corner, so none is frozen.
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const double x[2] = {1.0 * i, 1.0 * j};
      m.add_vertex(x);
    }
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const std::int32_t a = 4 * j + i, q[4] = {a, a + 1, a + 5, a + 4};
      m.add_cell(CellType::kQuad4, q);
    }
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.cells_all_boundary, 0);
  EXPECT_TRUE(r.cells_all_boundary_examples.empty());
  EXPECT_EQ(r.all_boundary, std::vector<double>(9, 0.0));
  EXPECT_NE(quality_json(r).find("\"cells_all_boundary_examples\": []"), std::string::npos);
}

// Mid-edge nodes of quadratic cells have 1 or 2 incident elements by construction: they are not
// vertices of extreme valence (a regular tri6 grid was reported with hundreds).
TEST(TopologyCaps, MidEdgeNodesAreNotCountedAsVertices) {
  const int n = 6;
  Mesh m;
  m.space_dim = 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x[2] = {1.0 * i, 1.0 * j};
      m.add_vertex(x);
    }
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> mids;  // shared by neighbours
  auto mid = [&](std::int32_t a, std::int32_t b) {
    const auto key = std::minmax(a, b);
    auto it = mids.find(key);
    if (it != mids.end()) return it->second;
    const double x[2] = {0.5 * (m.vertex(a)[0] + m.vertex(b)[0]),
                         0.5 * (m.vertex(a)[1] + m.vertex(b)[1])};
    return mids[key] = m.add_vertex(x);
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = (n + 1) * j + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      const std::int32_t t1[6] = {a, b, c, mid(a, b), mid(b, c), mid(c, a)};
      const std::int32_t t2[6] = {a, c, d, mid(a, c), mid(c, d), mid(d, a)};
      m.add_cell(CellType::kTri6, t1);
      m.add_cell(CellType::kTri6, t2);
    }
  const QualityReport r = compute_quality(m);
  EXPECT_EQ(r.capped_valence_vertices, 0);  // interior corners of this grid have valence 6
  EXPECT_EQ(r.max_valence, 6);
}

}  // namespace
}  // namespace tmop
