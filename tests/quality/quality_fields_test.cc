#include "tmop/quality/quality_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/quality/test_meshes.h"
#include "tests/temp_dir.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

const DataArray* find(const Mesh& m, const std::string& name) {
  for (const DataArray& a : m.cell_data)
    if (a.name == name) return &a;
  return nullptr;
}

TEST(QualityFields, AddsOneArrayPerMeasureAndReplacesOldOnes) {
  Mesh m = testing_meshes::tet_block(2, 0.2);
  m.cell_data.push_back(DataArray{"mean_ratio", 1, std::vector<double>(m.num_cells(), -7)});
  const QualityReport r = compute_quality(m);
  add_quality_fields(r, &m);
  EXPECT_EQ(find(m, "min_angle_deg"), nullptr);  // no 2D angles in a tet mesh
  for (const char* name : {"inverted", "certified", "mean_ratio", "scaled_jacobian",
                           "condition_number", "min_det", "min_dihedral_deg", "max_dihedral_deg",
                           "min_edge_length", "max_edge_length", "edge_ratio"}) {
    const DataArray* a = find(m, name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->values.size(), static_cast<std::size_t>(m.num_cells())) << name;
  }
  int count = 0;
  for (const DataArray& a : m.cell_data) count += a.name == "mean_ratio";
  EXPECT_EQ(count, 1);
  EXPECT_EQ(find(m, "mean_ratio")->values, r.mean_ratio.values);
}

TEST(QualityFields, SurviveAVtuRoundTrip) {
  Mesh m = testing_meshes::tet_block(2, 0.2);
  const QualityReport r = compute_quality(m);
  add_quality_fields(r, &m);
  const std::string path = testing_tmp::dir() + "quality_fields.vtu";
  const Status written = write_mesh(path, m);
  ASSERT_TRUE(written.ok()) << written.message();
  Mesh back;
  const Status read = read_mesh(path, &back);
  ASSERT_TRUE(read.ok()) << read.message();
  const DataArray* a = find(back, "scaled_jacobian");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->values.size(), r.scaled_jacobian.values.size());
  for (std::size_t i = 0; i < a->values.size(); ++i)
    EXPECT_NEAR(a->values[i], r.scaled_jacobian.values[i], 1e-12);
}

}  // namespace
}  // namespace tmop
