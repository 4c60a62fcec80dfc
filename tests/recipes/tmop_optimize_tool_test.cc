// tmop_optimize's exit-code contract (README): 0 success, 1 the optimization cannot reach its
// goal, 2 bad input or usage, always one line on stderr; --write_on_failure writes the better of
// the input and the result and still exits 1.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

class TmopOptimizeTool : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system(("test -x " + tool_).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
    char dir[] = "/tmp/tmop_optimize_tool_XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    dir_ = dir;
    Mesh m = testing_grid::grid(CellType::kTri3, 4);
    ASSERT_TRUE(write_mesh(dir_ + "/grid.msh", m).ok());
  }
  void TearDown() override {
    if (!dir_.empty()) std::system(("rm -rf " + dir_).c_str());
  }
  // Runs the tool with `args`; returns its exit code, stderr in *err.
  int run(const std::string& args, std::string* err) {
    const std::string cmd = tool_ + " " + args + " > " + dir_ + "/out.txt 2> " + dir_ + "/err.txt";
    const int status = std::system(cmd.c_str());
    std::ifstream f(dir_ + "/err.txt");
    std::stringstream ss;
    ss << f.rdbuf();
    *err = ss.str();
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
  }
  std::string tool_ = TMOP_BINARY_DIR "/tools/tmop_optimize";
  std::string dir_;
};

TEST_F(TmopOptimizeTool, UsageErrorsExitWithTwoAndOneLine) {
  const std::string io = "--input=" + dir_ + "/grid.msh --output=" + dir_ + "/o.vtu ";
  for (const std::string& bad :
       {std::string("--bogus=1"), std::string("--metric=nope"), std::string("--max_iterations=-3"),
        std::string("--recipe=nope"), std::string("--feature_angle=0"), std::string("--power=0.5"),
        std::string("--boundary=sticky")}) {
    std::string err;
    EXPECT_EQ(run(io + bad, &err), 2) << bad << ": " << err;
    EXPECT_EQ(lines(err), 1) << bad << ": " << err;
  }
  std::string err;
  EXPECT_EQ(run(io, &err), 0) << err;
}

// A bad input is reported exactly as read_mesh locates it, without the program name (tmop_quality
// prints the same line for the same file).
TEST_F(TmopOptimizeTool, InputErrorsAreExactlyFileLineWhat) {
  const std::string bad = dir_ + "/bad.msh";
  {
    std::ofstream(bad) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 nan 0\n$EndNodes\n";
  }
  std::string err;
  EXPECT_EQ(run("--input=" + bad + " --output=" + dir_ + "/o.vtu", &err), 2);
  EXPECT_EQ(err, bad + ":6: coordinate is not finite\n");
  // Usage errors keep the program name.
  EXPECT_EQ(run("--input=" + bad, &err), 2);
  EXPECT_EQ(err, "tmop_optimize: --input and --output are required (see --help)\n");
}

// An output format that cannot hold the mesh is refused before anything is optimized (a quad
// mesh to .stl used to end in an empty file and exit 0), and nothing is written.
TEST_F(TmopOptimizeTool, OutputTheFormatCannotHoldIsRefusedBeforeOptimizing) {
  const std::string in = dir_ + "/quads.msh", out = dir_ + "/o.stl";
  ASSERT_TRUE(write_mesh(in, testing_grid::grid(CellType::kQuad4, 3)).ok());
  std::string err;
  EXPECT_EQ(run("--input=" + in + " --output=" + out, &err), 2);
  EXPECT_EQ(lines(err), 1) << err;
  EXPECT_EQ(err.rfind(out + ": cannot write quad4 cells to .stl", 0), 0u) << err;
  std::ifstream stdout_file(dir_ + "/out.txt");
  std::stringstream printed;
  printed << stdout_file.rdbuf();
  EXPECT_EQ(printed.str().find("before:"), std::string::npos) << printed.str();
  EXPECT_NE(std::system(("test -e " + out).c_str()), 0);
  EXPECT_EQ(run("--input=" + in + " --output=" + dir_ + "/no/such/dir/o.msh", &err), 2);
  EXPECT_NE(err.find("does not exist"), std::string::npos) << err;
}

// An inverted triangle whose vertices are all on the (fixed) boundary cannot be repaired.
TEST_F(TmopOptimizeTool, HonestFailureWritesTheInputOnlyWhenAsked) {
  Mesh m = testing_grid::grid(CellType::kTri3, 1);  // two triangles, every vertex on the boundary
  std::swap(m.cell(0)[1], m.cell(0)[2]);
  const std::string in = dir_ + "/folded.msh", out = dir_ + "/o.msh";
  ASSERT_TRUE(write_mesh(in, m).ok());
  std::string err;
  EXPECT_EQ(run("--input=" + in + " --output=" + out, &err), 1);
  EXPECT_EQ(lines(err), 1) << err;
  EXPECT_NE(err.find("every node on the fixed boundary (try --boundary=slide)"), std::string::npos)
      << err;
  EXPECT_NE(std::system(("test -e " + out).c_str()), 0);  // nothing written
  EXPECT_EQ(run("--input=" + in + " --output=" + out + " --write_on_failure", &err), 1);
  EXPECT_NE(err.find("input written unchanged"), std::string::npos) << err;
  Mesh written;
  ASSERT_TRUE(read_mesh(out, &written).ok());
  EXPECT_EQ(written.coords, m.coords);
}

// A reference mesh of another topology is a usage error, refused before any work.
TEST_F(TmopOptimizeTool, ReferenceOfAnotherTopologyExitsTwoBeforeOptimizing) {
  const std::string ref = dir_ + "/ref.msh";
  ASSERT_TRUE(write_mesh(ref, testing_grid::grid(CellType::kTri3, 3)).ok());
  std::string err;
  EXPECT_EQ(run("--input=" + dir_ + "/grid.msh --output=" + dir_ + "/o.vtu --target=reference" +
                    " --reference=" + ref,
                &err),
            2);
  EXPECT_EQ(lines(err), 1) << err;
  EXPECT_NE(err.find(ref + ": its vertices and cells do not match"), std::string::npos) << err;
  std::ifstream out(dir_ + "/out.txt");
  std::stringstream ss;
  ss << out.rdbuf();
  EXPECT_EQ(ss.str().find("before:"), std::string::npos) << ss.str();
}

// tmop_quality --output writes NaN where a measure does not apply (the boundary lines of the grid
// here): tmop_optimize reads that file and writes the result with its own quality, not the
// input's stale arrays.
TEST_F(TmopOptimizeTool, ReadsTmopQualityOutputAndRefreshesItsQualityFields) {
  const std::string quality_tool = TMOP_BINARY_DIR "/tools/tmop_quality";
  if (std::system(("test -x " + quality_tool).c_str()) != 0) GTEST_SKIP() << "no tmop_quality";
  Mesh m = testing_grid::grid(CellType::kTri3, 4);
  m.coords[2 * 12] += 0.2;  // the centre vertex of the 5 x 5 grid moved: poorer triangles
  for (std::int32_t i = 0; i < 4; ++i) {  // the bottom boundary as line cells
    const std::int32_t line[2] = {i, i + 1};
    m.add_cell(CellType::kLine2, line);
  }
  ASSERT_TRUE(write_mesh(dir_ + "/bad.msh", m).ok());
  const std::string q = dir_ + "/q.vtu", o = dir_ + "/o.vtu";
  ASSERT_EQ(
      std::system(
          (quality_tool + " --input=" + dir_ + "/bad.msh --output=" + q + " > /dev/null").c_str()),
      0);
  Mesh with_fields;
  ASSERT_TRUE(read_mesh(q, &with_fields).ok());
  std::string err;
  ASSERT_EQ(run("--input=" + q + " --output=" + o + " --recipe=shape", &err), 0) << err;
  Mesh result, result_quality;
  ASSERT_TRUE(read_mesh(o, &result).ok());
  auto min_of = [](const Mesh& mesh, const std::string& name) {
    double v = 1e300;
    for (const DataArray& a : mesh.cell_data)
      if (a.name == name)
        for (double x : a.values)
          if (!std::isnan(x)) v = std::min(v, x);
    return v;
  };
  // The result's array is the result's quality: tmop_quality on the output agrees with it.
  ASSERT_EQ(std::system(
                (quality_tool + " --input=" + o + " --output=" + dir_ + "/oq.vtu" + " > /dev/null")
                    .c_str()),
            0);
  ASSERT_TRUE(read_mesh(dir_ + "/oq.vtu", &result_quality).ok());
  EXPECT_GT(min_of(result, "mean_ratio"), min_of(with_fields, "mean_ratio"));
  EXPECT_EQ(min_of(result, "mean_ratio"), min_of(result_quality, "mean_ratio"));
}

// Inputs are never modified; usage errors are refused before any work, exit 2, one line.
TEST_F(TmopOptimizeTool, OutputOrReportThatIsAnInputAndBadPathsAreRefusedFirst) {
  const std::string in = dir_ + "/grid.msh";
  ASSERT_EQ(
      std::system(("cp " + in + " " + dir_ + "/copy.msh && ln -s " + in + " " + dir_ + "/link.msh")
                      .c_str()),
      0);
  std::ifstream before(in, std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(before)), {});
  for (const std::string& args :
       {"--output=" + in, "--output=" + dir_ + "/link.msh",
        "--output=" + dir_ + "/o.msh --report=" + in, "--output=" + dir_ + "/o.msh stray",
        "--output=" + dir_ + "/o.msh --report=" + dir_ + "/no/such/dir/r.json",
        "--output=" + dir_ + "/o.msh --target=reference",
        "--output=" + dir_ + "/o.msh --target=size_field"}) {
    std::string err;
    EXPECT_EQ(run("--input=" + in + " " + args, &err), 2) << args << ": " << err;
    EXPECT_EQ(lines(err), 1) << args << ": " << err;
    EXPECT_NE(std::system(("test -e " + dir_ + "/o.msh").c_str()), 0) << args;
  }
  std::ifstream after(in, std::ios::binary);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(after)), {}), original);
}

// A failing run still writes its report: output null, the failure in "status", and "after" the
// mesh as it is (here nothing could move).
TEST_F(TmopOptimizeTool, FailedRunWritesItsReport) {
  Mesh m = testing_grid::grid(CellType::kTri3, 1);
  std::swap(m.cell(0)[1], m.cell(0)[2]);
  const std::string in = dir_ + "/folded.msh", report = dir_ + "/r.json";
  ASSERT_TRUE(write_mesh(in, m).ok());
  std::string err;
  EXPECT_EQ(run("--input=" + in + " --output=" + dir_ + "/o.msh --report=" + report, &err), 1);
  std::ifstream f(report);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string json = ss.str();
  EXPECT_NE(json.find("\"output\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"status\": \"cannot untangle"), std::string::npos) << json;
  EXPECT_NE(json.find("\"after\": {\"min_quality\": -"), std::string::npos) << json;
  EXPECT_EQ(run("--input=" + in + " --output=" + dir_ + "/o.msh --report=" + report +
                    " --write_on_failure",
                &err),
            1);
  std::ifstream g(report);
  std::stringstream tt;
  tt << g.rdbuf();
  EXPECT_NE(tt.str().find("\"output\": \"" + dir_ + "/o.msh\""), std::string::npos) << tt.str();
  EXPECT_NE(tt.str().find("\"inverted\": 1"), std::string::npos) << tt.str();
}

}  // namespace
}  // namespace tmop
