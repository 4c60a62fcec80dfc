// tests/recipes/run_command.h: runs a shell command for the tests that drive the tools.
#ifndef TMOP_TESTS_RECIPES_RUN_COMMAND_H_
#define TMOP_TESTS_RECIPES_RUN_COMMAND_H_

#include <stdio.h>
#include <sys/wait.h>

#include <string>

namespace tmop {
namespace testing_recipes {

// Runs `cmd` with stderr joined to stdout, appends what it printed to *out; its exit status, -1
// when it could not run or did not exit.
inline int run_command(const std::string& cmd, std::string* out) {
  FILE* p = popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out->append(buf, n);
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace testing_recipes
}  // namespace tmop

#endif  // TMOP_TESTS_RECIPES_RUN_COMMAND_H_
