// tmop_optimize's exit-code contract (README): 0 success, 1 the optimization cannot reach its
// goal, 2 bad input or usage, always one line on stderr; --write_on_failure writes the better of
// the input and the result and still exits 1.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include "tests/geometry/curved_test_meshes.h"
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
        std::string("--boundary=sticky"), std::string("--guarantee=maybe"),
        std::string("--partitions=0"), std::string("--partitions=two"),
        std::string("--partitions=4 --part_size=100"), std::string("--part_rings=-1")}) {
    std::string err;
    EXPECT_EQ(run(io + bad, &err), 2) << bad << ": " << err;
    EXPECT_EQ(lines(err), 1) << bad << ": " << err;
  }
  std::string err;
  EXPECT_EQ(run(io, &err), 0) << err;
}

// --msh_version and --binary choose the .msh output's version and encoding; a version other
// than 2.2 or 4.1 is a usage error (exit 2, one line) said before any work.
TEST_F(TmopOptimizeTool, MshVersionAndBinaryChooseTheOutputForm) {
  const std::string in = "--input=" + dir_ + "/grid.msh ";
  for (const std::string& bad : {std::string("4"), std::string("2.1"), std::string("")}) {
    std::string err;
    EXPECT_EQ(run(in + "--output=" + dir_ + "/o.msh --msh_version=" + bad, &err), 2) << err;
    EXPECT_EQ(lines(err), 1) << err;
  }
  const struct {
    std::string flags, header;
  } cases[] = {{"--msh_version=2.2", "2.2 0 8"},
               {"--msh_version=2.2 --binary", "2.2 1 8"},
               {"--msh_version=4.1 --binary", "4.1 1 8"},
               {"", "4.1 0 8"}};
  for (const auto& c : cases) {
    std::string err;
    const std::string out = dir_ + "/o.msh";
    ASSERT_EQ(run(in + "--output=" + out + " " + c.flags, &err), 0) << c.flags << ": " << err;
    std::ifstream f(out, std::ios::binary);
    std::string first, second;
    std::getline(f, first);
    std::getline(f, second);
    EXPECT_EQ(first, "$MeshFormat") << c.flags;
    EXPECT_EQ(second, c.header) << c.flags;
    Mesh m;
    EXPECT_TRUE(read_mesh(out, &m).ok()) << c.flags;
    EXPECT_EQ(m.num_cells(), testing_grid::grid(CellType::kTri3, 4).num_cells()) << c.flags;
  }
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

// A --geometry is checked against the mesh before any work (no "before:" line): malformed under
// every recipe, far from the mesh (with the distance), unused by a fixed volume boundary; and a
// recipe for another kind of mesh (sliver on 2D) is refused there too. All exit 2, one line.
TEST_F(TmopOptimizeTool, GeometryAndRecipeAreCheckedBeforeAnyWork) {
  const double c[3] = {2, 2, 0};
  const std::string sphere = dir_ + "/sphere.msh", box = dir_ + "/box.msh";
  ASSERT_TRUE(write_mesh(sphere, curved_meshes::cube_sphere(4, 3.0, c, true)).ok());
  ASSERT_TRUE(write_mesh(box, testing_grid::grid(CellType::kTet4, 2)).ok());
  auto stdout_text = [&]() {
    std::ifstream f(dir_ + "/out.txt");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  const struct {
    std::string input, args, expect;
  } cases[] = {
      {sphere, "--geometry=sphere:1,2", "expected 4 comma-separated numbers"},
      {sphere, "--geometry=sphere:1,2 --recipe=surface", "expected 4 comma-separated numbers"},
      {sphere, "--geometry=sphere:1,2 --recipe=laplace", "expected 4 comma-separated numbers"},
      {sphere, "--geometry=sphere:1,2 --recipe=shape", "expected 4 comma-separated numbers"},
      {sphere, "--geometry=sphere:0,0,0,1", "is 0.5176 from the mesh"},
      {sphere, "--geometry=sphere:0,0,0,1 --recipe=surface", "is 0.5176 from the mesh"},
      {box, "--geometry=plane:0,0,0,0,0,1", "would be unused"},
      {box, "--geometry=plane:0,0,-1,0,0,1 --boundary=slide", "from the mesh"},
      {dir_ + "/grid.msh", "--recipe=sliver", "recipe sliver needs a volume mesh"},
      {dir_ + "/grid.msh", "--geometry=plane:0,0,0,0,0,1 --boundary=slide", "no surfaces"},
  };
  for (const auto& k : cases) {
    std::string err;
    const std::string args = "--input=" + k.input + " --output=" + dir_ + "/o.msh " + k.args;
    EXPECT_EQ(run(args, &err), 2) << args << ": " << err;
    EXPECT_EQ(lines(err), 1) << args << ": " << err;
    EXPECT_NE(err.find(k.expect), std::string::npos) << args << ": " << err;
    EXPECT_EQ(stdout_text().find("before:"), std::string::npos) << args;
    EXPECT_NE(std::system(("test -e " + dir_ + "/o.msh").c_str()), 0) << args;
  }
  // The right geometry is used: every vertex stays on it.
  std::string err;
  EXPECT_EQ(
      run("--input=" + sphere + " --output=" + dir_ + "/o.msh --geometry=sphere:2,2,0,3", &err), 0)
      << err;
  Mesh out;
  ASSERT_TRUE(read_mesh(dir_ + "/o.msh", &out).ok());
  EXPECT_LT(curved_meshes::sphere_drift(out, c, 3.0), 1e-9);
  EXPECT_EQ(run("--input=" + box + " --output=" + dir_ +
                    "/o.msh --geometry=plane:0,0,0,0,0,1 --boundary=slide",
                &err),
            0)
      << err;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// Issue 19, item 8: --help shows tmop's flags only (not glog's) and exits 0; --version names the
// version; a bad flag value is a usage error (2), not gflags' 1.
TEST_F(TmopOptimizeTool, HelpVersionAndBadFlagValues) {
  std::string err;
  EXPECT_EQ(run("--help", &err), 0) << err;
  const std::string help = slurp(dir_ + "/out.txt");
  EXPECT_NE(help.find("-recipe"), std::string::npos);
  EXPECT_EQ(help.find("logtostderr"), std::string::npos);
  EXPECT_EQ(help.find("flagfile"), std::string::npos);
  EXPECT_EQ(run("--version", &err), 0) << err;
  EXPECT_EQ(slurp(dir_ + "/out.txt").rfind("tmop_optimize 0.", 0), 0u);
  const std::string io = "--input=" + dir_ + "/grid.msh --output=" + dir_ + "/o.vtu ";
  for (const std::string& bad : {std::string("--threads=abc"), std::string("--power=x"),
                                 std::string("--verbose=maybe"), std::string("--max_iterations")}) {
    EXPECT_EQ(run(io + bad, &err), 2) << bad << ": " << err;
    EXPECT_EQ(lines(err), 1) << bad << ": " << err;
  }
  EXPECT_EQ(run(io + "--threads=abc", &err), 2);
  EXPECT_EQ(err, "tmop_optimize: bad value 'abc' for --threads (expected an integer)\n");
}

// Issue 19, item 1: a directory crashed the tool (std::length_error) as --input, --reference or
// --moved.
TEST_F(TmopOptimizeTool, DirectoryInputsAreOneLineExitTwo) {
  const std::string d = dir_ + "/d.msh";
  ASSERT_EQ(std::system(("mkdir " + d).c_str()), 0);
  const std::string in = "--input=" + dir_ + "/grid.msh --output=" + dir_ + "/o.vtu ";
  for (const std::string& args : {"--input=" + d + " --output=" + dir_ + "/o.vtu",
                                  in + "--reference=" + d, in + "--recipe=preserve --moved=" + d}) {
    std::string err;
    EXPECT_EQ(run(args, &err), 2) << args;
    EXPECT_EQ(err, d + ": not a regular file (a directory)\n") << args;
  }
}

// Issue 19, item 7: the report went through a fixed REPORT.tmp (a user's file of that name was
// clobbered); now a unique temporary, nothing left behind. run.before names its measure.
TEST_F(TmopOptimizeTool, ReportUsesTheAtomicWriterAndNamesItsMeasure) {
  const std::string report = dir_ + "/r.json";
  { std::ofstream(report + ".tmp") << "mine"; }
  std::string err;
  ASSERT_EQ(
      run("--input=" + dir_ + "/grid.msh --output=" + dir_ + "/o.vtu --report=" + report, &err), 0)
      << err;
  EXPECT_EQ(slurp(report + ".tmp"), "mine");
  const std::string json = slurp(report);
  const std::size_t before = json.find("\"before\": {\"min_quality\": ");
  ASSERT_NE(before, std::string::npos) << json.substr(0, 400);
  // In "before" itself, ahead of "after".
  EXPECT_LT(json.find("\"min_quality_measure\": \"sample_mean_ratio\"", before),
            json.find("\"after\"", before))
      << json.substr(before, 200);
  EXPECT_EQ(std::system(("ls -A " + dir_ + " | grep -q tmp-").c_str()) == 0, false);
}

// Issue 19, item 7: SIGINT / SIGTERM mid-run cancel the recipe at its next iteration: nothing
// written (no output, report or temporary file), one line on stderr, exit 130.
TEST_F(TmopOptimizeTool, SignalsMidRunExit130WithOneLineAndLeaveNothing) {
  // stdout is a pipe here: line-buffer it so "before:" arrives when printed.
  if (std::system("command -v stdbuf > /dev/null") != 0) GTEST_SKIP() << "no stdbuf";
  // 82,944 tets (a 24^3 Kuhn-split cube), interior vertices jittered by up to h/10 per
  // coordinate (none inverts; the tool would refuse the input): the shape stage runs for seconds.
  const int n = 24;
  Mesh m = testing_grid::grid(CellType::kTet4, n);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.1 / n, 0.1 / n);
  for (int v = 0; v < m.num_vertices(); ++v) {
    const int i = v % (n + 1), j = v / (n + 1) % (n + 1), k = v / ((n + 1) * (n + 1));
    if (i == 0 || j == 0 || k == 0 || i == n || j == n || k == n) continue;
    for (int a = 0; a < 3; ++a) m.vertex(v)[a] += u(rng);
  }
  ASSERT_TRUE(write_mesh(dir_ + "/big.msh", m).ok());
  for (int sig : {SIGINT, SIGTERM}) {
    const std::string out = dir_ + "/sig", errf = dir_ + "/sig_err.txt";
    ASSERT_EQ(std::system(("rm -rf " + out + " && mkdir " + out).c_str()), 0);
    int pipe_fd[2];
    ASSERT_EQ(pipe(pipe_fd), 0);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      dup2(pipe_fd[1], 1);
      const int e = open(errf.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0644);
      dup2(e, 2);
      close(pipe_fd[0]);
      const std::string input = "--input=" + dir_ + "/big.msh";
      const std::string output = "--output=" + out + "/o.vtu";
      const std::string report = "--report=" + out + "/r.json";
      execlp("stdbuf", "stdbuf", "-oL", tool_.c_str(), input.c_str(), output.c_str(),
             report.c_str(), "--recipe=shape", "--max_iterations=100000", "--function_tolerance=0",
             "--threads=1", static_cast<char*>(nullptr));
      _exit(99);
    }
    close(pipe_fd[1]);
    // The run has started once the input's quality line is printed.
    std::string seen;
    char buf[256];
    ssize_t n;
    while (seen.find("before:") == std::string::npos && (n = read(pipe_fd[0], buf, sizeof buf)) > 0)
      seen.append(buf, static_cast<std::size_t>(n));
    // Inside the shape solve (its setup takes well under a second on this mesh).
    usleep(1000 * 1000);
    const auto signalled = std::chrono::steady_clock::now();
    kill(pid, sig);
    while ((n = read(pipe_fd[0], buf, sizeof buf)) > 0)
      seen.append(buf, static_cast<std::size_t>(n));
    close(pipe_fd[0]);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    const double latency =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
    std::printf("cancel latency (%s): %.3f s\n", sig == SIGINT ? "SIGINT" : "SIGTERM", latency);
    EXPECT_LT(latency, 30.0);
    ASSERT_TRUE(WIFEXITED(status)) << seen;
    EXPECT_EQ(WEXITSTATUS(status), 130) << seen;
    // The recipe is cancelled at its next iteration: exactly one line, naming the signal and
    // the iteration; nothing written.
    const std::string err = slurp(errf);
    const std::string head = std::string("tmop_optimize: interrupted by ") +
                             (sig == SIGINT ? "SIGINT" : "SIGTERM") + " after shape iteration ";
    EXPECT_EQ(err.compare(0, head.size(), head), 0) << err;
    const std::string tail = "; nothing written\n";
    ASSERT_GE(err.size(), tail.size()) << err;
    EXPECT_EQ(err.substr(err.size() - tail.size()), tail) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(std::system(("test -z \"$(ls -A " + out + ")\"").c_str()), 0);
  }
}

}  // namespace
}  // namespace tmop
