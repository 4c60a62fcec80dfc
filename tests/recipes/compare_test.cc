// The tmop_compare program (tools/tmop_compare.cc), run as users run it. Skipped when the tool is
// not built in this build tree.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tests/recipes/recipe_test_meshes.h"
#include "tests/temp_dir.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

using testing_recipes::exit_code;

const std::string kTool = std::string(TMOP_BINARY_DIR) + "/tools/tmop_compare";

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The number after `"key": ` at the first occurrence following `after`.
double number_after(const std::string& text, const std::string& after, const std::string& key) {
  std::size_t p = text.find("\"" + after + "\"");
  if (p == std::string::npos) return -1;
  p = text.find("\"" + key + "\": ", p);
  if (p == std::string::npos) return -1;
  return std::strtod(text.c_str() + p + key.size() + 4, nullptr);
}

class TmopCompareTool : public ::testing::Test {
 protected:
  void SetUp() override {
    if (exit_code("test -x " + kTool) != 0) GTEST_SKIP() << kTool << " not built";
    dir_ = testing_tmp::dir();
    Mesh a = testing_grid::grid(CellType::kQuad4, 4);
    Mesh b = a;
    b.vertex(6)[0] += 0.05;  // vertex (1, 1) of the 4 x 4 grid, spacing 0.25: h/5
    a_ = dir_ + "compare_a.vtu";
    b_ = dir_ + "compare_b.vtu";
    other_ = dir_ + "compare_other.vtu";
    ASSERT_TRUE(write_mesh(a_, a).ok());
    ASSERT_TRUE(write_mesh(b_, b).ok());
    ASSERT_TRUE(write_mesh(other_, testing_grid::grid(CellType::kQuad4, 3)).ok());
  }
  std::string dir_, a_, b_, other_;
};

TEST_F(TmopCompareTool, JsonHasQualityVerdictsAndDisplacements) {
  const std::string json = dir_ + "compare.json";
  ASSERT_EQ(exit_code(kTool + " " + a_ + " " + b_ + " --json --reference=" + a_ + " > " + json), 0);
  const std::string text = read_file(json);
  // The quality part is the quality module's report (its keys, docs/quality.md).
  EXPECT_NE(text.find("\"format\": \"tmop.quality/1\""), std::string::npos);
  EXPECT_NE(text.find("\"format\": \"tmop.compare/1\""), std::string::npos);
  // A is the regular grid: better on the worst and the mean scaled Jacobian.
  EXPECT_NE(text.find("\"scaled_jacobian\": {\"worst\": \"a\", \"mean\": \"a\"}"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\"inverted_cells\": \"equal\""), std::string::npos);
  EXPECT_NEAR(number_after(text, "b_minus_a", "max"), 0.05, 1e-12);
  EXPECT_NEAR(number_after(text, "b_minus_a", "max_relative"), 0.2, 1e-12);
  EXPECT_EQ(number_after(text, "b_minus_a", "moved"), 1);
  EXPECT_EQ(number_after(text, "a_minus_reference", "max"), 0);
  if (exit_code("test -x /usr/bin/python3") == 0) {
    EXPECT_EQ(exit_code("/usr/bin/python3 -m json.tool " + json + " > /dev/null"), 0);
  }
}

TEST_F(TmopCompareTool, FlagsAndTextTable) {
  const std::string out = dir_ + "compare.txt";
  ASSERT_EQ(exit_code(kTool + " --a=" + a_ + " --b=" + b_ + " > " + out), 0);
  const std::string text = read_file(out);
  EXPECT_NE(text.find("scaled Jacobian"), std::string::npos);
  EXPECT_NE(text.find("b_minus_a"), std::string::npos);
}

TEST_F(TmopCompareTool, DifferentTopologyIsOneLineAndExitTwo) {
  const std::string err = dir_ + "compare.err";
  EXPECT_EQ(exit_code(kTool + " " + a_ + " " + other_ + " 2> " + err), 2);
  std::ifstream in(err);
  std::string line, extra;
  std::getline(in, line);
  // The files in the order given (was: "OTHER and A").
  EXPECT_EQ(line, "tmop_compare: " + a_ + " and " + other_ +
                      " have different topologies (vertices or cells differ)");
  EXPECT_FALSE(std::getline(in, extra));
  EXPECT_EQ(exit_code(kTool + " " + a_ + " 2> /dev/null"), 2);
  EXPECT_EQ(exit_code(kTool + " --no_such_flag " + a_ + " " + b_ + " 2> /dev/null"), 2);
}

// Displacements relative to edge lengths at 1e-300 (squared lengths underflowed: h = 0, the
// relative displacement infinite, printed null).
TEST_F(TmopCompareTool, RelativeDisplacementAtTinyScale) {
  Mesh a = testing_grid::grid(CellType::kQuad4, 4);
  for (double& x : a.coords) x *= 1e-300;
  Mesh b = a;
  b.vertex(6)[0] += 0.05e-300;
  const std::string ta = dir_ + "tiny_a.vtu", tb = dir_ + "tiny_b.vtu", json = dir_ + "tiny.json";
  ASSERT_TRUE(write_mesh(ta, a).ok());
  ASSERT_TRUE(write_mesh(tb, b).ok());
  ASSERT_EQ(exit_code(kTool + " " + ta + " " + tb + " --json > " + json), 0);
  EXPECT_NEAR(number_after(read_file(json), "b_minus_a", "max_relative"), 0.2, 1e-9);
}

// Issue 19: a directory crashed the tool (std::length_error); bad flag values exited 1.
TEST_F(TmopCompareTool, DirectoriesAndBadFlagValuesExitTwoWithOneLine) {
  const std::string err = dir_ + "compare.err", d = dir_ + "compare_dir.vtu";
  ASSERT_EQ(exit_code("mkdir -p " + d), 0);
  EXPECT_EQ(exit_code(kTool + " " + d + " " + b_ + " 2> " + err), 2);
  EXPECT_EQ(read_file(err), d + ": not a regular file (a directory)\n");
  EXPECT_EQ(exit_code(kTool + " " + a_ + " " + b_ + " --reference=" + d + " 2> " + err), 2);
  EXPECT_EQ(read_file(err), d + ": not a regular file (a directory)\n");
  EXPECT_EQ(exit_code(kTool + " " + a_ + " " + b_ + " --threads=abc 2> " + err), 2);
  EXPECT_EQ(read_file(err), "tmop_compare: bad value 'abc' for --threads (expected an integer)\n");
  EXPECT_EQ(exit_code(kTool + " --version > " + err), 0);
  EXPECT_EQ(read_file(err).rfind("tmop_compare ", 0), 0u);
}

}  // namespace
}  // namespace tmop
