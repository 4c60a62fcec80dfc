// read_node_list (the --fixed_nodes file): indices, comments, and one printable error line.
#include "tmop/io/node_list.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "io_test_util.h"

namespace tmop {
namespace {

std::string write_text(const std::string& name, const std::string& text) {
  const std::string path = test::temp_dir() + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(NodeList, ReadsIndicesAndComments) {
  std::vector<char> flags;
  const std::string path = write_text("ok.nodes", "# fixed\n0 2\n\t4 # last\n2\n");
  ASSERT_TRUE(read_node_list(path, 5, &flags).ok());
  EXPECT_EQ(flags, (std::vector<char>{1, 0, 1, 0, 1}));
}

// Fuzz finding (tests/fuzz/regressions/nodes/control_char.nodes): the bad token went into the
// message raw, control bytes and all.
TEST(NodeList, BadTokenIsQuotedPrintably) {
  std::vector<char> flags;
  const std::string path = write_text("bad.nodes", "# c\n\x1c\x01" + std::string(100, 'x') + "\n");
  const Status s = read_node_list(path, 5, &flags);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("bad.nodes:2: '"), std::string::npos) << s.message();
  EXPECT_NE(s.message().find("is not a node index"), std::string::npos) << s.message();
  EXPECT_LT(s.message().size(), 200u);
  for (unsigned char c : s.message()) EXPECT_GE(c, 0x20) << s.message();
}

}  // namespace
}  // namespace tmop
