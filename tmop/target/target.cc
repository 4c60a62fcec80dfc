#include "tmop/target/target.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tmop/element/ideal_element.h"
#include "tmop/element/shape.h"
#include "tmop/mesh/topology.h"

namespace tmop {
namespace {

struct NameOf {
  TargetType type;
  const char* name;
};
const NameOf kNames[] = {
    {TargetType::kIdealUnitSize, "ideal_unit"},  {TargetType::kIdealEqualSize, "equal_size"},
    {TargetType::kIdealLocalSize, "local_size"}, {TargetType::kIdealSizeField, "size_field"},
    {TargetType::kReference, "reference"},       {TargetType::kMeanEdgeLength, "lambda_identity"},
    {TargetType::kComposed, "composed"},
};

double det(const double* A, int d) {
  if (d == 2) return A[0] * A[3] - A[1] * A[2];
  return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
         A[2] * (A[3] * A[7] - A[4] * A[6]);
}

void gather(const Mesh& mesh, int c, double* x) {
  const int n = mesh.cell_size(c), sd = mesh.space_dim;
  const std::int32_t* nodes = mesh.cell(c);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < sd; ++a) x[i * sd + a] = mesh.vertex(nodes[i])[a];
}

// det of A for d x d, or the area / volume scale sqrt(det(A^T A)) of a 3 x 2 surface Jacobian.
double measure_det(const double* A, int space_dim, int d) {
  if (space_dim == d) return det(A, d);
  double g11 = 0, g12 = 0, g22 = 0;
  for (int c = 0; c < 3; ++c) {
    g11 += A[c * 2] * A[c * 2];
    g12 += A[c * 2] * A[c * 2 + 1];
    g22 += A[c * 2 + 1] * A[c * 2 + 1];
  }
  return std::sqrt(std::max(0.0, g11 * g22 - g12 * g12));
}

// The 2 x 2 R of A = Q R (QR of a 3 x 2 surface Jacobian): the same lengths and angles as A in
// the cell's own plane, so a reference target on a surface keeps its shape and size.
void surface_reference(const double* A, double* W) {
  double l1 = 0, dot = 0;
  for (int c = 0; c < 3; ++c) {
    l1 += A[c * 2] * A[c * 2];
    dot += A[c * 2] * A[c * 2 + 1];
  }
  l1 = std::sqrt(l1);
  W[0] = l1;
  W[1] = l1 > 0 ? dot / l1 : 0;
  W[2] = 0;
  W[3] = l1 > 0 ? measure_det(A, 3, 2) / l1 : 0;
}

}  // namespace

bool reference_matches(const Mesh& a, const Mesh& b) {
  return a.num_vertices() == b.num_vertices() && a.space_dim == b.space_dim &&
         a.cell_types == b.cell_types && a.cell_nodes == b.cell_nodes;
}

bool target_type_from_name(const std::string& name, TargetType* type) {
  for (const NameOf& n : kNames)
    if (name == n.name) {
      *type = n.type;
      return true;
    }
  return false;
}

const char* target_type_name(TargetType type) {
  for (const NameOf& n : kNames)
    if (n.type == type) return n.name;
  return "?";
}

double cell_equivalent_edge(const Mesh& mesh, int c) {
  const CellType t = mesh.cell_type(c);
  const int d = cell_dim(t);
  double x[kMaxCellNodes * 3], A[9];
  gather(mesh, c, x);
  double volume = 0;
  for (const SamplePoint& p : sample_points(t, SampleRule::kGauss)) {
    cell_jacobian(t, x, mesh.space_dim, p.xi, A);
    volume += p.weight * measure_det(A, mesh.space_dim, d);
  }
  volume *= reference_volume(t);
  const double h = std::pow(std::abs(volume) / ideal_volume(t), 1.0 / d);
  return volume < 0 ? -h : h;
}

double mean_equivalent_edge(const Mesh& mesh) {
  const int d = mesh.dim();
  double sum = 0;
  int n = 0;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (mesh.is_element(c, d)) {
      sum += std::abs(cell_equivalent_edge(mesh, c));
      ++n;
    }
  return n ? sum / n : 1.0;
}

void target_jacobian(const Mesh& mesh, int c, const double* xi, double* A) {
  const CellType t = mesh.cell_type(c);
  double x[kMaxCellNodes * 3];
  gather(mesh, c, x);
  cell_jacobian(t, x, mesh.space_dim, xi, A);
  if (mesh.space_dim != cell_dim(t)) {
    double a[6];
    std::copy(A, A + 6, a);
    surface_reference(a, A);
  }
}

SampleSet canonical_sample_set(const Mesh& mesh, SampleRule rule) {
  SampleSet set;
  const int d = mesh.dim();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d)) continue;
    for (const SamplePoint& p : sample_points(mesh.cell_type(c), rule)) set.add(c, p.xi, p.weight);
  }
  return set;
}

Status build_targets(const Mesh& mesh, SampleRule rule, const TargetSpec& spec,
                     std::vector<double>* W) {
  return build_targets(mesh, canonical_sample_set(mesh, rule), spec, W);
}

Status build_targets(const Mesh& mesh, const SampleSet& points, const TargetSpec& spec,
                     std::vector<double>* W) {
  const int d = mesh.dim();
  if (d < 2) return Status::Failure("targets need a mesh of 2D or 3D elements");
  if (mesh.space_dim != d && d != 2)
    return Status::Failure("targets: elements of dimension " + std::to_string(d) + " in " +
                           std::to_string(mesh.space_dim) + "D space");
  const Mesh& ref = spec.reference ? *spec.reference : mesh;
  if ((spec.type == TargetType::kReference || spec.type == TargetType::kComposed) &&
      !reference_matches(mesh, ref))
    return Status::Failure("reference mesh: its vertices and cells do not match the mesh's");
  if (spec.type == TargetType::kComposed) return build_composed_targets(mesh, points, spec, W);
  if (!spec.cell_scale.empty() && static_cast<int>(spec.cell_scale.size()) != mesh.num_cells())
    return Status::Failure("targets: cell_scale needs one factor per cell");
  if (!(spec.frame.length > 0) || !std::isfinite(spec.frame.length))
    return Status::Failure("target frame: the length scale must be positive");

  // One size for the whole mesh where the target asks for it.
  double h_all = 1.0;
  if (spec.type == TargetType::kIdealEqualSize) {
    h_all = mean_equivalent_edge(mesh);
  } else if (spec.type == TargetType::kMeanEdgeLength) {
    const auto edges = mesh_edges(mesh);
    double sum = 0;
    for (const auto& e : edges) {
      double l2 = 0;
      for (int a = 0; a < mesh.space_dim; ++a) {
        const double t = mesh.vertex(e[1])[a] - mesh.vertex(e[0])[a];
        l2 += t * t;
      }
      sum += std::sqrt(l2);
    }
    h_all = edges.empty() ? 1.0 : sum / edges.size();
  }
  const DataArray* field = nullptr;
  if (spec.type == TargetType::kIdealSizeField) {
    for (const DataArray& a : mesh.point_data)
      if (a.name == spec.size_field && a.components == 1) field = &a;
    if (!field)
      return Status::Failure("size field '" + spec.size_field +
                             "': no 1-component point data array of that name");
  }
  if (!(h_all > 0) || !std::isfinite(h_all))
    return Status::Failure("target size is not positive (degenerate mesh?)");

  std::vector<double> out;
  out.reserve(points.size() * d * d);
  double N[kMaxCellNodes];
  int cached_cell = -1;
  double h_cell = h_all, ideal[9];
  for (std::size_t p = 0; p < points.size(); ++p) {
    const int c = points.cell[p];
    const double* xi = &points.xi[3 * p];
    const CellType t = mesh.cell_type(c);
    if (c != cached_cell) {
      cached_cell = c;
      ideal_jacobian(t, ideal);
      if (spec.type == TargetType::kIdealLocalSize) {
        h_cell = std::abs(cell_equivalent_edge(mesh, c));
        if (!(h_cell > 0))
          return Status::Failure("cell " + std::to_string(c) + ": zero volume, no local size");
      }
    }
    double w[9];
    if (spec.type == TargetType::kReference) {
      target_jacobian(ref, c, xi, w);
      if (!spec.cell_scale.empty())
        for (int i = 0; i < d * d; ++i) w[i] *= spec.cell_scale[c];
      const double dw = det(w, d);
      if (!(std::abs(dw) > 0) || !std::isfinite(dw))
        return Status::Failure("cell " + std::to_string(c) +
                               ": reference Jacobian is singular at a sample point");
    } else {
      double h = h_cell;
      if (field) {
        shape_values(t, xi, N);
        h = 0;
        for (int i = 0; i < mesh.cell_size(c); ++i) h += N[i] * field->values[mesh.cell(c)[i]];
        h /= spec.frame.length;  // user units -> the mesh's
        if (!(h > 0) || !std::isfinite(h))
          return Status::Failure("size field '" + spec.size_field +
                                 "' is not positive and finite in cell " + std::to_string(c));
      }
      for (int i = 0; i < d * d; ++i) w[i] = h * ideal[i];
    }
    out.insert(out.end(), w, w + d * d);
  }
  W->swap(out);
  return Status::Ok();
}

}  // namespace tmop
