#include "tmop/recipes/laplace.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "tmop/element/ideal_element.h"
#include "tmop/element/shape.h"
#include "tmop/geometry/geometry_manifold.h"
#include "tmop/mesh/topology.h"
#include "tmop/metric/small_matrix.h"
#include "tmop/optimize/stage.h"

namespace tmop {
namespace {

// W^-1 of each cell type's ideal element, computed once per run.
struct IdealInverses {
  double inv[kNumCellTypes][9];
  explicit IdealInverses(int d) {
    for (int t = 0; t < kNumCellTypes; ++t) {
      const CellType type = static_cast<CellType>(t);
      if (cell_dim(type) != d) continue;
      double W[9], C[9];
      ideal_jacobian(type, W);
      double det;
      if (d == 2) {
        small_matrix::cofactor<2>(W, C);
        det = small_matrix::det<2>(W);
      } else {
        small_matrix::cofactor<3>(W, C);
        det = small_matrix::det<3>(W);
      }
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) inv[t][d * i + j] = C[d * j + i] / det;  // cof^T / det
    }
  }
};

// The cell's worst shape quality over the rule's points; a non-positive det T returns det T
// itself (<= 0), so "worse" keeps its meaning for cells that are already inverted.
double cell_worst_quality(const Mesh& mesh, int c, SampleRule rule, const IdealInverses& ideal) {
  const CellType type = mesh.cell_type(c);
  const int d = mesh.space_dim;
  double x[kMaxCellNodes * 3];
  const std::int32_t* nodes = mesh.cell(c);
  for (int i = 0; i < mesh.cell_size(c); ++i)
    for (int a = 0; a < d; ++a) x[d * i + a] = mesh.vertex(nodes[i])[a];
  const double* Winv = ideal.inv[static_cast<int>(type)];
  double worst = std::numeric_limits<double>::infinity();
  for (const SamplePoint& p : sample_points(type, rule)) {
    double A[9], T[9];
    cell_jacobian(type, x, d, p.xi, A);
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) {
        double s = 0;
        for (int k = 0; k < d; ++k) s += A[d * i + k] * Winv[d * k + j];
        T[d * i + j] = s;
      }
    const double det = d == 2 ? small_matrix::det<2>(T) : small_matrix::det<3>(T);
    double q = det;
    if (det > 0) {
      const double f2 = d == 2 ? small_matrix::frobenius2<2>(T) : small_matrix::frobenius2<3>(T);
      q = d * std::pow(det, 2.0 / d) / f2;
    }
    worst = std::min(worst, q);
  }
  return worst;
}

}  // namespace

Status laplace(Mesh* mesh, const LaplaceOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = "laplace";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  if (mesh->space_dim != d)
    return Status::Failure("laplace: surface meshes (2D cells in 3D) need a geometry");
  for (int c = 0; c < mesh->num_cells(); ++c)
    if (mesh->is_element(c, d) && cell_info(mesh->cell_type(c)).order > 1)
      return Status::Failure("laplace: quadratic elements are not supported (cell " +
                             std::to_string(c) + " is " + cell_name(mesh->cell_type(c)) + ")");
  std::vector<char> fixed = options.fixed;
  std::unique_ptr<BoundaryConstraints> geometry;
  if (options.slide) {
    Status g = BoundaryConstraints::Build(*mesh, options.boundary, &geometry);
    if (!g.ok()) return g;
    const std::vector<char> corners = geometry->fixed_flags();
    if (fixed.empty()) fixed.assign(mesh->num_vertices(), 0);
    for (std::size_t v = 0; v < fixed.size() && v < corners.size(); ++v) fixed[v] |= corners[v];
  }
  if (fixed.empty()) fixed = boundary_vertex_mask(*mesh);
  if (static_cast<int>(fixed.size()) != mesh->num_vertices())
    return Status::Failure("laplace: fixed-vertex flags: one per vertex expected");
  mark_periodic_vertices(*mesh, &fixed);  // as every stage does (optimize/stage_spec.cc)
  if (options.max_sweeps < 0 || !(options.tolerance >= 0))
    return Status::Failure("laplace: max_sweeps and tolerance must be >= 0");
  result->before = measure_mesh(*mesh, options.rule);

  // Edge neighbours in compressed rows.
  const int nv = mesh->num_vertices();
  const auto edges = mesh_edges(*mesh);
  std::vector<std::int64_t> offsets(nv + 1, 0);
  for (const auto& e : edges) ++offsets[e[0] + 1], ++offsets[e[1] + 1];
  for (int v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  std::vector<std::int32_t> neighbours(offsets[nv]);
  {
    std::vector<std::int64_t> next(offsets.begin(), offsets.end() - 1);
    for (const auto& e : edges) {
      neighbours[next[e[0]]++] = e[1];
      neighbours[next[e[1]]++] = e[0];
    }
  }
  const Adjacency cells = vertex_to_cells(*mesh);
  const IdealInverses ideal(d);

  StageResult stage;
  stage.name = "laplace";
  stage.num_elements = mesh->num_elements();
  stage.inverted_before = result->before.inverted;
  stage.min_quality_before = result->before.min_quality;
  for (int v = 0; v < nv; ++v) stage.num_free_vertices += !fixed[v] && offsets[v + 1] > offsets[v];
  stage.termination = "max_sweeps reached";

  for (int sweep = 0; sweep < options.max_sweeps; ++sweep) {
    double max_relative_move = 0;
    int moved = 0;
    for (int v = 0; v < nv; ++v) {
      const std::int64_t b = offsets[v], e = offsets[v + 1];
      if (fixed[v] || e == b) continue;
      double* x = mesh->vertex(v);
      double centroid[3] = {0, 0, 0}, mean_edge = 0;
      for (std::int64_t k = b; k < e; ++k) {
        const double* y = mesh->vertex(neighbours[k]);
        double l2 = 0;
        for (int a = 0; a < d; ++a) {
          centroid[a] += y[a];
          l2 += (y[a] - x[a]) * (y[a] - x[a]);
        }
        mean_edge += std::sqrt(l2);
      }
      mean_edge /= static_cast<double>(e - b);
      double step2 = 0;
      for (int a = 0; a < d; ++a) {
        centroid[a] /= static_cast<double>(e - b);
        step2 += (centroid[a] - x[a]) * (centroid[a] - x[a]);
      }
      const double step = std::sqrt(step2);
      if (!(step > options.tolerance * mean_edge)) continue;

      double worst_before = std::numeric_limits<double>::infinity();
      for (std::int64_t k = cells.offsets[v]; k < cells.offsets[v + 1]; ++k)
        worst_before =
            std::min(worst_before, cell_worst_quality(*mesh, cells.items[k], options.rule, ideal));
      double saved[3];
      for (int a = 0; a < d; ++a) saved[a] = x[a], x[a] = centroid[a];
      if (geometry && geometry->geometry(v)) {  // a sliding vertex: back onto its geometry
        double on[3];
        geometry->geometry(v)->Project(x, on);
        for (int a = 0; a < d; ++a) x[a] = on[a];
      }
      // Accept only moves that keep every incident element valid (q > 0) and do not lower
      // the worst incident quality; an inverted neighbourhood may only improve.
      double worst_after = std::numeric_limits<double>::infinity();
      bool valid = true;
      for (std::int64_t k = cells.offsets[v]; k < cells.offsets[v + 1]; ++k) {
        const double q = cell_worst_quality(*mesh, cells.items[k], options.rule, ideal);
        worst_after = std::min(worst_after, q);
        valid = valid && (q > 0 || worst_before <= 0);
      }
      if (!valid || worst_after < worst_before) {
        for (int a = 0; a < d; ++a) x[a] = saved[a];
        continue;
      }
      ++moved;
      max_relative_move = std::max(max_relative_move, step / mean_edge);
    }
    stage.iterations = sweep + 1;
    IterationRecord rec = measure_mesh(*mesh, options.rule);
    rec.iteration = sweep + 1;
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stage.history.push_back(rec);
    if (options.progress) {
      ProgressRecord p;
      static_cast<IterationRecord&>(p) = rec;
      p.stage = stage.name;
      if (!options.progress(p)) {
        stage.termination = "cancelled by the progress callback";
        break;
      }
    }
    if (moved == 0 || max_relative_move < options.tolerance) {
      stage.termination = "no vertex moved more than tolerance x its mean edge length";
      break;
    }
  }
  result->after = measure_mesh(*mesh, options.rule);
  stage.inverted_after = result->after.inverted;
  stage.min_quality_after = result->after.min_quality;
  result->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stage.seconds = result->seconds;
  stage.solves = 0;
  stage.linear_solver = "none";
  result->stages.push_back(stage);
  if (options.progress.cancelled()) return Status::Cancelled("laplace: cancelled");
  return Status::Ok();
}

}  // namespace tmop
