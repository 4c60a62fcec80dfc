// tmop/io/atomic_file.cc
// Atomic output files and the registry of temporary files the signal handler removes.
#include "tmop/io/atomic_file.h"

#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <thread>

namespace tmop {
namespace {

// Registered temporary paths. A slot's path is written only while the slot is claimed
// (kWriting) and read by the handler only when it is kLive, so the handler never reads a half
// written path; buffers are static, so nothing it reads is ever freed.
constexpr int kSlots = 32;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kWriting = 1, kLive = 2 };
std::atomic<int> g_state[kSlots];
char g_path[kSlots][kMaxPath];
char g_program[64] = "tmop";

int register_path(const std::string& path) {
  if (path.size() + 1 > kMaxPath) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (g_state[i].compare_exchange_strong(expected, kWriting)) {
      std::memcpy(g_path[i], path.c_str(), path.size() + 1);
      g_state[i].store(kLive);
      return i;
    }
  }
  return -1;  // more than kSlots files at once: not removed on a signal (never happens in tmop)
}

void unregister_path(int slot) {
  if (slot >= 0) g_state[slot].store(kFree);
}

void write_all(int fd, const char* s) {
  std::size_t n = std::strlen(s);
  while (n > 0) {
    const ssize_t w = ::write(fd, s, n);
    if (w <= 0) return;
    s += w;
    n -= static_cast<std::size_t>(w);
  }
}

// cancel_on_signal: the first signal only raises g_cancel (and records which signal came);
// a second one, or any signal once g_immediate is set, takes the immediate path on_signal.
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler stores to lock-free atomics only");
std::atomic<bool> g_cancel{false};
std::atomic<int> g_cancel_signal{0};
std::atomic<bool> g_immediate{true};

extern "C" void on_signal(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (g_state[i].load() == kLive) ::unlink(g_path[i]);
  write_all(2, g_program);
  write_all(2, sig == SIGINT ? ": interrupted by SIGINT" : ": interrupted by SIGTERM");
  write_all(2, "; no partial output left\n");
  ::_exit(130);
}

// cancel_on_signal's thread: SIGINT and SIGTERM are blocked in every thread and taken here
// synchronously by sigwait, so no library's own handler (METIS installs one for SIGTERM around
// its calls and fails the call) ever sees them.
void wait_for_signals(sigset_t set) {
  for (;;) {
    int sig = 0;
    if (::sigwait(&set, &sig) != 0) continue;
    if (g_immediate.load() || g_cancel.load()) on_signal(sig);
    g_cancel_signal.store(sig);
    g_cancel.store(true);
  }
}

void install(void (*handler)(int)) {
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = handler;
  sigfillset(&sa.sa_mask);  // the handler runs once, not interrupted by the other signal
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
}

std::string directory_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

void remove_temporaries_on_signal(const char* program) {
  std::snprintf(g_program, sizeof g_program, "%s", program);
  g_immediate.store(true);
  install(on_signal);
}

const std::atomic<bool>* cancel_on_signal(const char* program) {
  std::snprintf(g_program, sizeof g_program, "%s", program);
  g_immediate.store(false);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  ::pthread_sigmask(SIG_BLOCK, &set, nullptr);  // threads created later inherit the mask
  std::thread(wait_for_signals, set).detach();
  return &g_cancel;
}

int cancel_signal() { return g_cancel_signal.load(); }

bool stop_cancelling_on_signal() {
  g_immediate.store(true);
  return g_cancel.load();
}

TempFile::TempFile(const std::string& path, const std::string& suffix) : path_(path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = directory_of(path);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string ext = suffix.empty() ? "" : "." + suffix;
  tmp_ = dir + "/." + base + ".tmp-XXXXXX" + ext;
  // SIGINT and SIGTERM wait while the file is created and registered, so none can come between.
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  ::pthread_sigmask(SIG_BLOCK, &block, &old);
  fd_ = ::mkstemps(&tmp_[0], static_cast<int>(ext.size()));
  const int error = errno;
  if (fd_ >= 0) slot_ = register_path(tmp_);
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (fd_ < 0)
    throw Error(path + ": cannot create a temporary file in " + dir + " (" + std::strerror(error) +
                ")");
  // mkstemps creates the file 0600; an output file gets the usual 0666 minus the umask.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::fchmod(fd_, 0666 & ~mask);
}

TempFile::~TempFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) ::unlink(tmp_.c_str());
  unregister_path(slot_);
}

void TempFile::write(std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error(path_ + ": write error (" + (n < 0 ? std::strerror(errno) : "disk full?") + ")");
    done += static_cast<std::size_t>(n);
  }
}

void TempFile::close_fd() {
  if (fd_ < 0) return;
  const int r = ::close(fd_);
  fd_ = -1;
  if (r != 0) throw Error(path_ + ": write error (" + std::strerror(errno) + ")");
}

void TempFile::commit() {
  close_fd();
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw Error(path_ + ": cannot write (rename of the temporary file failed: " +
                std::strerror(errno) + ")");
  committed_ = true;
}

Status write_file_atomically(const std::string& path, std::string_view bytes) {
  try {
    TempFile tmp(path, "");
    tmp.write(bytes);
    tmp.commit();
  } catch (const Error& e) {
    return Status::Failure(e.what());
  } catch (const std::bad_alloc&) {
    return Status::Failure(path + ": out of memory while writing");
  }
  return Status::Ok();
}

}  // namespace tmop
