// The one atomic writer (tmop/io/atomic_file.h): unique temporary names next to the output,
// nothing left behind on failure, and on SIGINT / SIGTERM the registered temporary files are
// removed, one line is printed and the process exits 130.
#include "tmop/io/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_util.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace {

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n != "." && n != "..") names.push_back(n);
    }
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

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporaries) {
  const std::string dir = test::temp_dir();
  ASSERT_TRUE(write_file_atomically(dir + "/r.json", "one\n").ok());
  ASSERT_TRUE(write_file_atomically(dir + "/r.json", "two\n").ok());
  EXPECT_EQ(slurp(dir + "/r.json"), "two\n");
  // A user's file named like the old fixed temporary is not touched.
  std::ofstream(dir + "/r.json.tmp") << "mine";
  ASSERT_TRUE(write_file_atomically(dir + "/r.json", "three\n").ok());
  EXPECT_EQ(slurp(dir + "/r.json.tmp"), "mine");
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"r.json", "r.json.tmp"}));
}

TEST(AtomicFile, FailuresLeaveNothingAndSayWhy) {
  const std::string dir = test::temp_dir();
  Status s = write_file_atomically(dir + "/missing/r.json", "x");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message().rfind(dir + "/missing/r.json: cannot create a temporary file", 0), 0u)
      << s.message();
  ASSERT_EQ(mkdir((dir + "/sub").c_str(), 0755), 0);
  s = write_file_atomically(dir + "/sub", "x");  // rename over a directory fails
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"sub"}));
  EXPECT_TRUE(list_dir(dir + "/sub").empty());
}

TEST(AtomicFile, TemporaryNamesAreUniqueAndRemovedUnlessCommitted) {
  const std::string dir = test::temp_dir();
  {
    TempFile a(dir + "/out.ply", "ply"), b(dir + "/out.ply", "ply");
    EXPECT_NE(a.name(), b.name());
    EXPECT_EQ(a.name().rfind(dir + "/.out.ply.tmp-", 0), 0u) << a.name();
    EXPECT_EQ(a.name().substr(a.name().size() - 4), ".ply");
    a.write("abc");
    a.commit();
  }
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"out.ply"}));
  EXPECT_EQ(slurp(dir + "/out.ply"), "abc");
}

// In a child: the handler is installed, a temporary file is half written, the signal comes.
void expect_signal_cleans_up(int sig, const char* line) {
  const std::string dir = test::temp_dir();
  const std::string err = dir + "/stderr.txt";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0644);
    ::dup2(fd, 2);
    remove_temporaries_on_signal("child");
    TempFile t(dir + "/mesh.vtu", "");
    t.write("<VTKFile half written");
    TempFile u(dir + "/report.json", "");
    ::raise(sig);
    ::_exit(3);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(slurp(err), line);
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"stderr.txt"}));
}

TEST(AtomicFile, SigintAndSigtermRemoveTemporariesAndExit130) {
  expect_signal_cleans_up(SIGINT, "child: interrupted by SIGINT; no partial output left\n");
  expect_signal_cleans_up(SIGTERM, "child: interrupted by SIGTERM; no partial output left\n");
}

// cancel_on_signal: the first signal only raises the flag (the process goes on, the temporary file
// stays), a second one takes the immediate path; after stop_cancelling_on_signal the first one
// does (an output being written is removed, nothing renamed into place).
void expect_cancel_then_exit(int sig, bool stop_first) {
  const std::string dir = test::temp_dir();
  const std::string err = dir + "/stderr.txt";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_CREAT | O_WRONLY | O_TRUNC, 0644);
    ::dup2(fd, 2);
    const std::atomic<bool>* cancel = cancel_on_signal("child");
    TempFile t(dir + "/mesh.vtu", "");
    t.write("<VTKFile half written");
    if (stop_first) {
      if (stop_cancelling_on_signal()) ::_exit(4);  // no signal came yet
    } else {
      ::kill(::getpid(), sig);  // process-directed, as a user's signal: taken by the signal thread
      for (int i = 0; i < 5000 && !cancel->load(); ++i) ::usleep(1000);
      if (!cancel->load() || cancel_signal() != sig) ::_exit(5);
      if (list_dir(dir).size() != 2) ::_exit(6);  // the temporary file is still there
    }
    ::kill(::getpid(), sig);
    ::sleep(5);
    ::_exit(3);  // not reached: the signal thread exits the process
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_EQ(slurp(err), std::string("child: interrupted by ") +
                            (sig == SIGINT ? "SIGINT" : "SIGTERM") + "; no partial output left\n");
  EXPECT_EQ(list_dir(dir), (std::vector<std::string>{"stderr.txt"}));
}

TEST(AtomicFile, CancelOnSignalRaisesTheFlagThenASecondSignalExits) {
  for (int sig : {SIGINT, SIGTERM}) {
    expect_cancel_then_exit(sig, false);
    expect_cancel_then_exit(sig, true);
  }
}

}  // namespace
}  // namespace tmop
