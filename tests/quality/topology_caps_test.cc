#include "tmop/quality/topology_caps.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace tmop
