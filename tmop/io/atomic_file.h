// tmop/io/atomic_file.h
// The one way tmop writes an output file: a temporary file with a unique name (mkstemps) in the
// output's directory, filled, then renamed over the output. OUT either holds the complete new
// file or is untouched; on failure the temporary file is removed. While a temporary file exists
// it is registered, so remove_temporaries_on_signal's handler can delete it when SIGINT or
// SIGTERM ends the program mid-write: nothing partial is left anywhere. cancel_on_signal turns
// the first signal into a cancel flag for a long run (tmop_optimize) instead.
//
//   write_file_atomically: the whole content at once (meshes, reports, SVG pictures).
//   TempFile: for writers that need a path of their own (OpenMesh picks its format by the
//     temporary file's extension); commit() renames it over the output.
#ifndef TMOP_IO_ATOMIC_FILE_H_
#define TMOP_IO_ATOMIC_FILE_H_

#include <atomic>
#include <string>
#include <string_view>

#include "tmop/core/status.h"

namespace tmop {

// Status "PATH: cannot write ... (reason)" on failure; the previous file at path is untouched.
Status write_file_atomically(const std::string& path, std::string_view bytes);

// Installs SIGINT and SIGTERM handlers (async-signal-safe): they remove every registered
// temporary file, print "PROGRAM: interrupted by SIGINT; no partial output left" on stderr and
// end the process with exit code 130. `program` is copied (at most 63 characters).
void remove_temporaries_on_signal(const char* program);

// For a long run that cancels cleanly; call it before any thread is started: blocks SIGINT and
// SIGTERM (every later thread inherits the mask) and takes them in a thread of its own (sigwait,
// so no other handler, e.g. METIS's, sees them). The first signal only raises the returned flag
// (a lock-free atomic), to be passed as
// RecipeOptions::cancel; the caller then stops, writes nothing and reports the signal
// (cancel_signal()). A second signal while cancelling takes remove_temporaries_on_signal's
// immediate path (temporaries removed, one line, exit 130).
const std::atomic<bool>* cancel_on_signal(const char* program);
// The signal that raised cancel_on_signal's flag (SIGINT or SIGTERM), 0 when none came.
int cancel_signal();
// Before writing outputs: from now on a signal takes the immediate path (the temporary file
// being written is removed, nothing is renamed into place). Returns whether the flag was raised
// before the switch: the caller then writes nothing.
bool stop_cancelling_on_signal();

class TempFile {
 public:
  // Creates ".BASE.tmp-XXXXXX.SUFFIX" next to path (suffix without the dot, may be empty),
  // mode 0666 minus the umask. Throws Error("PATH: cannot create a temporary file in DIR").
  TempFile(const std::string& path, const std::string& suffix);
  ~TempFile();  // removes the temporary file unless commit() succeeded
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& name() const { return tmp_; }
  int fd() const { return fd_; }
  // Writes all bytes to fd(); throws Error("PATH: write error (...)").
  void write(std::string_view bytes);
  void close_fd();  // closes fd() (OpenMesh then writes by name); throws on a close error
  // Closes fd() if open and renames the temporary file over the output; throws Error on failure
  // (the temporary file is then removed by the destructor).
  void commit();

 private:
  std::string path_, tmp_;
  int fd_ = -1;
  int slot_ = -1;  // registration for the signal handler
  bool committed_ = false;
};

}  // namespace tmop

#endif  // TMOP_IO_ATOMIC_FILE_H_
