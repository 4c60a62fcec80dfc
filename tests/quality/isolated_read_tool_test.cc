// The tools with the isolated read of HDF5-based files (tmop/io/isolated_read.h), run as users run
// them: a crash in the reading child is one line and exit 2 with no output written, the libhdf5
// finding of docs/fuzzing.md is one line, and SIGINT to the tool (alone, or to its process group
// as Ctrl-C sends it) ends both processes. The child is reached through TMOP_ISOLATED_READ_TEST.
// Skipped when the tools or CGNS are not built.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include "tests/temp_dir.h"

namespace {

const std::string kBin = std::string(TMOP_BINARY_DIR) + "/tools/";
const std::string kCgns = std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/corpus/cgns/box_a.cgns";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs TOOL ARGS with TMOP_ISOLATED_READ_TEST=test, stderr to err; in its own process group.
pid_t start(const std::string& tool, const std::vector<std::string>& args, const std::string& test,
            const std::string& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    if (!test.empty()) ::setenv("TMOP_ISOLATED_READ_TEST", test.c_str(), 1);
    if (!std::freopen(err.c_str(), "w", stderr) || !std::freopen("/dev/null", "w", stdout))
      ::_exit(99);
    std::vector<char*> argv{const_cast<char*>(tool.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(tool.c_str(), argv.data());
    ::_exit(98);
  }
  return pid;
}

int finish(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

// Gone, or a zombie of a reaper that is not ours (the tool, its parent, is dead).
bool ended(pid_t pid) {
  for (int i = 0; i < 100; ++i) {
    const std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
    const std::size_t paren = stat.rfind(')');
    if (stat.empty() ||
        (paren != std::string::npos && stat.size() > paren + 2 && stat[paren + 2] == 'Z'))
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  return false;
}

class IsolatedReadTool : public ::testing::Test {
 protected:
  void SetUp() override {
    if (::access((kBin + "tmop_quality").c_str(), X_OK) != 0) GTEST_SKIP() << "tools not built";
    dir_ = tmop::testing_tmp::dir();
    const pid_t p = start(kBin + "tmop_quality", {"--input=" + kCgns}, "", dir_ + "probe.err");
    if (finish(p) != 0) GTEST_SKIP() << "no CGNS support: " << slurp(dir_ + "probe.err");
  }
  std::string dir_;
};

TEST_F(IsolatedReadTool, ACrashInTheReaderIsOneLineAndExitTwo) {
  const std::string err = dir_ + "crash.err", out = dir_ + "crash_out.vtu";
  const pid_t p =
      start(kBin + "tmop_quality", {"--input=" + kCgns, "--output=" + out}, "signal 11", err);
  EXPECT_EQ(finish(p), 2);
  EXPECT_EQ(slurp(err), kCgns +
                            ": the HDF5 library crashed reading this file (SIGSEGV, signal 11); "
                            "the file is damaged or not a valid CGNS file\n");
  EXPECT_NE(::access(out.c_str(), F_OK), 0);  // nothing written
}

TEST_F(IsolatedReadTool, TheLibhdf5FindingIsOneLine) {
  const std::string f =
      std::string(TMOP_SOURCE_DIR) + "/tests/fuzz/regressions/exo/hdf5_invalid_free.exo";
  const std::string err = dir_ + "finding.err";
  EXPECT_EQ(finish(start(kBin + "tmop_quality", {"--input=" + f}, "", err)), 2);
  const std::string e = slurp(err);
  EXPECT_EQ(e.rfind(f + ": ", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), e.size() - 1) << e;  // one line, libexodusii's own text not shown
}

// SIGINT while the child reads: to the tool alone (kill PID) or to the group (Ctrl-C).
void interrupt(const std::string& dir, const std::string& tool, bool group,
               const std::string& want) {
  const std::string pidfile = dir + "child.pid", err = dir + "int.err";
  std::remove(pidfile.c_str());
  std::vector<std::string> args{"--input=" + kCgns};
  if (tool == "tmop_optimize") args.push_back("--output=" + dir + "int_out.vtu");
  const pid_t p = start(kBin + tool, args, "sleep " + pidfile, err);
  pid_t child = 0;
  for (int i = 0; i < 500 && child == 0; ++i) {
    child = std::atoi(slurp(pidfile).c_str());
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_GT(child, 0) << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the tool waits in the read
  ::kill(group ? -p : p, SIGINT);
  EXPECT_EQ(finish(p), 130) << tool << (group ? " group" : "");
  EXPECT_EQ(slurp(err), want) << tool << (group ? " group" : "");
  EXPECT_TRUE(ended(child)) << tool << (group ? " group" : "");
  EXPECT_NE(::access((dir + "int_out.vtu").c_str(), F_OK), 0);
}

TEST_F(IsolatedReadTool, SigintEndsTheToolAndTheReadingProcess) {
  for (bool group : {false, true}) {
    interrupt(dir_, "tmop_quality", group,
              "tmop_quality: interrupted by SIGINT; no partial output left\n");
    interrupt(dir_, "tmop_optimize", group,
              "tmop_optimize: interrupted by SIGINT while reading the input; nothing written\n");
  }
}

}  // namespace
