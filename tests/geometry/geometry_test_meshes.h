// tests/geometry/geometry_test_meshes.h
// Fixture access for the geometry tests: meshes made with gmsh from the .geo files beside them
// (tests/geometry/data/) and /data/part.geo (`gmsh -3 data/part.geo -clmax 0.2`).
#ifndef TMOP_TESTS_GEOMETRY_GEOMETRY_TEST_MESHES_H_
#define TMOP_TESTS_GEOMETRY_GEOMETRY_TEST_MESHES_H_

#include <gtest/gtest.h>

#include <string>

#include "tmop/io/mesh_io.h"
#include "tmop/mesh/mesh.h"

namespace tmop {
namespace testing_util {

inline std::string geometry_data(const std::string& name) {
  return std::string(TMOP_SOURCE_DIR) + "/tests/geometry/data/" + name;
}

inline Mesh load_geometry_mesh(const std::string& name) {
  Mesh mesh;
  const Status s = read_mesh(geometry_data(name), &mesh);
  EXPECT_TRUE(s.ok()) << s.message();
  return mesh;
}

}  // namespace testing_util
}  // namespace tmop

#endif  // TMOP_TESTS_GEOMETRY_GEOMETRY_TEST_MESHES_H_
