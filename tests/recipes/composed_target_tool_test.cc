// tmop_optimize --target=composed: the factor flags, their usage errors (exit 2, one line on
// stderr) and "every factor from the input keeps the input".
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

class ComposedTargetTool : public ::testing::Test {
 protected:
  void SetUp() override {
    tool_ = TMOP_BINARY_DIR "/tools/tmop_optimize";
    if (std::system(("test -x " + tool_).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
    char dir[] = "/tmp/tmop_composed_XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    dir_ = dir;
    std::mt19937 rng(9);
    Mesh quads = testing_grid::grid(CellType::kQuad4, 5);
    testing_grid::perturb(&quads, 5, 0.3, &rng);
    DataArray h{"h", 1, {}};
    for (int v = 0; v < quads.num_vertices(); ++v)
      h.values.push_back(0.15 + 0.1 * quads.vertex(v)[1]);
    quads.point_data.push_back(h);
    quads_ = quads;
    ASSERT_TRUE(write_mesh(dir_ + "/quads.vtu", quads).ok());
    Mesh tets = testing_grid::grid(CellType::kTet4, 3);
    testing_grid::perturb(&tets, 3, 0.3, &rng);
    tets_ = tets;
    ASSERT_TRUE(write_mesh(dir_ + "/tets.vtu", tets).ok());
  }
  void TearDown() override {
    if (!dir_.empty()) std::system(("rm -rf " + dir_).c_str());
  }

  // Runs the tool on `input` (a file in the temporary folder) with `flags`; returns the exit
  // status and keeps stderr.
  int run(const std::string& input, const std::string& flags) {
    const std::string cmd = tool_ + " --input=" + dir_ + "/" + input + " --output=" + dir_ +
                            "/out.vtu " + flags + " > " + dir_ + "/log 2> " + dir_ + "/err";
    const int status = std::system(cmd.c_str());
    std::ifstream err(dir_ + "/err");
    std::stringstream ss;
    ss << err.rdbuf();
    stderr_ = ss.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  void expect_usage_error(const std::string& input, const std::string& flags,
                          const std::string& part) {
    EXPECT_EQ(run(input, flags), 2) << flags;
    EXPECT_NE(stderr_.find(part), std::string::npos) << flags << ": " << stderr_;
    EXPECT_EQ(std::count(stderr_.begin(), stderr_.end(), '\n'), 1) << stderr_;
    std::ifstream out(dir_ + "/out.vtu");
    EXPECT_FALSE(out.good()) << "no output on a usage error";
  }

  std::string tool_, dir_, stderr_;
  Mesh quads_, tets_;
};

TEST_F(ComposedTargetTool, UsageErrorsExitTwoWithOneLine) {
  expect_usage_error("quads.vtu", "--target_size=1", "--target_size needs --target=composed");
  expect_usage_error("quads.vtu", "--target=composed --target_size=big",
                     "--target_size: size source 'big' is not");
  expect_usage_error("quads.vtu", "--target=composed --target_orientation=sideways",
                     "--target_orientation: orientation source 'sideways'");
  expect_usage_error("quads.vtu", "--target=composed --target_shape=round",
                     "--target_shape must be ideal or initial");
  expect_usage_error("quads.vtu", "--target=composed --target_skew=equal",
                     "--target_skew: skew source 'equal'");
  expect_usage_error("tets.vtu", "--target=composed --target_skew=60",
                     "composed target skew: 3 values");
  expect_usage_error("quads.vtu", "--target=composed --target_aspect=1,2,3",
                     "composed target aspect: 2 values");
  expect_usage_error("quads.vtu", "--target=composed --target_size=field:nope",
                     "no point_data array 'nope'");
  expect_usage_error("quads.vtu", "--target=composed --target_size=-2",
                     "composed target size: invalid value -2");
  expect_usage_error("quads.vtu", "--target=composed --target_size=0 --target_skew=60",
                     "composed target size: invalid value 0");
  expect_usage_error("quads.vtu", "--target=bogus", "unknown --target 'bogus'");
}

TEST_F(ComposedTargetTool, EveryFactorFromTheInputKeepsTheInput) {
  for (const char* input : {"quads.vtu", "tets.vtu"}) {
    ASSERT_EQ(run(input,
                  "--recipe=shape --metric=size_shape_orientation --target=composed "
                  "--target_size=initial --target_orientation=initial --target_shape=initial"),
              0)
        << stderr_;
    Mesh in, out;
    ASSERT_TRUE(read_mesh(dir_ + "/" + input, &in).ok());
    ASSERT_TRUE(read_mesh(dir_ + "/out.vtu", &out).ok());
    ASSERT_EQ(in.coords.size(), out.coords.size());
    for (std::size_t i = 0; i < in.coords.size(); ++i)
      EXPECT_NEAR(out.coords[i], in.coords[i], 1e-10) << input;
    std::system(("rm -f " + dir_ + "/out.vtu").c_str());
  }
}

TEST_F(ComposedTargetTool, FieldSizeAndConstantFactorsRun) {
  EXPECT_EQ(run("quads.vtu",
                "--recipe=shape --metric=size_shape --target=composed --target_size=field:h "
                "--target_orientation=angle:30 --target_skew=80 --target_aspect=1.5,1"),
            0)
      << stderr_;
  Mesh out;
  ASSERT_TRUE(read_mesh(dir_ + "/out.vtu", &out).ok());
  EXPECT_NE(out.coords, quads_.coords);
  std::system(("rm -f " + dir_ + "/out.vtu").c_str());
  EXPECT_EQ(run("tets.vtu",
                "--recipe=shape --target=composed --target_size=0.3 "
                "--target_orientation=1,0,0,0,1,0 --target_skew=ideal --target_aspect=initial"),
            0)
      << stderr_;
}

}  // namespace
}  // namespace tmop
