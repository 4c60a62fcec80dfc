// tmop/optimize/stage_spec.cc
#include "tmop/optimize/stage_spec.h"

#include <cmath>
#include <string>

#include "tmop/geometry/boundary_constraints.h"
#include "tmop/mesh/topology.h"
#include "tmop/metric/metric.h"
#include "tmop/optimize/sample_point_cost.h"

namespace tmop {

bool solver_method_from_name(const std::string& name, SolverOptions::Method* method) {
  if (name == "lm")
    *method = SolverOptions::Method::kLevenbergMarquardt;
  else if (name == "dogleg")
    *method = SolverOptions::Method::kDogleg;
  else
    return false;
  return true;
}

bool linear_solver_from_name(const std::string& name, SolverOptions::LinearSolver* solver) {
  if (name == "auto")
    *solver = SolverOptions::LinearSolver::kAuto;
  else if (name == "cholesky")
    *solver = SolverOptions::LinearSolver::kSparseCholesky;
  else if (name == "cgnr")
    *solver = SolverOptions::LinearSolver::kCgnr;
  else
    return false;
  return true;
}

Status check_stage_spec(const Mesh& mesh, const StageSpec& spec) {
  const int d = mesh.dim();
  if (d < 2) return Status::Failure("the mesh has no 2D or 3D elements to optimize");
  const bool surface = mesh.space_dim != d;
  if (surface && (d != 2 || !spec.boundary))
    return Status::Failure("surface meshes (2D cells in 3D) need a geometry (recipe surface)");
  if (spec.boundary && spec.boundary->num_vertices() != mesh.num_vertices())
    return Status::Failure("boundary constraints were built for another mesh");
  if (spec.terms.empty() || spec.terms.size() > static_cast<std::size_t>(kMaxTerms))
    return Status::Failure("a stage needs 1 or 2 metric terms");
  for (const TermSpec& t : spec.terms) {
    if (!t.metric) return Status::Failure("a metric term has no metric");
    if (t.metric->dim() != d)
      return Status::Failure("metric " + t.metric->name() + " is " +
                             std::to_string(t.metric->dim()) + "D but the mesh is " +
                             std::to_string(d) + "D");
  }
  for (double x : mesh.coords)
    if (!std::isfinite(x)) return Status::Failure("the mesh has a non-finite coordinate");
  if (!(std::isfinite(spec.power) && spec.power >= 1))
    return Status::Failure("the power-mean order p must be finite and >= 1");
  if (!(std::isfinite(spec.power_scale_fraction) && spec.power_scale_fraction > 0))
    return Status::Failure("the power objective's scale fraction must be finite and > 0");
  if (!(spec.power_model_cutoff > 0))
    return Status::Failure("the power objective's model cutoff must be > 0");
  if (!(spec.untangle_sigma_min > 0 && spec.untangle_sigma_min < 1))
    return Status::Failure("untangling: sigma_min must lie in (0, 1)");
  // Ceres's dogleg needs a factorisation: under kAuto it always gets sparse Cholesky (below).
  const bool dogleg = spec.solver.method == SolverOptions::Method::kDogleg;
  if (dogleg && spec.solver.linear_solver == SolverOptions::LinearSolver::kCgnr)
    return Status::Failure(
        "the dogleg method needs sparse Cholesky (Ceres's dogleg cannot use CGNR): use the lm "
        "method with CGNR, or the cholesky or auto linear solver");
  return Status::Ok();
}

Status stage_fixed_vertices(const Mesh& mesh, const StageSpec& spec, std::vector<char>* out) {
  std::vector<char>& fixed = *out;
  fixed = spec.fixed;
  if (spec.boundary) {
    const std::vector<char> corners = spec.boundary->fixed_flags();
    if (fixed.empty()) fixed.assign(mesh.num_vertices(), 0);
    for (std::size_t v = 0; v < fixed.size() && v < corners.size(); ++v) fixed[v] |= corners[v];
  }
  if (fixed.empty()) fixed = boundary_vertex_mask(mesh);
  if (static_cast<int>(fixed.size()) != mesh.num_vertices())
    return Status::Failure("fixed-vertex flags: one per vertex expected");
  // Periodic vertices (Mesh::periodic) stay where they are: moving one side of a link without
  // its image would break the periodicity the file declares.
  mark_periodic_vertices(mesh, &fixed);
  return Status::Ok();
}

}  // namespace tmop
