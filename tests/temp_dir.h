// A scratch directory private to this test process, so that tests ctest runs in parallel never
// share a file: ::testing::TempDir() is one directory for all of them, and two tests writing
// "tool.err" there raced (a CI failure). Created on first use, removed when the process exits.
#ifndef TMOP_TESTS_TEMP_DIR_H_
#define TMOP_TESTS_TEMP_DIR_H_

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tmop {
namespace testing_tmp {

// The directory, with a trailing '/'; empty if it cannot be created.
inline const std::string& dir() {
  static const std::string path = [] {
    std::string templ = std::filesystem::temp_directory_path().string() + "/tmop_test_XXXXXX";
    if (mkdtemp(templ.data()) == nullptr) return std::string();
    static std::string to_remove;
    to_remove = templ;
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(to_remove, ignored);
    });
    return templ + "/";
  }();
  return path;
}

}  // namespace testing_tmp
}  // namespace tmop

#endif  // TMOP_TESTS_TEMP_DIR_H_
