// tmop_optimize over the recipe registry: unused options refused (exit 2, one line),
// --fixed_nodes (file or field) keeps nodes bit for bit and locates bad files, the report
// carries settings, version and the size and hash of every file it reads, and --from_report
// reproduces a run.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include "tests/optimize/grid_meshes.h"
#include "tmop/io/mesh_io.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// The report's entry of one read file: {"flag", "path", "bytes", "fnv1a64"}, the hash computed
// here independently of the tool (FNV-1a 64 of the file's bytes).
std::string input_file_entry(const std::string& flag, const std::string& path) {
  const std::string bytes = slurp(path);
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return "{\"flag\": \"" + flag + "\", \"path\": \"" + path +
         "\", \"bytes\": " + std::to_string(bytes.size()) + ", \"fnv1a64\": \"" + hex + "\"}";
}

class RegistryTool : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system(("test -x " + tool_).c_str()) != 0) GTEST_SKIP() << "tmop_optimize not built";
    char dir[] = "/tmp/tmop_registry_tool_XXXXXX";
    ASSERT_NE(mkdtemp(dir), nullptr);
    dir_ = dir;
    mesh_ = testing_grid::grid(CellType::kTri3, 8);
    std::mt19937 rng(7);
    testing_grid::perturb(&mesh_, 8, 0.3, &rng);
    in_ = dir_ + "/in.msh";
    ASSERT_TRUE(write_mesh(in_, mesh_).ok());
  }
  void TearDown() override {
    if (!dir_.empty()) std::system(("rm -rf " + dir_).c_str());
  }
  int run(const std::string& args, std::string* err) {
    const std::string cmd = tool_ + " " + args + " > " + dir_ + "/out.txt 2> " + dir_ + "/err.txt";
    const int status = std::system(cmd.c_str());
    *err = slurp(dir_ + "/err.txt");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::string io(const std::string& out = "o.msh") {
    return "--input=" + in_ + " --output=" + dir_ + "/" + out + " --threads=1 ";
  }
  std::string tool_ = TMOP_BINARY_DIR "/tools/tmop_optimize";
  std::string dir_, in_;
  Mesh mesh_;
};

TEST_F(RegistryTool, OptionsARecipeDoesNotUseAreRefused) {
  const struct {
    std::string args, message;
  } cases[] = {
      {"--recipe=laplace --metric=shape_2d", "--metric is not used by recipe laplace"},
      {"--recipe=sliver --power=3", "--power is not used by recipe sliver"},
      {"--recipe=untangle --metric=shape_2d", "--metric is not used by recipe untangle"},
      {"--recipe=laplace --max_iterations=10", "--max_iterations is not used by recipe laplace"},
      {"--recipe=shape --size_field=h",
       "--size_field is not used by recipe shape without --target=size_field"},
      {"--recipe=preserve --moved=" + std::string("x.msh") + " --geometry=sphere:0,0,0,1",
       "--geometry is not used by recipe preserve"},
  };
  for (const auto& c : cases) {
    std::string err;
    EXPECT_EQ(run(io() + c.args, &err), 2) << c.args;
    EXPECT_EQ(err, "tmop_optimize: " + c.message + "\n") << c.args;
  }
  std::string err;
  EXPECT_EQ(run("--help", &err), 0);
  const std::string help = slurp(dir_ + "/out.txt");
  for (const char* name : {"auto:", "high_order:", "laplace:", "sliver:", "preserve:"})
    EXPECT_NE(help.find(name), std::string::npos) << name;
}

TEST_F(RegistryTool, FixedNodesFromAFileOrAFieldKeepTheirBits) {
  const std::vector<char> boundary = boundary_vertex_mask(mesh_);
  std::vector<int> fixed;
  for (int v = 0; v < mesh_.num_vertices(); v += 4)
    if (!boundary[v]) fixed.push_back(v);
  ASSERT_GE(fixed.size(), 5u);
  {
    std::ofstream f(dir_ + "/fixed.txt");
    f << "# held nodes\n";
    for (std::size_t i = 0; i < fixed.size(); ++i) f << fixed[i] << (i % 3 == 2 ? "\n" : "  ");
    f << "  # end\n";
  }
  Mesh with_field = mesh_;
  DataArray a;
  a.name = "hold";
  a.values.assign(mesh_.num_vertices(), 0.0);
  for (int v : fixed) a.values[v] = 1;
  with_field.point_data.push_back(a);
  const std::string field_in = dir_ + "/field.vtu";
  ASSERT_TRUE(write_mesh(field_in, with_field).ok());
  for (const std::string recipe : {"shape", "laplace", "equal_edge", "size_adapt"}) {
    for (const bool field : {false, true}) {
      std::string args =
          field ? "--input=" + field_in + " --output=" + dir_ +
                      "/o.vtu --fixed_nodes=field:hold --recipe=" + recipe
                : io("o.vtu") + "--fixed_nodes=" + dir_ + "/fixed.txt --recipe=" + recipe;
      if (recipe != "laplace" && field) args += " --threads=1";
      if (recipe == "laplace" && !field) args.replace(args.find(" --threads=1"), 12, "");
      std::string err;
      ASSERT_EQ(run(args, &err), 0) << args << ": " << err;
      Mesh out;
      ASSERT_TRUE(read_mesh(dir_ + "/o.vtu", &out).ok());
      int moved = 0;
      for (int v = 0; v < mesh_.num_vertices(); ++v) {
        const bool same =
            out.vertex(v)[0] == mesh_.vertex(v)[0] && out.vertex(v)[1] == mesh_.vertex(v)[1];
        moved += !same;
      }
      for (int v : fixed) {
        EXPECT_EQ(out.vertex(v)[0], mesh_.vertex(v)[0]) << args << " node " << v;
        EXPECT_EQ(out.vertex(v)[1], mesh_.vertex(v)[1]) << args << " node " << v;
      }
      EXPECT_GT(moved, 0) << args;
    }
  }
}

TEST_F(RegistryTool, BadFixedNodeFilesAreFileLineExitTwo) {
  const std::string f = dir_ + "/bad.txt";
  const struct {
    std::string text, message;
  } cases[] = {
      {"1 2\n# ok\n3 x7\n", f + ":3: 'x7' is not a node index\n"},
      {"1\n\n5 100000\n", f + ":3: node 100000 out of range 0..80\n"},
      {"-1\n", f + ":1: node -1 out of range 0..80\n"},
  };
  for (const auto& c : cases) {
    { std::ofstream(f) << c.text; }
    std::string err;
    EXPECT_EQ(run(io() + "--fixed_nodes=" + f, &err), 2) << c.text;
    EXPECT_EQ(err, c.message) << c.text;
  }
  std::string err;
  EXPECT_EQ(run(io() + "--fixed_nodes=" + dir_ + "/none.txt", &err), 2);
  EXPECT_EQ(err.rfind(dir_ + "/none.txt: cannot open", 0), 0u) << err;
  EXPECT_EQ(run(io() + "--fixed_nodes=field:nope", &err), 2);
  EXPECT_NE(err.find("no point-data array 'nope'"), std::string::npos) << err;
}

// The report names the settings as used, tmop's version and commit, the input's size and hash;
// a rerun from it (another output) writes the same bytes, and command-line flags override it.
TEST_F(RegistryTool, ARunReproducedFromItsReportIsByteIdentical) {
  const std::string report = dir_ + "/r.json";
  std::string err;
  ASSERT_EQ(run(io("a.msh") + "--recipe=shape --power=3 --report=" + report, &err), 0) << err;
  const std::string json = slurp(report);
  for (const char* key :
       {"\"settings\": {\"recipe\": \"shape\", \"metric\": \"shape_barrier_2d\"", "\"power\": 3",
        "\"tmop\": {\"version\": \"0.", "\"commit\": ", "\"fnv1a64\": \"", "\"flags\": {",
        "\"max_iterations\": \"200\"", "\"threads\": \"1\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json.substr(0, 1500);
  const std::string size = "\"bytes\": " + std::to_string(slurp(in_).size());
  EXPECT_NE(json.find(size), std::string::npos) << size;
  ASSERT_EQ(run("--from_report=" + report + " --output=" + dir_ + "/b.msh", &err), 0) << err;
  EXPECT_EQ(slurp(dir_ + "/a.msh"), slurp(dir_ + "/b.msh"));
  // A flag given on the command line wins: p = 1 is another result.
  ASSERT_EQ(run("--from_report=" + report + " --output=" + dir_ + "/c.msh --power=1", &err), 0)
      << err;
  EXPECT_NE(slurp(dir_ + "/a.msh"), slurp(dir_ + "/c.msh"));
  // A missing or bad report: exit 2, one line naming it.
  EXPECT_EQ(run("--from_report=" + dir_ + "/none.json --output=" + dir_ + "/d.msh", &err), 2);
  EXPECT_EQ(err.rfind(dir_ + "/none.json: cannot open", 0), 0u) << err;
  { std::ofstream(dir_ + "/bad.json") << "{\"flags\": {\"power\": 3}}"; }
  EXPECT_EQ(run("--from_report=" + dir_ + "/bad.json --output=" + dir_ + "/d.msh", &err), 2);
  EXPECT_EQ(err.rfind(dir_ + "/bad.json: byte ", 0), 0u) << err;
  { std::ofstream(dir_ + "/other.json") << "{\"x\": 1}"; }
  EXPECT_EQ(run("--from_report=" + dir_ + "/other.json --output=" + dir_ + "/d.msh", &err), 2);
  EXPECT_EQ(err, dir_ + "/other.json: not a tmop_optimize report (no \"flags\" object)\n");
}

// Fuzz findings (tests/fuzz/regressions/report): a flag value with control bytes went into the
// message raw; a \u escape without 4 hex digits and an unknown escape were taken as text.
TEST_F(RegistryTool, BadReportValuesAndEscapesAreOnePrintableLine) {
  const struct {
    const char* json;
    const char* message;
  } cases[] = {
      {"{\"flags\": {\"threads\": \"\\u0010x\"}}", "flag --threads: bad value '?x'"},
      {"{\"flags\": {\"threads\": \"\\u12zz\"}}", "byte 25: bad \\u escape (4 hex digits)"},
      {"{\"flags\": {\"threads\": \"\\q\"}}", "byte 25: bad escape \\q"},
  };
  for (const auto& c : cases) {
    { std::ofstream(dir_ + "/r.json") << c.json; }
    std::string err;
    EXPECT_EQ(run("--from_report=" + dir_ + "/r.json --output=" + dir_ + "/d.msh", &err), 2);
    EXPECT_EQ(err, dir_ + "/r.json: " + c.message + "\n") << c.json;
  }
}

// "input_files" lists every file the run reads with its size and hash: the input, a
// --fixed_nodes FILE and the --from_report; a changed file changes its hash.
TEST_F(RegistryTool, TheReportHashesEveryFileTheRunReads) {
  const std::string nodes = dir_ + "/fixed.txt", report = dir_ + "/r.json";
  std::string err, hashes[2];
  for (int pass = 0; pass < 2; ++pass) {
    { std::ofstream(nodes) << (pass == 0 ? "3 4\n# held\n5\n" : "3 4\n# held\n6\n"); }
    ASSERT_EQ(run(io() + "--fixed_nodes=" + nodes + " --report=" + report, &err), 0) << err;
    const std::string json = slurp(report), entry = input_file_entry("fixed_nodes", nodes);
    EXPECT_NE(json.find("\"input_files\": [\n    " + input_file_entry("input", in_) + ",\n    " +
                        entry + "\n  ]"),
              std::string::npos)
        << entry << "\n"
        << json.substr(0, 1200);
    hashes[pass] = entry;
  }
  EXPECT_NE(hashes[0], hashes[1]);  // same size, one byte changed
  // A rerun lists the report it read, and the files its flags name.
  const std::string rerun = dir_ + "/r2.json";
  ASSERT_EQ(run("--from_report=" + report + " --output=" + dir_ + "/b.msh --report=" + rerun, &err),
            0)
      << err;
  const std::string json = slurp(rerun);
  EXPECT_NE(json.find(input_file_entry("fixed_nodes", nodes)), std::string::npos) << json;
  EXPECT_NE(json.find(input_file_entry("from_report", report)), std::string::npos) << json;
}

}  // namespace
}  // namespace tmop
