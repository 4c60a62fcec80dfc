#include "tmop/target/composed_target.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tmop/element/shape.h"
#include "tmop/mesh/mesh.h"
#include "tmop/target/smoothed_aspect.h"
#include "tmop/target/target.h"
#include "tmop/target/target_factors.h"

namespace tmop {
namespace {

constexpr int kNumKinds = 4;
constexpr FactorKind kKinds[kNumKinds] = {FactorKind::kSize, FactorKind::kOrientation,
                                          FactorKind::kSkew, FactorKind::kAspect};

int value_count(FactorKind kind, int d) {
  switch (kind) {
    case FactorKind::kSize:
      return 1;
    case FactorKind::kOrientation:
      return d == 2 ? 2 : 6;
    case FactorKind::kSkew:
      return d == 2 ? 1 : 3;
    case FactorKind::kAspect:
      return d;
  }
  return 0;
}

const char* value_meaning(FactorKind kind, int d) {
  switch (kind) {
    case FactorKind::kSize:
      return "a positive equivalent edge length";
    case FactorKind::kOrientation:
      return d == 2 ? "a non-zero first axis" : "two non-parallel axes";
    case FactorKind::kSkew:
      return d == 2 ? "an angle in (0, 180) degrees"
                    : "angles phi12, phi13, phi23 in (0, 180) degrees making a trihedron";
    case FactorKind::kAspect:
      return "positive relative column lengths";
  }
  return "";
}

std::string list(const double* v, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v[i]);
    s += (i ? "," : "") + std::string(buf);
  }
  return s;
}

Status failure(FactorKind kind, const std::string& what) {
  return Status::Failure(std::string("composed target ") + factor_kind_name(kind) + ": " + what);
}

// Sets the `kind` part of *f from user values v (value_count of them), mapped into the mesh's
// frame. False when the values are out of range.
bool apply_values(FactorKind kind, int d, const double* v, const TargetFrame& frame,
                  TargetFactors* f) {
  switch (kind) {
    case FactorKind::kSize: {
      const double h = v[0] / frame.length;
      if (!(h > 0) || !std::isfinite(h)) return false;
      f->size = h;
      return true;
    }
    case FactorKind::kOrientation: {
      double R[9];
      if (!orientation_from_axes(d, v, R)) return false;
      // The axes are the user's; the mesh's frame is rotated by frame.rotation.
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          double r = 0;
          for (int k = 0; k < d; ++k) r += frame.rotation[i * 3 + k] * R[k * 3 + j];
          f->orientation[i * 3 + j] = r;
        }
      return true;
    }
    case FactorKind::kSkew:
      return skew_from_angles(d, v, f->skew);
    case FactorKind::kAspect:
      return aspect_from_lengths(d, v, f->aspect);
  }
  return false;
}

void copy_part(FactorKind kind, const TargetFactors& from, TargetFactors* to) {
  switch (kind) {
    case FactorKind::kSize:
      to->size = from.size;
      break;
    case FactorKind::kOrientation:
      std::copy(from.orientation, from.orientation + 9, to->orientation);
      break;
    case FactorKind::kSkew:
      std::copy(from.skew, from.skew + 9, to->skew);
      break;
    case FactorKind::kAspect:
      std::copy(from.aspect, from.aspect + 3, to->aspect);
      break;
  }
}

bool parse_numbers(const std::string& text, std::vector<double>* out) {
  out->clear();
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find(',', begin);
    if (end == std::string::npos) end = text.size();
    const std::string item = text.substr(begin, end - begin);
    if (item.empty()) return false;
    char* stop = nullptr;
    errno = 0;
    const double x = std::strtod(item.c_str(), &stop);
    if (*stop != '\0' || errno != 0 || !std::isfinite(x)) return false;
    out->push_back(x);
    begin = end + 1;
  }
  return !out->empty();
}

}  // namespace

const char* factor_kind_name(FactorKind kind) {
  switch (kind) {
    case FactorKind::kSize:
      return "size";
    case FactorKind::kOrientation:
      return "orientation";
    case FactorKind::kSkew:
      return "skew";
    case FactorKind::kAspect:
      return "aspect";
  }
  return "?";
}

Status parse_target_factor(FactorKind kind, const std::string& text, TargetFactor* factor) {
  TargetFactor f;
  const bool orientation = kind == FactorKind::kOrientation;
  if (text == "ideal" || (orientation && text == "identity")) {
    f.source = FactorSource::kIdeal;
  } else if (text == "initial") {
    f.source = FactorSource::kInitial;
  } else if (kind == FactorKind::kAspect && text == "smooth") {
    f.source = FactorSource::kSmooth;
  } else if (kind == FactorKind::kSize && text == "equal") {
    f.source = FactorSource::kMeanSize;
  } else if (text.rfind("field:", 0) == 0 && text.size() > 6) {
    f.source = FactorSource::kField;
    f.field = text.substr(6);
  } else if (orientation && text.rfind("angle:", 0) == 0) {
    std::vector<double> deg;
    if (!parse_numbers(text.substr(6), &deg) || deg.size() != 1)
      return Status::Failure("orientation source '" + text + "': angle:DEG needs one number");
    const double r = deg[0] * 3.14159265358979323846 / 180;
    f.source = FactorSource::kConstant;
    f.value = {std::cos(r), std::sin(r)};
  } else if (parse_numbers(text, &f.value)) {
    f.source = FactorSource::kConstant;
  } else {
    const char* known = "";
    switch (kind) {
      case FactorKind::kSize:
        known = "ideal, equal, initial, field:NAME or a length";
        break;
      case FactorKind::kOrientation:
        known = "identity, initial, field:NAME, angle:DEG or axis components";
        break;
      case FactorKind::kSkew:
        known = "ideal, initial, field:NAME or angles in degrees";
        break;
      case FactorKind::kAspect:
        known = "ideal, initial, smooth, field:NAME or relative lengths";
        break;
    }
    return Status::Failure(std::string(factor_kind_name(kind)) + " source '" + text + "' is not " +
                           known);
  }
  *factor = std::move(f);
  return Status::Ok();
}

namespace {

// What the factors need, found once before the per-point loop.
struct Resolved {
  const TargetFactor* factors[kNumKinds];
  const DataArray* fields[kNumKinds] = {nullptr, nullptr, nullptr, nullptr};
  TargetFactors constants;  // the constant factors, converted
  bool need_initial = false, need_shape = false, need_mean = false, need_smooth = false;
};

Status resolve(const Mesh& mesh, const TargetSpec& spec, Resolved* r) {
  const int d = mesh.dim();
  if (d < 2 || d > 3) return Status::Failure("targets need a mesh of 2D or 3D elements");
  const bool surface = mesh.space_dim != d;
  const TargetFrame& frame = spec.frame;
  if (!(frame.length > 0) || !std::isfinite(frame.length))
    return Status::Failure("target frame: the length scale must be positive");
  if (spec.reference && !reference_matches(mesh, *spec.reference))
    return Status::Failure("reference mesh: its vertices and cells do not match the mesh's");
  const ComposedTarget& ct = spec.composed;
  r->factors[0] = &ct.size;
  r->factors[1] = &ct.orientation;
  r->factors[2] = &ct.skew;
  r->factors[3] = &ct.aspect;
  for (int k = 0; k < kNumKinds; ++k) {
    const FactorKind kind = kKinds[k];
    const TargetFactor& f = *r->factors[k];
    const int n = value_count(kind, d);
    if (f.source == FactorSource::kMeanSize && kind != FactorKind::kSize)
      return failure(kind, "'equal' is a source of the size only");
    if (surface && kind == FactorKind::kOrientation && f.source != FactorSource::kIdeal &&
        f.source != FactorSource::kInitial)
      return failure(kind,
                     "a surface mesh's targets live in each cell's plane: use ideal or initial");
    switch (f.source) {
      case FactorSource::kIdeal:
        break;
      case FactorSource::kMeanSize:
        r->need_mean = true;
        break;
      case FactorSource::kInitial:
        r->need_initial = true;
        break;
      case FactorSource::kSmooth:
        if (kind != FactorKind::kAspect)
          return failure(kind, "'smooth' is a source of the aspect only");
        r->need_smooth = true;
        break;
      case FactorSource::kConstant:
        if (static_cast<int>(f.value.size()) != n)
          return failure(kind, std::to_string(n) + " value" + (n > 1 ? "s" : "") + " (" +
                                   value_meaning(kind, d) + ") expected for " + std::to_string(d) +
                                   "D elements, got " + std::to_string(f.value.size()));
        if (!apply_values(kind, d, f.value.data(), frame, &r->constants))
          return failure(kind, "invalid value " + list(f.value.data(), n) + " (expected " +
                                   value_meaning(kind, d) + ")");
        break;
      case FactorSource::kField: {
        for (const DataArray& a : mesh.point_data)
          if (a.name == f.field &&
              (a.components == n ||
               (kind == FactorKind::kOrientation && d == 2 && a.components == 3)) &&
              a.values.size() == std::size_t(mesh.num_vertices()) * a.components)
            r->fields[k] = &a;
        if (!r->fields[k])
          return failure(kind, "no point_data array '" + f.field + "' with " + std::to_string(n) +
                                   " component" + (n > 1 ? "s" : "") + " (" +
                                   value_meaning(kind, d) + ")");
        r->need_shape = true;
        break;
      }
      case FactorSource::kFunction:
        if (!f.function) return failure(kind, "the function source has no function");
        r->need_shape = true;
        break;
    }
  }
  return Status::Ok();
}

}  // namespace

Status check_composed_target(const Mesh& mesh, const TargetSpec& spec) {
  Resolved r;
  return resolve(mesh, spec, &r);
}

Status build_composed_targets(const Mesh& mesh, const SampleSet& points, const TargetSpec& spec,
                              std::vector<double>* W) {
  Resolved r;
  Status status = resolve(mesh, spec, &r);
  if (!status.ok()) return status;
  const int d = mesh.dim();
  const Mesh& initial_mesh = spec.reference ? *spec.reference : mesh;
  const TargetFrame& frame = spec.frame;
  double mean = 1;
  if (r.need_mean) {
    mean = mean_equivalent_edge(initial_mesh);
    if (!(mean > 0) || !std::isfinite(mean))
      return failure(FactorKind::kSize, "the mean size is not positive (degenerate mesh?)");
  }

  SmoothedAspect smooth;
  if (r.need_smooth) {
    status = smooth.build(initial_mesh);
    if (!status.ok()) return Status::Failure("composed target: " + status.message());
  }

  std::vector<double> out;
  out.reserve(points.size() * d * d);
  double N[kMaxCellNodes], A[9], w[9];
  TargetFactors ideal, initial;
  int ideal_type = -1;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const int c = points.cell[p];
    const double* xi = &points.xi[3 * p];
    const CellType t = mesh.cell_type(c);
    if (static_cast<int>(t) != ideal_type) {
      ideal_type = static_cast<int>(t);
      ideal = ideal_factors(t);
    }
    auto in_cell = [c] { return " in cell " + std::to_string(c); };  // for messages only
    if (r.need_initial) {
      target_jacobian(initial_mesh, c, xi, A);
      if (!factor_jacobian(t, A, &initial))
        return Status::Failure("composed target: cell " + std::to_string(c) +
                               ": the initial Jacobian has det <= 0 at a sample point (factors "
                               "from the initial mesh need a valid element)");
    }
    double x_user[3] = {0, 0, 0};
    if (r.need_shape) {
      shape_values(t, xi, N);
      // Physical position in the mesh's frame, then back to the user's for functions.
      double x[3] = {0, 0, 0};
      const int sd = mesh.space_dim;
      for (int i = 0; i < mesh.cell_size(c); ++i)
        for (int a = 0; a < sd; ++a) x[a] += N[i] * mesh.vertex(mesh.cell(c)[i])[a];
      for (int a = 0; a < sd; ++a) {
        double y = 0;
        for (int b = 0; b < sd; ++b) y += frame.rotation[b * 3 + a] * x[b];
        x_user[a] = frame.centre[a] + frame.length * y;
      }
    }
    TargetFactors f = ideal;
    for (int k = 0; k < kNumKinds; ++k) {
      const FactorKind kind = kKinds[k];
      const TargetFactor& src = *r.factors[k];
      switch (src.source) {
        case FactorSource::kIdeal:
          break;
        case FactorSource::kMeanSize:
          f.size = mean;
          break;
        case FactorSource::kInitial:
          copy_part(kind, initial, &f);
          break;
        case FactorSource::kSmooth: {
          double v[3] = {1, 1, 1};
          smooth.aspect(initial_mesh, c, xi, v);
          if (!apply_values(kind, d, v, frame, &f))
            return failure(kind, "smoothed aspect " + list(v, d) + " is invalid" + in_cell());
          break;
        }
        case FactorSource::kConstant:
          copy_part(kind, r.constants, &f);
          break;
        case FactorSource::kField: {
          const DataArray& a = *r.fields[k];
          const int n = value_count(kind, d);
          double v[6] = {0, 0, 0, 0, 0, 0};
          for (int i = 0; i < mesh.cell_size(c); ++i) {
            const double* vi = &a.values[std::size_t(mesh.cell(c)[i]) * a.components];
            for (int j = 0; j < n; ++j) v[j] += N[i] * vi[j];
          }
          if (!apply_values(kind, d, v, frame, &f))
            return failure(kind, "field '" + src.field + "' gives invalid values " + list(v, n) +
                                     in_cell() + " (" + value_meaning(kind, d) + ")");
          break;
        }
        case FactorSource::kFunction: {
          const int n = value_count(kind, d);
          double v[6];
          for (double& vi : v) vi = std::nan("");
          src.function(x_user, v);
          if (!apply_values(kind, d, v, frame, &f))
            return failure(kind, "the function gives invalid values " + list(v, n) + in_cell() +
                                     " (" + value_meaning(kind, d) + ")");
          break;
        }
      }
    }
    compose_factors(t, f, w);
    for (int i = 0; i < d * d; ++i)
      if (!std::isfinite(w[i])) return Status::Failure("composed target: not finite" + in_cell());
    out.insert(out.end(), w, w + d * d);
  }
  W->swap(out);
  return Status::Ok();
}

}  // namespace tmop
