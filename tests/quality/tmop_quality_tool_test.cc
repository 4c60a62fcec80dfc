// The tmop_quality program (tools/tmop_quality.cc), run as users run it. Skipped when the tools
// are not built in this build tree.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
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
