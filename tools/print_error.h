// tools/print_error.h
// How every tool reports a failure: one newline-terminated line on stderr. A message that already
// starts with the name of a file the tool was given ("FILE:LINE: what", "FILE:byte N: what",
// "FILE: what", as read_mesh and write_mesh locate their errors) is printed as it is, so editors
// and scripts can jump to the place and every tool prints the same line for the same bad file;
// any other message (usage errors) gets the program name: "tmop_quality: --input is required".
// Header-only: every tool includes it.
#ifndef TMOP_TOOLS_PRINT_ERROR_H_
#define TMOP_TOOLS_PRINT_ERROR_H_

#include <cstdio>
#include <string>
#include <vector>

namespace tmop_tools {

inline void print_error(const char* program, const std::string& message,
                        const std::vector<std::string>& files) {
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  while (!line.empty() && line.back() == ' ') line.pop_back();
  bool named = false;
  for (const std::string& f : files)
    named |= !f.empty() && line.size() > f.size() && line.compare(0, f.size(), f) == 0 &&
             line[f.size()] == ':';
  if (named)
    std::fprintf(stderr, "%s\n", line.c_str());
  else
    std::fprintf(stderr, "%s: %s\n", program, line.c_str());
}

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_PRINT_ERROR_H_
