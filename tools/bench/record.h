// tools/bench/record.h
// The parts of a tmop_bench JSON record that do not depend on the task: clocks (wall, CPU of
// all threads, peak RSS), the machine, the commit and time of the run, the mesh, and the
// median / minimum of repeated timings (docs/benchmarks.md, "tmop_bench JSON record").
#ifndef TMOP_TOOLS_BENCH_RECORD_H_
#define TMOP_TOOLS_BENCH_RECORD_H_

#include <chrono>
#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop_bench {

using Clock = std::chrono::steady_clock;

double cpu_seconds();  // user + sys of all threads so far (getrusage)
double peak_rss_mb();  // ru_maxrss
double seconds_since(Clock::time_point t0);
// Short commit of the checkout the tool was compiled from, "-dirty" when tmop/ has local
// changes; read when the program runs (the record also carries the build time).
std::string git_commit();
std::string utc_now();  // ISO 8601, seconds
double load_average();  // 1-minute, -1 when unknown

// A JSON object built field by field (keys in insertion order).
class Json {
 public:
  Json& num(const std::string& k, double v);
  Json& integer(const std::string& k, long long v);
  Json& str(const std::string& k, const std::string& v);
  Json& boolean(const std::string& k, bool v);
  Json& obj(const std::string& k, const Json& v);
  Json& nums(const std::string& k, const std::vector<double>& v);
  Json& raw(const std::string& k, const std::string& v);
  std::string text() const { return "{" + fields_ + "}"; }

 private:
  std::string fields_;
};

Json machine_json();  // nproc, cpu model, memory, kernel
Json mesh_json(const tmop::Mesh& mesh, const std::string& path);
double median(std::vector<double> v);

// Wall and CPU time of the measured parts of K runs.
struct Timing {
  std::vector<double> wall, cpu;
  Clock::time_point t0;
  double c0 = 0;
  void start();
  void stop();
  void add_to(Json* j) const;  // wall_seconds (median), wall_seconds_min, cpu_seconds, all
};

}  // namespace tmop_bench

#endif  // TMOP_TOOLS_BENCH_RECORD_H_
