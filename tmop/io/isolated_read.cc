// tmop/io/isolated_read.cc
// fork / pipe / waitpid around a reader that calls libhdf5 (isolated_read.h), and the switch
// set_isolated_hdf5_reads of mesh_io.h.
#include "tmop/io/isolated_read.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>

#include "tmop/core/status.h"
#include "tmop/io/atomic_file.h"
#include "tmop/io/mesh_io.h"
#include "tmop/io/mesh_pipe.h"

// Present only when the program links an MPI library (weak: tmop_io does not depend on MPI).
extern "C" int MPI_Initialized(int* flag) __attribute__((weak));

namespace tmop {
namespace {

std::atomic<bool> g_isolated{false};
std::atomic<void (*)(int)> g_child_hook{nullptr};
std::atomic<double> g_cpu_base{20.0};
std::atomic<double> g_cpu_per_mb{1.0};

// The child's CPU-time limit for reading PATH, in whole seconds (isolated_read.h).
long cpu_limit_seconds(const std::string& path) {
  struct stat st;
  const double mb = ::stat(path.c_str(), &st) == 0 ? static_cast<double>(st.st_size) / 1e6 : 0.0;
  const double limit = g_cpu_base.load() + g_cpu_per_mb.load() * mb;
  return limit >= 1e9 ? 1000000000L : std::max(1L, static_cast<long>(std::ceil(limit)));
}

// OpenMPI (and others) do not support fork in an MPI process: isolation is off under mpirun
// (its rank variables, as MpiSession checks) and once the program has initialised MPI.
bool mpi_in_use() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v) != nullptr) return true;
  int initialized = 0;
  if (MPI_Initialized != nullptr && MPI_Initialized(&initialized) == 0 && initialized) return true;
  return false;
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV";
    case SIGABRT:
      return "SIGABRT";
    case SIGBUS:
      return "SIGBUS";
    case SIGFPE:
      return "SIGFPE";
    case SIGILL:
      return "SIGILL";
    case SIGKILL:
      return "SIGKILL";
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    case SIGQUIT:
      return "SIGQUIT";
    case SIGPIPE:
      return "SIGPIPE";
    case SIGXCPU:
      return "SIGXCPU";
    default:
      return "a signal";
  }
}

std::string signal_message(const std::string& path, const char* kind, int sig) {
  const std::string name = signal_name(sig);
  if (sig == SIGXCPU)
    return path + ": the HDF5 library did not finish reading this file in " +
           std::to_string(cpu_limit_seconds(path)) +
           " s of CPU time (the reading process was stopped); the file is damaged or not a "
           "valid " +
           kind + " file";
  if (sig == SIGINT || sig == SIGTERM || sig == SIGHUP || sig == SIGQUIT)
    return path + ": reading was interrupted (" + name + ")";
  if (sig == SIGKILL)
    return path + ": the reading process was killed (SIGKILL; out of memory, or from outside)";
  return path + ": the HDF5 library crashed reading this file (" + name + ", signal " +
         std::to_string(sig) + "); the file is damaged or not a valid " + kind + " file";
}

// The tools' tests (tests/quality/tmop_quality_tool_test.cc) reach the child through the
// environment: TMOP_ISOLATED_READ_TEST="signal N" raises signal N in the child before it reads,
// "sleep PIDFILE" writes the child's pid to PIDFILE and sleeps (to signal the tool meanwhile).
void test_hook_from_environment() {
  const char* test = std::getenv("TMOP_ISOLATED_READ_TEST");
  if (!test) return;
  int sig = 0;
  char file[256] = {0};
  if (std::sscanf(test, "signal %d", &sig) == 1) ::raise(sig);
  if (std::sscanf(test, "sleep %255s", file) == 1) {
    if (FILE* f = std::fopen(file, "w")) {
      std::fprintf(f, "%d\n", static_cast<int>(::getpid()));
      std::fclose(f);
    }
    for (int i = 0; i < 600; ++i) ::sleep(1);
  }
}

// The child: defaults for every signal, parse, send, _exit. Never returns.
[[noreturn]] void child_main(int fd, pid_t parent, const std::string& path, io::MeshReader read,
                             long cpu_seconds) {
  for (int sig = 1; sig < NSIG; ++sig)
    if (sig != SIGKILL && sig != SIGSTOP) ::signal(sig, SIG_DFL);
  ::signal(SIGPIPE, SIG_IGN);  // a parent gone: the write fails and the child ends
  sigset_t none;
  sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);  // cancel_on_signal's mask is inherited
#ifdef __linux__
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(4);  // the parent died before the prctl
#else
  (void)parent;
#endif
  // libexodusii and libhdf5 print diagnostics of their own on a damaged file; the parent reports
  // one line, so the child's stdout and stderr go to /dev/null.
  const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
  if (null >= 0) {
    ::dup2(null, 1);
    ::dup2(null, 2);
  }
  // libhdf5 loops forever on some damaged files (tests/fuzz/regressions/exo/hdf5_hang.exo): a
  // CPU-time limit ends such a read with SIGXCPU (SIGKILL a second later). No core file: a
  // crash of the child must not leave one in the user's directory.
  const struct rlimit cpu = {static_cast<rlim_t>(cpu_seconds),
                             static_cast<rlim_t>(cpu_seconds + 1)};
  ::setrlimit(RLIMIT_CPU, &cpu);
  const struct rlimit core = {0, 0};
  ::setrlimit(RLIMIT_CORE, &core);
  if (void (*hook)(int) = g_child_hook.load()) hook(fd);
  test_hook_from_environment();
  bool sent = false;
  try {
    Mesh* mesh = new Mesh;  // never freed: _exit ends the process
    read(path, mesh);
    sent = io::send_mesh(fd, *mesh);
  } catch (const Error& e) {
    sent = io::send_message(fd, 'E', e.what());
  } catch (const std::bad_alloc&) {
    sent = io::send_message(fd, 'A', "");
  } catch (const std::exception& e) {
    sent = io::send_message(fd, 'X', e.what());
  }
  ::_exit(sent ? 0 : 3);
}

// Owns the child until it is reaped: an exception in the parent kills and reaps it.
class Child {
 public:
  Child(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
  ~Child() {
    close_fd();
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    reap();
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  int fd() const { return fd_; }
  void kill() { ::kill(pid_, SIGKILL); }
  void close_fd() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  int reap() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_;
  int fd_;
};

}  // namespace

void set_isolated_hdf5_reads(bool on) { g_isolated.store(on); }

bool isolated_hdf5_reads() { return g_isolated.load() && !mpi_in_use(); }

namespace io {

void set_isolated_read_child_hook(void (*hook)(int fd)) { g_child_hook.store(hook); }

void set_isolated_read_cpu_limit(double base_seconds, double seconds_per_megabyte) {
  g_cpu_base.store(base_seconds);
  g_cpu_per_mb.store(seconds_per_megabyte);
}

bool has_hdf5_signature(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  char head[8] = {0};
  ssize_t n = 0;
  while ((n = ::read(fd, head, sizeof head)) < 0 && errno == EINTR) {
  }
  ::close(fd);
  return n == 8 && std::memcmp(head, "\x89HDF\r\n\x1a\n", 8) == 0;
}

void read_isolated(const std::string& path, MeshReader read, const char* kind, Mesh* mesh) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw Error(path + ": cannot start the reading process (" + std::strerror(errno) + ")");
  const long cpu_seconds = cpu_limit_seconds(path);
  std::fflush(nullptr);  // nothing the caller buffered is written twice
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(path + ": cannot start the reading process (" + std::strerror(e) + ")");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], parent, path, read, cpu_seconds);
  }
  ::close(fds[1]);
  Child child(pid, fds[0]);
  std::string message, damaged;
  char got = 0;
  // A tool's cancel_on_signal flag (atomic_file.h) raised while the child reads: stop waiting.
  const auto cancelled = [] { return cancel_signal() != 0; };
  try {
    got = receive_mesh(child.fd(), mesh, &message, cancelled);
  } catch (const Error& e) {
    damaged = e.what();
  }
  child.close_fd();
  if (damaged == "interrupted") {
    child.kill();
    child.reap();
    mesh->clear();
    throw Error(signal_message(path, kind, cancel_signal()));
  }
  const int status = child.reap();
  if (WIFSIGNALED(status) || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || !damaged.empty())
    mesh->clear();
  if (WIFSIGNALED(status)) throw Error(signal_message(path, kind, WTERMSIG(status)));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw Error(path +
                ": the HDF5 library failed reading this file (the reading process exited "
                "with status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                "); the file is damaged or not a valid " + kind + " file");
  if (!damaged.empty()) throw Error(path + ": the reading process sent " + damaged);
  if (got == 'E') throw Error(message);
  if (got == 'A') throw std::bad_alloc();
  if (got == 'X') throw std::runtime_error(message);
}

}  // namespace io
}  // namespace tmop
