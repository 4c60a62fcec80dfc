// tmop/io/isolated_read.h
// The isolated read: a reader that hands file bytes to libhdf5 (libcgns always; libexodusii for
// netCDF-4 files) runs in a forked child process, so that a crash inside libhdf5 on a damaged
// file (docs/fuzzing.md: libhdf5 1.10.8 frees an invalid pointer in nc_open on a crafted
// netCDF-4 file) becomes a one-line error instead of ending the program. Internal to io/;
// read_mesh uses it when set_isolated_hdf5_reads(true) (mesh_io.h) and MPI is not in use.
//
// read_isolated(path, read, kind, mesh): fork (POSIX); the child resets its signal handlers and
//   mask to the defaults (a signal ends it; the parent's handlers, which remove the parent's
//   temporary files, never run there), asks to be killed when the parent dies (Linux:
//   PR_SET_PDEATHSIG), sends its stdout and stderr to /dev/null (libexodusii's and libhdf5's own
//   diagnostics: the parent reports one line), calls read(path, &m), sends m or the exception
//   through a pipe (mesh_pipe.h) and leaves with _exit (no atexit handlers, no stdio flush, no
//   destructors: nothing is written twice, no file is written). The parent receives the mesh into
//   *mesh while the child sends it (no size cap but memory), then reaps the child (waitpid,
//   EINTR-safe; on an exception in the parent the child is killed and reaped: no zombie) and:
//   - rethrows the child's tmop::Error (same message), std::bad_alloc, or any other
//     std::exception as std::runtime_error(what) (what a direct read would have thrown);
//   - child over its CPU-time limit (set_isolated_read_cpu_limit; libhdf5 loops forever on some
//     damaged files): Error "PATH: the HDF5 library did not finish reading this file in N s of
//     CPU time (the reading process was stopped); the file is damaged or not a valid KIND file";
//   - child ended by SIGSEGV, SIGABRT, ... : Error "PATH: the HDF5 library crashed reading this
//     file (SIGABRT, signal 6); the file is damaged or not a valid KIND file";
//     by SIGINT, SIGTERM, SIGHUP, SIGQUIT: "PATH: reading was interrupted (SIGINT)";
//     by SIGKILL: "PATH: the reading process was killed (SIGKILL; out of memory?)";
//   - child exited with a status other than 0 (ASan ends a process that way): "PATH: the HDF5
//     library failed reading this file (the reading process exited with status N); ...";
//   - truncated or damaged stream: "PATH: the reading process sent damaged data: WHAT".
//   fork or pipe failing: Error "PATH: cannot start the reading process (REASON)".
//   Cost: one fork of the caller (copy-on-write page tables) and one copy of the mesh through
//   the pipe (docs/formats.md, "Process isolation", has the measurement).
//   The child never writes a core file (RLIMIT_CORE 0).
// set_isolated_read_cpu_limit(base, per_mb): the child's CPU-time limit is base + per_mb x the
//   file's size in MB, rounded up to whole seconds (RLIMIT_CPU; default 20 s + 1 s/MB, far above
//   what a valid file needs: docs/formats.md, "Process isolation"). The fuzz target sets 2 s.
// has_hdf5_signature(path): the file starts with "\x89HDF\r\n\x1a\n" (netCDF-4, CGNS).
// set_isolated_read_child_hook(hook): tests and the fuzz target only: hook(fd) runs in the child
//   right after fork, before the read (fd is the pipe to the parent). nullptr: none. For the
//   tools' tests the environment variable TMOP_ISOLATED_READ_TEST does the same: "signal N"
//   raises signal N in the child, "sleep PIDFILE" writes the child's pid there and sleeps.
#ifndef TMOP_IO_ISOLATED_READ_H_
#define TMOP_IO_ISOLATED_READ_H_

#include <string>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

using MeshReader = void (*)(const std::string& path, Mesh* mesh);

void read_isolated(const std::string& path, MeshReader read, const char* kind, Mesh* mesh);

bool has_hdf5_signature(const std::string& path);

void set_isolated_read_child_hook(void (*hook)(int fd));

void set_isolated_read_cpu_limit(double base_seconds, double seconds_per_megabyte);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_ISOLATED_READ_H_
