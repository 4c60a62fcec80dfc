#include "tmop/geometry/geometry_source.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "tmop/geometry/cylinder_manifold.h"
#include "tmop/geometry/plane_manifold.h"
#include "tmop/geometry/reference_surface.h"
#include "tmop/geometry/sphere_manifold.h"
#include "tmop/geometry/triangle_surface_manifold.h"

namespace tmop {
namespace {

// Parses exactly `count` comma-separated finite numbers.
bool parse_numbers(const std::string& text, int count, std::vector<double>* values) {
  values->clear();
  const char* p = text.c_str();
  for (int i = 0; i < count; ++i) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    if (end == p || errno != 0 || !std::isfinite(v)) return false;
    values->push_back(v);
    p = end;
    if (i + 1 < count) {
      if (*p != ',') return false;
      ++p;
    }
  }
  return *p == '\0';
}

double norm3(const double* v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

}  // namespace

Status load_geometry_source(const std::string& spec, GeometrySource* out,
                            const GeometryFrame& frame) {
  if (!(frame.length > 0)) return Status::Failure("geometry: frame length must be positive");
  // Points and lengths map to the frame; directions rotate.
  auto direction = [&](double* p) {
    double y[3];
    for (int i = 0; i < 3; ++i)
      y[i] = frame.rotation[3 * i] * p[0] + frame.rotation[3 * i + 1] * p[1] +
             frame.rotation[3 * i + 2] * p[2];
    for (int i = 0; i < 3; ++i) p[i] = y[i];
  };
  auto point = [&](double* p) {
    for (int i = 0; i < 3; ++i) p[i] = (p[i] - frame.centre[i]) / frame.length;
    direction(p);
  };
  *out = GeometrySource();
  if (spec.empty()) {
    out->description = "own boundary";
    return Status::Ok();
  }
  const std::size_t colon = spec.find(':');
  const std::string name = colon == std::string::npos ? "" : spec.substr(0, colon);
  if (name == "sphere" || name == "plane" || name == "cylinder") {
    const int count = name == "sphere" ? 4 : (name == "plane" ? 6 : 7);
    std::vector<double> x;
    if (!parse_numbers(spec.substr(colon + 1), count, &x)) {
      return Status::Failure("geometry '" + spec + "': expected " + std::to_string(count) +
                             " comma-separated numbers after '" + name + ":'");
    }
    out->kind = GeometrySourceKind::kAnalytic;
    out->description = name;
    point(x.data());
    if (name == "sphere") {
      if (!(x[3] > 0)) return Status::Failure("geometry '" + spec + "': radius must be > 0");
      out->surface = std::make_unique<SphereManifold>(x.data(), x[3] / frame.length);
    } else if (name == "plane") {
      if (norm3(&x[3]) == 0) return Status::Failure("geometry '" + spec + "': zero normal");
      direction(&x[3]);
      out->surface = std::make_unique<PlaneManifold>(x.data(), &x[3]);
    } else {
      if (norm3(&x[3]) == 0) return Status::Failure("geometry '" + spec + "': zero axis");
      if (!(x[6] > 0)) return Status::Failure("geometry '" + spec + "': radius must be > 0");
      direction(&x[3]);
      out->surface = std::make_unique<CylinderManifold>(x.data(), &x[3], x[6] / frame.length);
    }
    return Status::Ok();
  }
  std::vector<double> vertices;
  std::vector<std::int32_t> triangles;
  SurfaceRepair repair;
  const Status s = read_reference_surface(spec, &vertices, &triangles, &repair);
  if (!s.ok()) {
    return Status::Failure(s.message() +
                           " (geometry: sphere:cx,cy,cz,r | plane:p,n | cylinder:p,d,r | FILE)");
  }
  // TriangleSurfaceManifold CHECKs for a usable triangle; a file of slivers is the user's
  // doing, so it is reported here instead. Same relative area test as the manifold's.
  bool usable = false;
  for (std::size_t t = 0; t + 2 < triangles.size() && !usable; t += 3) {
    const double* a = &vertices[3 * triangles[t]];
    const double* b = &vertices[3 * triangles[t + 1]];
    const double* c = &vertices[3 * triangles[t + 2]];
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double e3[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]};
    const double h = std::max({norm3(e1), norm3(e2), norm3(e3)});
    usable = norm3(n) > 1e-14 * h * h;
  }
  if (!usable) return Status::Failure(spec + ": the surface has no triangle with positive area");
  for (std::size_t v = 0; v + 2 < vertices.size(); v += 3) point(&vertices[v]);
  out->kind = GeometrySourceKind::kSurfaceFile;
  out->description = spec;
  if (repair.dropped_degenerate > 0 || repair.split_polygons > 0)
    out->description += " (" + std::to_string(repair.dropped_degenerate) +
                        " degenerate facets dropped, " + std::to_string(repair.split_polygons) +
                        " polygons split)";
  out->surface = std::make_unique<TriangleSurfaceManifold>(std::move(vertices), triangles);
  return Status::Ok();
}

}  // namespace tmop
