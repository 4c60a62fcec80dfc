// tools/parse_flags.h
// gflags parsing with the tools' exit-code contract: an unknown flag is a usage error, so it
// exits 2 with one line on stderr (gflags itself would exit 1), before gflags sees the
// arguments. Header-only: every tool includes it.
#ifndef TMOP_TOOLS_PARSE_FLAGS_H_
#define TMOP_TOOLS_PARSE_FLAGS_H_

#include <gflags/gflags.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace tmop_tools {

inline void parse_flags(int* argc, char*** argv) {
  for (int i = 1; i < *argc; ++i) {
    const char* a = (*argv)[i];
    if (std::strcmp(a, "--") == 0) break;  // the rest are positional
    if (a[0] != '-' || a[1] == '\0') continue;
    std::string name(a + (a[1] == '-' ? 2 : 1));
    name = name.substr(0, name.find('='));
    gflags::CommandLineFlagInfo info;
    if (gflags::GetCommandLineFlagInfo(name.c_str(), &info)) continue;
    // --noNAME sets a bool flag to false.
    if (name.compare(0, 2, "no") == 0 &&
        gflags::GetCommandLineFlagInfo(name.substr(2).c_str(), &info) && info.type == "bool")
      continue;
    const char* slash = std::strrchr((*argv)[0], '/');  // the program's name, as other errors
    std::fprintf(stderr, "%s: unknown flag %s (see --help)\n", slash ? slash + 1 : (*argv)[0], a);
    std::exit(2);
  }
  gflags::ParseCommandLineFlags(argc, argv, true);
}

}  // namespace tmop_tools

#endif  // TMOP_TOOLS_PARSE_FLAGS_H_
