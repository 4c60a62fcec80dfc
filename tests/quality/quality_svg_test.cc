#include "tmop/quality/quality_svg.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/quality/test_meshes.h"
#include "tests/temp_dir.h"

namespace tmop {
namespace {

using testing_meshes::have_python;
using testing_meshes::run;

// Well-formed XML with an <svg> root, checked by Python's parser.
void expect_well_formed_svg(const std::string& svg, const std::string& name) {
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  if (!have_python()) GTEST_SKIP() << "/usr/bin/python3 not available";
  const std::string path = testing_tmp::dir() + name;
  std::ofstream(path) << svg;
  EXPECT_TRUE(
      run("/usr/bin/python3 -c \"import sys, xml.etree.ElementTree as E; "
          "r = E.parse('" +
          path +
          "').getroot(); "
          "sys.exit(0 if r.tag.endswith('svg') else 1)\""));
}

TEST(QualitySvg, PlanarMeshIsColouredWithAColourBar) {
  Mesh m = testing_meshes::tri_grid(4, 0.2);
  std::swap(m.cell(3)[1], m.cell(3)[2]);
  const std::string svg = quality_svg(m, compute_quality(m));
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
  EXPECT_NE(svg.find("#ff00ff"), std::string::npos);  // the inverted cell
  EXPECT_NE(svg.find("mean ratio"), std::string::npos);
  expect_well_formed_svg(svg, "planar.svg");
}

TEST(QualitySvg, VolumeMeshGetsHistogramsAndADihedralScatter) {
  const Mesh m = testing_meshes::tet_block(3, 0.3);
  const std::string svg = quality_svg(m, compute_quality(m));
  EXPECT_NE(svg.find("max vs min dihedral angle"), std::string::npos);
  EXPECT_NE(svg.find("<circle"), std::string::npos);
  expect_well_formed_svg(svg, "volume.svg");
}

TEST(QualitySvg, CompareOverlaysBothReports) {
  const QualityReport before = compute_quality(testing_meshes::tet_block(3, 0.35));
  const QualityReport after = compute_quality(testing_meshes::tet_block(3, 0.05));
  const std::string svg = quality_svg_compare(before, after, "input <raw>", "tmop");
  EXPECT_NE(svg.find("input &lt;raw&gt;"), std::string::npos);
  EXPECT_NE(svg.find("tmop"), std::string::npos);
  EXPECT_NE(svg.find("#d95f02"), std::string::npos);
  EXPECT_NE(svg.find("#1b9e77"), std::string::npos);
  expect_well_formed_svg(svg, "compare.svg");
}

}  // namespace
}  // namespace tmop
