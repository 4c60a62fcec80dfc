#include "tmop/recipes/recipe_result.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace tmop {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

namespace {

std::string record_json(const IterationRecord& r, bool with_iteration) {
  std::string s = "{";
  if (with_iteration)
    s += "\"iteration\": " + std::to_string(r.iteration) +
         ", \"objective\": " + json_number(r.objective) +
         ", \"solver_objective\": " + json_number(r.solver_objective) + ", ";
  s += "\"min_quality\": " + json_number(r.min_quality) +
       (with_iteration ? "" : ", \"min_quality_measure\": \"sample_mean_ratio\"") +
       ", \"inverted\": " + (r.inverted < 0 ? std::string("null") : std::to_string(r.inverted));
  if (with_iteration) s += ", \"seconds\": " + json_number(r.seconds);
  return s + "}";
}

}  // namespace

std::string recipe_json(const RecipeResult& r) {
  std::string s =
      "{\"recipe\": " + json_string(r.recipe) + ", \"seconds\": " + json_number(r.seconds) +
      ", \"before\": " + record_json(r.before, false) +
      ", \"after\": " + record_json(r.after, false) +
      ", \"certified\": " + (r.certified < 0 ? "null" : std::to_string(r.certified)) +
      ", \"uncertified\": " + (r.uncertified < 0 ? "null" : std::to_string(r.uncertified)) +
      ", \"layer_cells\": " + (r.layer_cells < 0 ? "null" : std::to_string(r.layer_cells)) +
      ", \"held_vertices\": " + (r.held_vertices < 0 ? "null" : std::to_string(r.held_vertices)) +
      ", \"guard_held_cells\": " +
      (r.guard_held_cells < 0 ? "null" : std::to_string(r.guard_held_cells)) + ", \"stages\": [";
  for (std::size_t i = 0; i < r.stages.size(); ++i) {
    const StageResult& st = r.stages[i];
    s += i ? ", {" : "{";
    s += "\"name\": " + json_string(st.name) +
         ", \"linear_solver\": " + json_string(st.linear_solver) +
         ", \"elements\": " + std::to_string(st.num_elements) +
         ", \"sample_points\": " + std::to_string(st.num_sample_points) +
         ", \"free_vertices\": " + std::to_string(st.num_free_vertices) +
         ", \"initial_objective\": " + json_number(st.initial_objective) +
         ", \"final_objective\": " + json_number(st.final_objective) +
         ", \"iterations\": " + std::to_string(st.iterations) +
         ", \"solves\": " + std::to_string(st.solves) + ", \"parts\": " + std::to_string(st.parts) +
         ", \"sweeps\": " + std::to_string(st.sweeps) + ", \"element_iterations\": " +
         std::to_string(st.parts ? st.part_element_iterations
                                 : static_cast<std::int64_t>(st.num_elements) * st.iterations) +
         ", \"termination\": " + json_string(st.termination) +
         ", \"seconds\": " + json_number(st.seconds) +
         ", \"inverted_before\": " + std::to_string(st.inverted_before) +
         ", \"inverted_after\": " + std::to_string(st.inverted_after) +
         ", \"min_quality_before\": " + json_number(st.min_quality_before) +
         ", \"min_quality_after\": " + json_number(st.min_quality_after) + ", \"history\": [";
    for (std::size_t k = 0; k < st.history.size(); ++k)
      s += (k ? ", " : "") + record_json(st.history[k], true);
    s += "]}";
  }
  return s + "]}";
}

}  // namespace tmop
