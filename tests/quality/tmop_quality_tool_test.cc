// The tmop_quality program (tools/tmop_quality.cc), run as users run it. Skipped when the tools
// are not built in this build tree.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/quality/test_meshes.h"
#include "tests/temp_dir.h"
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
    dir_ = testing_tmp::dir();
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

// --output honours --binary and --msh_version like tmop_optimize; a bad version exits 2.
TEST_F(TmopQualityTool, MshVersionAndBinaryChooseTheOutputForm) {
  const std::string msh = dir_ + "tool_out.msh";
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --output=" + msh +
                      " --msh_version=3 > /dev/null 2>&1"),
            2);
  ASSERT_EQ(exit_code(kTool + " --input=" + input_ + " --output=" + msh +
                      " --msh_version=2.2 --binary > /dev/null"),
            0);
  std::ifstream in(msh, std::ios::binary);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(second, "2.2 1 8");
  Mesh out;
  EXPECT_TRUE(read_mesh(msh, &out).ok());
  EXPECT_EQ(out.num_cells(), testing_meshes::tet_block(2, 0.2).num_cells());
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

std::string slurp_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Issue 19: a directory as input crashed (SIGABRT, std::length_error) or, named ".", was an
// "unknown mesh file extension '.'"; --help / --version / bad values follow the tool contract.
TEST_F(TmopQualityTool, DirectoriesHelpVersionAndBadValues) {
  const std::string err = dir_ + "tool.err", out = dir_ + "tool.out", d = dir_ + "tool_dir.msh";
  ASSERT_EQ(exit_code("mkdir -p " + d), 0);
  EXPECT_EQ(exit_code(kTool + " --input=" + d + " 2> " + err), 2);
  EXPECT_EQ(slurp_file(err), d + ": not a regular file (a directory)\n");
  EXPECT_EQ(exit_code("cd " + dir_ + " && " + kTool + " --input=. 2> " + err), 2);
  EXPECT_EQ(slurp_file(err), ".: not a regular file (a directory)\n");
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --threads=abc 2> " + err), 2);
  EXPECT_EQ(slurp_file(err), "tmop_quality: bad value 'abc' for --threads (expected an integer)\n");
  EXPECT_EQ(exit_code(kTool + " --help > " + out), 0);
  EXPECT_NE(slurp_file(out).find("-sample_rule"), std::string::npos);
  EXPECT_EQ(exit_code(kTool + " --version > " + out), 0);
  EXPECT_EQ(slurp_file(out).rfind("tmop_quality 0.", 0), 0u) << slurp_file(out);
}

// --svg goes through the atomic writer: a failed write leaves neither a truncated SVG under the
// final name nor a temporary file.
TEST_F(TmopQualityTool, SvgIsWrittenAtomically) {
  const std::string sub = dir_ + "svg_sub";
  ASSERT_EQ(exit_code("rm -rf " + sub + " && mkdir -p " + sub), 0);
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --svg=" + sub + "/q.svg > /dev/null"), 0);
  EXPECT_NE(slurp_file(sub + "/q.svg").find("</svg>"), std::string::npos);
  EXPECT_EQ(exit_code("test $(ls -A " + sub + " | wc -l) -eq 1"), 0);  // no temporaries
  // The rename fails (the target is a directory): exit 1, no temporary left.
  ASSERT_EQ(exit_code("mkdir " + sub + "/d.svg"), 0);
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --svg=" + sub + "/d.svg > /dev/null 2>&1"),
            1);
  EXPECT_EQ(exit_code("test $(ls -A " + sub + " | wc -l) -eq 2"), 0);
  EXPECT_EQ(exit_code("rmdir " + sub + "/d.svg"), 0);
  // Unwritable directory: exit 1, the old picture untouched, nothing else left.
  if (::geteuid() == 0) GTEST_SKIP() << "root can write anywhere";
  const std::string before = slurp_file(sub + "/q.svg");
  ASSERT_EQ(exit_code("chmod 555 " + sub), 0);
  EXPECT_EQ(exit_code(kTool + " --input=" + input_ + " --svg=" + sub + "/q.svg > /dev/null 2>&1"),
            1);
  ASSERT_EQ(exit_code("chmod 755 " + sub), 0);
  EXPECT_EQ(slurp_file(sub + "/q.svg"), before);
  EXPECT_EQ(exit_code("test $(ls -A " + sub + " | wc -l) -eq 1"), 0);
}

}  // namespace
}  // namespace tmop
