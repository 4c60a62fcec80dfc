#include "tools/bench/record.h"

#include <sys/resource.h>
#include <sys/utsname.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>

#include "tmop/element/cell_type.h"
#include "tmop/recipes/recipe_result.h"

namespace tmop_bench {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\n");
  const auto e = s.find_last_not_of(" \t\n");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The value after "key" and ':' in the first line of FILE that starts with key, or "".
std::string proc_field(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, key.size(), key) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return trim(line.substr(colon + 1));
    }
  return "";
}

std::string command_output(const std::string& command) {
  std::string out;
  if (FILE* p = popen(command.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  return trim(out);
}

}  // namespace

double cpu_seconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_mb() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kilobytes on Linux
}

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string git_commit() {
  std::string dir = __FILE__;
  dir = dir.substr(0, dir.find_last_of('/'));
  const std::string git = "git -C '" + dir + "' ";
  std::string c = command_output(git + "rev-parse --short HEAD 2>/dev/null");
  if (c.empty()) return "unknown";
  if (!command_output(git + "status --porcelain --untracked-files=no -- ':/tmop' 2>/dev/null")
           .empty())
    c += "-dirty";
  return c;
}

std::string utc_now() {
  char buf[32];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

double load_average() {
  std::ifstream in("/proc/loadavg");
  double l = -1;
  in >> l;
  return l;
}

Json& Json::num(const std::string& k, double v) { return raw(k, tmop::json_number(v)); }
Json& Json::integer(const std::string& k, long long v) { return raw(k, std::to_string(v)); }
Json& Json::str(const std::string& k, const std::string& v) { return raw(k, tmop::json_string(v)); }
Json& Json::boolean(const std::string& k, bool v) { return raw(k, v ? "true" : "false"); }
Json& Json::obj(const std::string& k, const Json& v) { return raw(k, v.text()); }
Json& Json::nums(const std::string& k, const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + tmop::json_number(v[i]);
  return raw(k, s + "]");
}
Json& Json::raw(const std::string& k, const std::string& v) {
  fields_ += (fields_.empty() ? "" : ", ") + tmop::json_string(k) + ": " + v;
  return *this;
}

Json machine_json() {
  Json m;
  utsname u;
  uname(&u);
  m.integer("nproc", std::thread::hardware_concurrency())
      .str("cpu", proc_field("/proc/cpuinfo", "model name"))
      .num("memory_gb", std::atof(proc_field("/proc/meminfo", "MemTotal").c_str()) / 1048576.0)
      .str("kernel", std::string(u.sysname) + " " + u.release);
  return m;
}

Json mesh_json(const tmop::Mesh& mesh, const std::string& path) {
  const std::vector<int> counts = mesh.count_by_type();
  const int d = mesh.dim();
  std::string types;
  for (int t = 0; t < tmop::kNumCellTypes; ++t) {
    const auto type = static_cast<tmop::CellType>(t);
    if (counts[t] == 0 || tmop::cell_dim(type) != d) continue;
    types += (types.empty() ? "" : "+") + std::string(tmop::cell_name(type));
  }
  Json j;
  j.str("path", path)
      .integer("elements", mesh.num_elements())
      .integer("vertices", mesh.num_vertices())
      .str("type", types)
      .integer("dim", d);
  return j;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void Timing::start() {
  c0 = cpu_seconds();
  t0 = Clock::now();
}

void Timing::stop() {
  wall.push_back(seconds_since(t0));
  cpu.push_back(cpu_seconds() - c0);
}

void Timing::add_to(Json* j) const {
  j->num("wall_seconds", median(wall))
      .num("wall_seconds_min", wall.empty() ? 0 : *std::min_element(wall.begin(), wall.end()))
      .num("cpu_seconds", median(cpu))
      .nums("wall_seconds_all", wall);
}

}  // namespace tmop_bench
