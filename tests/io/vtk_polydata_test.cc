// Legacy .vtk POLYDATA (what VTK filters and ParaView write for surfaces) is read as vertex /
// line2 / tri3 / quad4 cells; cell data follows the VERTICES, LINES, POLYGONS order.
#include <gtest/gtest.h>

#include <fstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

const char* kPoints = "POINTS 5 double\n0 0 0 1 0 0 1 1 0 0 1 0.5 0.25 0.125 1\n";

void expect_mesh(const Mesh& m) {
  ASSERT_EQ(m.space_dim, 3);
  ASSERT_EQ(m.num_cells(), 4);
  EXPECT_EQ(m.cell_types[0], CellType::kVertex);
  EXPECT_EQ(m.cell_types[1], CellType::kLine2);
  EXPECT_EQ(m.cell_types[2], CellType::kQuad4);
  EXPECT_EQ(m.cell_types[3], CellType::kTri3);
  EXPECT_EQ(std::vector<std::int32_t>(m.cell(2), m.cell(2) + 4),
            (std::vector<std::int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(std::vector<std::int32_t>(m.cell(3), m.cell(3) + 3),
            (std::vector<std::int32_t>{0, 1, 4}));
  EXPECT_EQ(m.cell_region, (std::vector<std::int32_t>{1, 2, 3, 4}));
  EXPECT_EQ(m.vertex(4)[2], 1.0);
}

TEST(VtkPolydata, OldCellLayout) {
  const std::string path = test::temp_dir() + "/p.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\np\nASCII\nDATASET POLYDATA\n"
                      << kPoints
                      << "VERTICES 1 2\n1 4\nLINES 1 3\n2 0 1\nPOLYGONS 2 9\n4 0 1 2 3\n3 0 1 4\n"
                         "CELL_DATA 4\nSCALARS gmsh:physical int 1\nLOOKUP_TABLE default\n"
                         "1 2 3 4\n";
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_TRUE(s.ok()) << s.message();
  expect_mesh(m);
}

TEST(VtkPolydata, Version51Layout) {
  const std::string path = test::temp_dir() + "/p.vtk";
  std::ofstream(path) << "# vtk DataFile Version 5.1\np\nASCII\nDATASET POLYDATA\n"
                      << kPoints
                      << "VERTICES 2 1\nOFFSETS vtktypeint64\n0 1\nCONNECTIVITY vtktypeint64\n4\n"
                         "LINES 2 2\nOFFSETS vtktypeint64\n0 2\nCONNECTIVITY vtktypeint64\n0 1\n"
                         "POLYGONS 3 7\nOFFSETS vtktypeint64\n0 4 7\nCONNECTIVITY vtktypeint64\n"
                         "0 1 2 3 0 1 4\nCELL_DATA 4\nFIELD FieldData 1\ngmsh:physical 1 4 int\n"
                         "1 2 3 4\n";
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_TRUE(s.ok()) << s.message();
  expect_mesh(m);
}

TEST(VtkPolydata, PolygonsBeyondQuadsAreRejectedWithALocation) {
  const std::string path = test::temp_dir() + "/p.vtk";
  std::ofstream(path) << "# vtk DataFile Version 3.0\np\nASCII\nDATASET POLYDATA\n"
                      << kPoints << "POLYGONS 1 6\n5 0 1 2 3 4\n";
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), path +
                             ":7: POLYGONS row 0 has 5 points; tmop reads single vertices, "
                             "2-point lines, triangles and quadrilaterals");
}

}  // namespace
}  // namespace tmop
