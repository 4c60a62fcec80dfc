// write_mesh is atomic: the output is either the complete new file or untouched, and no
// temporary file is left behind.
#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.' || (std::string(e->d_name) != "." && std::string(e->d_name) != ".."))
        names.push_back(e->d_name);
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(Write, FailedWriteLeavesExistingFileAndNoTemporaries) {
  const std::string dir = test::temp_dir();
  const std::string out = dir + "/out.stl";
  { std::ofstream(out) << "previous content\n"; }
  // A tet cannot go into .stl: the error comes after the temporary file was created.
  const Status s = write_mesh(out, test::make_mesh({CellType::kTet4}));
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind(out + ": cannot write tet4", 0), 0u) << s.message();
  EXPECT_EQ(slurp(out), "previous content\n");
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.stl"});
  // The same for a format tmop writes itself.
  const Status v = write_mesh(dir + "/out.mesh", test::make_mesh({CellType::kHex27}));
  EXPECT_FALSE(v.ok());
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.stl"});
}

TEST(Write, SuccessfulWriteReplacesTheFileAndLeavesNoTemporaries) {
  const std::string dir = test::temp_dir();
  const std::string out = dir + "/out.msh";
  { std::ofstream(out) << "previous content\n"; }
  const Mesh m = test::make_mesh({CellType::kTet4, CellType::kTri3});
  ASSERT_TRUE(write_mesh(out, m).ok());
  EXPECT_EQ(list_dir(dir), std::vector<std::string>{"out.msh"});
  Mesh back;
  ASSERT_TRUE(read_mesh(out, &back).ok());
  EXPECT_EQ(test::diff_meshes(m, back), "");
}

TEST(Write, MissingDirectoryAndBadOptionsFailWithAMessage) {
  const Mesh m = test::make_mesh({CellType::kTet4});
  Status s = write_mesh("/nonexistent/dir/out.msh", m);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind("/nonexistent/dir/out.msh: ", 0), 0u) << s.message();
  const std::string dir = test::temp_dir();
  WriteOptions o;
  o.msh_version = 30;
  s = write_mesh(dir + "/x.msh", m, o);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("MSH version 30"), std::string::npos);
  s = write_mesh(dir + "/x.abc", m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("unknown mesh file extension"), std::string::npos);
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(Write, InconsistentMeshIsRefused) {
  const std::string dir = test::temp_dir();
  Mesh m = test::make_mesh({CellType::kTet4, CellType::kTri3});
  m.cell_region.pop_back();
  for (const char* ext : {"msh", "vtk", "vtu", "mesh", "obj"})
    EXPECT_FALSE(write_mesh(dir + "/x." + ext, m).ok()) << ext;
  m = test::make_mesh({CellType::kTet4});
  m.cell_nodes[2] = 1000;
  const Status s = write_mesh(dir + "/x.vtu", m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("refers to vertex 1000"), std::string::npos) << s.message();
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(Write, ReadingNeverModifiesTheInput) {
  const std::string dir = test::temp_dir();
  const std::string path = dir + "/in.vtu";
  ASSERT_TRUE(write_mesh(path, test::make_mesh({CellType::kHex8})).ok());
  chmod(path.c_str(), 0444);  // read-only input still reads
  const std::string before = slurp(path);
  Mesh m;
  ASSERT_TRUE(read_mesh(path, &m).ok());
  EXPECT_EQ(slurp(path), before);
}

TEST(Write, ExtensionsAreCaseInsensitive) {
  const std::string dir = test::temp_dir();
  const Mesh m = test::make_mesh({CellType::kTet4});
  ASSERT_TRUE(write_mesh(dir + "/A.MSH", m).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(dir + "/A.MSH", &back).ok());
  EXPECT_EQ(test::diff_meshes(m, back), "");
}

}  // namespace
}  // namespace tmop
