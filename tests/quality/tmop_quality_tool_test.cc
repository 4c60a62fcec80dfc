// The tmop_quality program (tools/tmop_quality.cc), run as users run it. Skipped when the tools
// are not built in this build tree.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/quality/test_meshes.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

const std::string kTool = std::string(TMOP_BINARY_DIR) + "/tools/tmop_quality";

int exit_code(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class TmopQualityTool : public ::testing::Test {
 protected:
  void SetUp() override {
    if (exit_code("test -x " + kTool) != 0) GTEST_SKIP() << kTool << " not built";
    dir_ = ::testing::TempDir();
    input_ = dir_ + "tool_input.vtu";
    ASSERT_TRUE(write_mesh(input_, testing_meshes::tet_block(2, 0.2)).ok());
  }
  std::string dir_, input_;
};

TEST_F(TmopQualityTool, PrintsJsonAndWritesFieldsAndSvg) {
  const std::string json = dir_ + "tool.json", vtu = dir_ + "tool_out.vtu", svg = dir_ + "t.svg";
  ASSERT_EQ(exit_code(kTool + " --input=" + input_ + " --json --output=" + vtu + " --svg=" + svg +
                      " > " + json),
            0);
  Mesh out;
  ASSERT_TRUE(read_mesh(vtu, &out).ok());
  bool found = false;
  for (const DataArray& a : out.cell_data) found = found || a.name == "mean_ratio";
  EXPECT_TRUE(found);
  if (!testing_meshes::have_python()) GTEST_SKIP() << "/usr/bin/python3 not available";
  EXPECT_EQ(exit_code("/usr/bin/python3 -m json.tool " + json + " > /dev/null"), 0);
  EXPECT_EQ(exit_code("/usr/bin/python3 -c \"import xml.etree.ElementTree as E; E.parse('" + svg +
                      "')\""),
            0);
}

TEST_F(TmopQualityTool, BadInputAndUsageErrorsExitWithTwo) {
  const std::string err = dir_ + "tool.err";
  EXPECT_EQ(exit_code(kTool + " --input=" + dir_ + "missing.msh 2> " + err), 2);
  std::ifstream in(err);
  std::string line, extra;
  std::getline(in, line);
  EXPECT_NE(line.find("missing.msh"), std::string::npos);
  EXPECT_FALSE(std::getline(in, extra));  // exactly one line
  EXPECT_EQ(exit_code(kTool + " 2> /dev/null"), 2);
  EXPECT_EQ(exit_code(kTool + " --no_such_flag 2> /dev/null"), 2);
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --threads=x 2> /dev/null"), 2);
  EXPECT_EQ(exit_code(kTool + " --help > /dev/null"), 0);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Errors about a file are exactly "FILE:LINE: what" (or "FILE: what") on one line, without the
// program name, as tmop_optimize prints them: the same line for the same bad file in every tool.
TEST_F(TmopQualityTool, FileErrorsAreExactlyFileLineWhat) {
  const std::string bad = dir_ + "garbage_line.obj", err = dir_ + "tool.err";
  { std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nthis is not obj\nf 1 2 3\n"; }
  EXPECT_EQ(exit_code(kTool + " --input=" + bad + " > /dev/null 2> " + err), 2);
  EXPECT_EQ(slurp(err), bad + ":4: unknown OBJ statement 'this'\n");
  // An output the format cannot hold: exit 1, the write_mesh message as it is, no file.
  const std::string stl = dir_ + "tets.stl";
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --output=" + stl + " > /dev/null 2> " + err),
            1);
  const std::string line = slurp(err);
  EXPECT_EQ(line.rfind(stl + ": cannot write tet4 cells to .stl", 0), 0u) << line;
  EXPECT_EQ(line.find('\n'), line.size() - 1) << line;
  EXPECT_NE(exit_code("test -e " + stl), 0);
  // Usage errors keep the program name.
  EXPECT_EQ(exit_code(kTool + " 2> " + err), 2);
  EXPECT_EQ(slurp(err), "tmop_quality: --input is required (see --help)\n");
}

TEST_F(TmopQualityTool, SummaryIsTheDefault) {
  const std::string out = dir_ + "summary.txt";
  ASSERT_EQ(exit_code(kTool + " --input=" + input_ + " > " + out), 0);
  std::ifstream in(out);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("mean ratio"), std::string::npos);
  EXPECT_NE(text.find("tet4 48"), std::string::npos);
}

}  // namespace
}  // namespace tmop
