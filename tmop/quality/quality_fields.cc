#include "tmop/quality/quality_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace tmop {
namespace {

void put(const std::string& name, std::vector<double> values, Mesh* mesh) {
  for (DataArray& a : mesh->cell_data) {
    if (a.name == name) {
      a.components = 1;
      a.values = std::move(values);
      return;
    }
  }
  mesh->cell_data.push_back(DataArray{name, 1, std::move(values)});
}

}  // namespace

void add_quality_fields(const QualityReport& report, Mesh* mesh) {
  if (report.num_cells != mesh->num_cells()) {
    std::fprintf(stderr, "tmop: add_quality_fields: report has %lld cells, mesh %d\n",
                 static_cast<long long>(report.num_cells), mesh->num_cells());
    std::abort();
  }
  put("inverted", std::vector<double>(report.inverted.begin(), report.inverted.end()), mesh);
  // Arrays that apply to no element (angles of a tet mesh) would only add all-NaN columns.
  auto any = [](const std::vector<double>& v) {
    return std::any_of(v.begin(), v.end(), [](double x) { return !std::isnan(x); });
  };
  if (any(report.certified)) put("certified", report.certified, mesh);
  // Elements a fixed boundary freezes (topology_caps.h), so they can be found in a viewer.
  if (any(report.all_boundary)) put("all_boundary", report.all_boundary, mesh);
  for (const QualityMeasure* m : report.measures())
    if (any(m->values)) put(m->key, m->values, mesh);
}

bool refresh_quality_fields(const QualityReport& report, Mesh* mesh) {
  auto is_quality_field = [&](const std::string& name) {
    if (name == "inverted" || name == "certified" || name == "all_boundary") return true;
    for (const QualityMeasure* m : report.measures())
      if (name == m->key) return true;
    return false;
  };
  const std::size_t n = mesh->cell_data.size();
  mesh->cell_data.erase(
      std::remove_if(mesh->cell_data.begin(), mesh->cell_data.end(),
                     [&](const DataArray& a) { return is_quality_field(a.name); }),
      mesh->cell_data.end());
  if (mesh->cell_data.size() == n) return false;
  add_quality_fields(report, mesh);
  return true;
}

}  // namespace tmop
