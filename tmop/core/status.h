// tmop/core/status.h
// Status: the result of an operation the user can make fail (a bad file, an impossible request).
// Programmer errors are CHECKs; user errors are a Status with a one-line message that names the
// place ("mesh.msh:17: node index 12 out of range 1..10").
//
// Error: the exception library internals throw to unwind a parser or a solve quickly; public
// functions that return Status catch it at their boundary, so callers see no exceptions unless
// a function's header says so.
#ifndef TMOP_CORE_STATUS_H_
#define TMOP_CORE_STATUS_H_

#include <stdexcept>
#include <string>
#include <utility>

namespace tmop {

class Status {
 public:
  Status() = default;  // OK
  static Status Ok() { return Status(); }
  static Status Failure(std::string message) { return Status(std::move(message)); }
  // A run stopped on request (a progress callback returned false, a cancel flag was raised): not
  // ok(), and cancelled() tells it from a failure. The caller's data is in a valid state.
  static Status Cancelled(std::string message) {
    Status s(std::move(message));
    s.cancelled_ = true;
    return s;
  }

  bool ok() const { return !failed_; }
  bool cancelled() const { return cancelled_; }
  explicit operator bool() const { return ok(); }
  // One line, no trailing newline; empty when ok().
  const std::string& message() const { return message_; }

 private:
  explicit Status(std::string message) : failed_(true), message_(std::move(message)) {}
  bool failed_ = false;
  bool cancelled_ = false;
  std::string message_;
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace tmop

#endif  // TMOP_CORE_STATUS_H_
