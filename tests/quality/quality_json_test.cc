#include "tmop/quality/quality_json.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "tests/quality/test_meshes.h"
#include "tests/temp_dir.h"

namespace tmop {
namespace {

using testing_meshes::have_python;
using testing_meshes::run;

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = testing_tmp::dir() + name;
  std::ofstream(path) << text;
  return path;
}

// The value text after "key": at its first occurrence.
std::string value_of(const std::string& json, const std::string& key) {
  const std::size_t k = json.find("\"" + key + "\": ");
  if (k == std::string::npos) return "";
  const std::size_t start = k + key.size() + 4;
  return json.substr(start, json.find_first_of(",\n", start) - start);
}

TEST(QualityJson, HasTheDocumentedKeysAndParses) {
  const QualityReport r = compute_quality(testing_meshes::tet_block(3, 0.2));
  const std::string json = quality_json(r);
  for (const char* key : {"format",
                          "dim",
                          "space_dim",
                          "planar",
                          "vertices",
                          "elements",
                          "cells",
                          "tet4",
                          "inverted_cells",
                          "certifiable_cells",
                          "certified_cells",
                          "tets",
                          "slivers",
                          "angle_deg",
                          "dihedral_deg",
                          "edge_length",
                          "mean_ratio",
                          "scaled_jacobian",
                          "condition_number",
                          "min_det",
                          "min_angle_deg",
                          "max_angle_deg",
                          "min_dihedral_deg",
                          "max_dihedral_deg",
                          "min_edge_length",
                          "max_edge_length",
                          "edge_ratio",
                          "histograms",
                          "count",
                          "infinite",
                          "min",
                          "mean",
                          "max",
                          "edges",
                          "counts",
                          "below",
                          "above"}) {
    EXPECT_NE(json.find(std::string("\"") + key + "\": "), std::string::npos) << key;
  }
  EXPECT_EQ(value_of(json, "tet4"), "162");
  EXPECT_EQ(value_of(json, "angle_deg"), "null");  // 2D angles do not apply to tets
  if (!have_python()) GTEST_SKIP() << "/usr/bin/python3 not available";
  const std::string path = write_temp("quality.json", json);
  EXPECT_TRUE(run("/usr/bin/python3 -m json.tool " + path + " > /dev/null"));
  // Keys and values as a JSON reader sees them.
  EXPECT_TRUE(run("/usr/bin/python3 -c \"import json,sys; d=json.load(open('" + path +
                  "')); sys.exit(0 if d['cells']=={'tet4':162} and d['inverted_cells']==0 and "
                  "d['mean_ratio']['max']<=1 and d['dihedral_deg']['min']>0 and "
                  "d['slivers']==0 else 1)\""));
}

TEST(QualityJson, NumbersReadBackExactly) {
  const QualityReport r = compute_quality(testing_meshes::tet_block(2, 0.3));
  const std::string json = quality_json(r);
  const std::size_t at = json.find("\"mean_ratio\": {");
  ASSERT_NE(at, std::string::npos);
  const std::string mean = value_of(json.substr(at), "mean");
  EXPECT_EQ(std::strtod(mean.c_str(), nullptr), r.mean_ratio.mean);
  const std::string edge_mean = value_of(json.substr(json.find("\"edge_length\": {")), "mean");
  EXPECT_EQ(std::strtod(edge_mean.c_str(), nullptr), r.edge_length.mean);
}

// tmop_optimize keeps only the summaries of its before/after reports: the JSON must not change.
TEST(QualityJson, ReleasingPerCellValuesKeepsTheJson) {
  QualityReport r = compute_quality(testing_meshes::tet_block(3, 0.3));
  const std::string json = quality_json(r);
  ASSERT_FALSE(r.mean_ratio.values.empty());
  r.release_per_cell_values();
  for (const QualityMeasure* m : r.measures()) EXPECT_TRUE(m->values.empty()) << m->key;
  EXPECT_TRUE(r.inverted.empty());
  EXPECT_TRUE(r.certified.empty());
  EXPECT_TRUE(r.all_boundary.empty());
  EXPECT_EQ(quality_json(r), json);
}

TEST(QualityJson, MeasuresThatDoNotApplyAreNull) {
  const std::string json = quality_json(compute_quality(testing_meshes::tri_grid(2, 0.1)));
  EXPECT_EQ(value_of(json, "dihedral_deg"), "null");
  EXPECT_EQ(value_of(json, "min_dihedral_deg"), "null");
  EXPECT_EQ(value_of(json, "slivers"), "null");
  EXPECT_EQ(value_of(json, "planar"), "true");
  EXPECT_NE(value_of(json, "angle_deg"), "null");
  const std::string empty = quality_json(compute_quality(Mesh()));
  EXPECT_EQ(value_of(empty, "mean_ratio"), "null");
  EXPECT_EQ(value_of(empty, "edge_length"), "null");
  if (!have_python()) GTEST_SKIP() << "/usr/bin/python3 not available";
  EXPECT_TRUE(
      run("/usr/bin/python3 -m json.tool " + write_temp("empty.json", empty) + " > /dev/null"));
}

TEST(QualityJson, InfiniteConditionNumbersAreCountedNotPrinted) {
  Mesh m = testing_meshes::tri_grid(2, 0.1);
  std::swap(m.cell(0)[1], m.cell(0)[2]);
  const std::string json = quality_json(compute_quality(m));
  EXPECT_EQ(json.find("inf"), json.find("infinite"));  // no "inf" / "nan" literals
  EXPECT_EQ(json.find("nan"), std::string::npos);
  const std::size_t at = json.find("\"condition_number\": {");
  EXPECT_EQ(value_of(json.substr(at), "infinite"), "1");
}

}  // namespace
}  // namespace tmop
