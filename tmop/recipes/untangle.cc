#include "tmop/recipes/untangle.h"

#include <algorithm>
#include <chrono>
#include <cstdint>

#include "tmop/element/bezier.h"
#include "tmop/element/sample_points.h"
#include "tmop/mesh/topology.h"
#include "tmop/metric/untangle.h"
#include "tmop/quality/cell_quality.h"
#include "tmop/quality/count_inverted.h"
#include "tmop/quality/element_scan.h"
#include "tmop/quality/jacobian_certificate.h"
#include "tmop/quality/quality_options.h"
#include "tmop/recipes/quadratic_curving.h"

namespace tmop {
namespace {

std::string cell_list(const std::vector<int>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size() && i < 10; ++i)
    s += (i ? ", " : "") + std::to_string(cells[i]);
  if (cells.size() > 10) s += ", ... (" + std::to_string(cells.size()) + " in all)";
  return s;
}

// The cells tmop_quality (compute_quality, count_inverted) counts as inverted: det J <= 0 at a
// corner or default sample point, and tri6 / tet10 whose Bernstein bound cannot prove det J > 0.
std::vector<int> quality_inverted_cells(const Mesh& mesh) {
  QualityOptions options;
  options.angles = false;
  options.threads = 1;  // the callback appends in cell order
  std::vector<int> cells;
  scan_elements(mesh, options, [&](std::int64_t, std::int64_t c, const CellQuality& q) {
    if (q.inverted) cells.push_back(static_cast<int>(c));
  });
  return cells;
}

// The failure line of an untangling that ends with inverted cells, counted as tmop_quality
// counts them (so that it agrees with the tool's counts), with what would help. at_points: the
// cells the stage left inverted at its sample points (null: the input was returned instead).
// fixed: the vertices that could not move (empty: none reported); boundary_fixed: they are the
// default fixed boundary, which sliding would release.
std::string still_inverted_message(const Mesh& mesh, const StageResult& stage,
                                   const std::vector<int>* at_points,
                                   const std::vector<char>& fixed, bool boundary_fixed) {
  std::vector<int> all = quality_inverted_cells(mesh);
  const std::size_t by_quality = all.size();
  if (at_points)
    for (int c : *at_points)
      if (!std::binary_search(all.begin(), all.begin() + by_quality, c)) all.push_back(c);
  std::sort(all.begin(), all.end());
  const int n = static_cast<int>(all.size());
  std::string text = "could not untangle in " + std::to_string(stage.solves) + " eps rounds (" +
                     std::to_string(stage.iterations) + " iterations): " + std::to_string(n) +
                     (n == 1 ? " cell" : " cells") + " still inverted";
  if (at_points && static_cast<int>(at_points->size()) != n)
    text += " (" + std::to_string(at_points->size()) + " with det J <= 0 at a sample point, " +
            std::to_string(n - static_cast<int>(at_points->size())) +
            " more by the Bernstein certificate of det J)";
  text += ": " + cell_list(all);
  if (!at_points) text += "; the input is returned (the untangling ended with more)";
  int at_fixed = 0;
  if (!fixed.empty())
    for (int c : all) {
      bool touches = false;
      for (int i = 0; i < mesh.cell_size(c) && !touches; ++i) touches = fixed[mesh.cell(c)[i]];
      at_fixed += touches;
    }
  if (at_fixed > 0) {
    text +=
        "; " + std::to_string(at_fixed) + " of them " + (at_fixed == 1 ? "has" : "have") +
        (boundary_fixed ? " nodes on the fixed boundary: try --boundary=slide" : " fixed nodes");
  }
  return text;
}

bool has_certificate(CellType t) { return t == CellType::kTri6 || t == CellType::kTet10; }

// Certifies every tri6 / tet10 element; for each cell not proven valid, adds the lattice points
// of its non-positive Bernstein coefficients to `extra` (once per point). Returns the number of
// cells with a certificate; fills `uncertified` and `inverted` (proven inverted).
int certify(const Mesh& mesh, SampleSet* extra, std::vector<int>* uncertified,
            std::vector<int>* inverted) {
  uncertified->clear();
  inverted->clear();
  const int d = mesh.dim();
  int count = 0;
  double x[kMaxCellNodes * 3], coef[kMaxBezierCoefficients];
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (!mesh.is_element(c, d) || !has_certificate(mesh.cell_type(c))) continue;
    ++count;
    const CellType t = mesh.cell_type(c);
    const int n = mesh.cell_size(c);
    if (mesh.space_dim == d) {
      for (int i = 0; i < n; ++i)
        for (int a = 0; a < d; ++a) x[i * d + a] = mesh.vertex(mesh.cell(c)[i])[a];
    } else {  // a surface cell: in its own plane, as tmop_quality certifies it
      double nodes[kMaxCellNodes * 3];
      for (int i = 0; i < n; ++i)
        for (int a = 0; a < 3; ++a) nodes[i * 3 + a] = mesh.vertex(mesh.cell(c)[i])[a];
      cell_plane_coordinates(t, nodes, nullptr, x);
    }
    // The depth tmop_quality uses, so that both report the same cells as proven.
    const JacobianSign sign = certify_jacobian(t, x, QualityOptions().bezier_subdivision);
    if (sign == JacobianSign::kPositive) continue;
    uncertified->push_back(c);
    if (sign == JacobianSign::kNonPositive) inverted->push_back(c);
    const int m = jacobian_bezier_coefficients(t, x, coef);
    const double weight = 1.0 / sample_points(t, SampleRule::kDefault).size();
    for (int k = 0; k < m; ++k) {
      if (coef[k] > 0) continue;
      double xi[3] = {0, 0, 0};
      jacobian_bezier_point(t, k, xi);
      bool seen = false;
      for (std::size_t e = 0; e < extra->size() && !seen; ++e)
        seen = extra->cell[e] == c && extra->xi[3 * e] == xi[0] && extra->xi[3 * e + 1] == xi[1] &&
               extra->xi[3 * e + 2] == xi[2];
      if (!seen) extra->add(c, xi, weight);
    }
  }
  return count;
}

}  // namespace

Status untangle(Mesh* mesh, const UntangleOptions& options, RecipeResult* result) {
  const auto start = std::chrono::steady_clock::now();
  *result = RecipeResult();
  result->recipe = options.improve_shape_after ? "auto" : "untangle";
  const int d = mesh->dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements");
  if (!(options.sigma_min > 0 && options.sigma_min < 1))
    return Status::Failure("untangle options: sigma_min must lie in (0, 1)");
  result->before = measure_mesh(*mesh, options.rule);
  const std::vector<double> input_coords = mesh->coords;
  const std::int64_t inverted_at_start = count_inverted(*mesh, options.solver.threads);
  auto finish = [&]() {
    result->after = measure_mesh(*mesh, options.rule);
    result->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };

  RecipeGeometry own;
  const RecipeGeometry* geometry = nullptr;
  Status gs = resolve_recipe_geometry(*mesh, options.slide, options.boundary, options.geometry,
                                      &own, &geometry);
  if (!gs.ok()) return gs;
  SampleSet extra;
  std::vector<int> uncertified, proven_inverted;
  int with_certificate = 0;
  if (options.certify) with_certificate = certify(*mesh, &extra, &uncertified, &proven_inverted);
  const int rounds = options.certify && with_certificate > 0 ? 1 + options.certify_rounds : 1;
  for (int round = 0; round < rounds; ++round) {
    StageSpec stage;
    stage.name =
        round == 0 ? "untangle" : "untangle (certification round " + std::to_string(round) + ")";
    stage.rule = options.rule;
    stage.extra_points = extra;
    stage.fixed = options.fixed;
    stage.solver = options.solver;
    stage.untangle = true;
    if (geometry) geometry->apply(&stage);
    stage.untangle_max_rounds = options.max_rounds;
    stage.untangle_round_iterations = options.round_iterations;
    stage.untangle_patience = options.patience;
    stage.untangle_spread_rounds = options.spread_rounds;
    stage.untangle_sigma_min = options.sigma_min;
    TermSpec term;
    try {
      term.metric = std::make_shared<UntangleMetric>(d, options.initial_eps, options.theta);
    } catch (const std::exception& e) {
      return Status::Failure(std::string("untangle options: ") + e.what());
    }
    term.target = options.target;
    stage.terms.push_back(term);
    StageResult sr;
    Status s = optimize_stage(mesh, stage, &sr);
    if (!s.ok()) return s;
    if (sr.solves > 0) result->stages.push_back(sr);
    if (options.solver.progress.cancelled()) {
      // Stopped mid-schedule: the stage kept its best state; never more inverted than the input.
      if (count_inverted(*mesh, options.solver.threads) > inverted_at_start)
        mesh->coords = input_coords;
      finish();
      return Status::Cancelled("untangle: cancelled");
    }
    if (!sr.inverted_cells.empty()) {
      // Never more inverted cells than the input had, as tmop_quality counts them (the stage
      // keeps its best round by its own sample points, which can differ for quadratic cells).
      const bool restore = count_inverted(*mesh, options.solver.threads) > inverted_at_start;
      if (restore) mesh->coords = input_coords;
      finish();
      const bool boundary_fixed = options.fixed.empty() && !geometry;
      return Status::Failure(still_inverted_message(
          *mesh, sr, restore ? nullptr : &sr.inverted_cells,
          boundary_fixed ? boundary_vertex_mask(*mesh) : options.fixed, boundary_fixed));
    }
    if (options.improve_shape_after) {
      ShapeOptions shape = options.shape;
      shape.fixed = options.fixed;
      shape.extra_points = extra;
      shape.geometry = geometry;
      // Quadratic cells: the curvature the untangler put where no cell needs it is taken back
      // first (quadratic_curving.h), so the shape stage's baseline is the re-curved mesh.
      if (sr.solves > 0) {
        RecipeResult curving;
        curve_untangled_nodes(mesh, shape, &curving);
        for (StageResult& st : curving.stages) {
          st.name += " after untangling";
          result->stages.push_back(std::move(st));
        }
      }
      // The caller's baseline is of the input: it serves only if untangling moved nothing.
      if (mesh->coords != input_coords) shape.input_baseline = nullptr;
      RecipeResult shape_result;
      s = improve_shape(mesh, shape, &shape_result);
      if (!s.ok()) return s;
      for (StageResult& st : shape_result.stages) result->stages.push_back(std::move(st));
      result->layer_cells = shape_result.layer_cells;
      result->held_vertices = shape_result.held_vertices;
      result->guard_held_cells = shape_result.guard_held_cells;
      if (shape.solver.progress.cancelled()) {
        finish();
        return Status::Cancelled("shape: cancelled");
      }
    }
    if (!options.certify || with_certificate == 0) break;
    const std::size_t points_before = extra.size();
    certify(*mesh, &extra, &uncertified, &proven_inverted);
    if (uncertified.empty() || extra.size() == points_before) break;
  }
  if (options.certify && with_certificate > 0) {
    result->certified = with_certificate - static_cast<int>(uncertified.size());
    result->uncertified = static_cast<int>(uncertified.size());
    result->uncertified_cells = uncertified;
  }
  finish();
  if (!proven_inverted.empty())
    return Status::Failure(std::to_string(proven_inverted.size()) +
                           " quadratic cells are inverted between their sample points "
                           "(Bernstein certificate): " +
                           cell_list(proven_inverted));
  // A quadratic cell whose Bernstein bound stays non-positive after every certification round
  // is not known to be valid: the recipe promises certified output, so that is a failure.
  if (!uncertified.empty())
    return Status::Failure(std::to_string(uncertified.size()) + " of " +
                           std::to_string(with_certificate) +
                           " quadratic cells could not be certified valid (Bernstein bound of "
                           "det J) after " +
                           std::to_string(options.certify_rounds) +
                           " certification rounds: " + cell_list(uncertified));
  return Status::Ok();
}

}  // namespace tmop
