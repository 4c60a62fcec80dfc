#include "tmop/optimize/partitioned_stage.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <thread>

#include "tmop/optimize/part_exchange.h"
#include "tmop/optimize/part_solve.h"
#include "tmop/partition/partition.h"
#include "tmop/quality/parallel_for.h"

namespace tmop {

int stage_num_parts(const Mesh& mesh, const StageSpec& spec) {
  const SolverOptions& so = spec.solver;
  if (spec.untangle || mesh.space_dim != mesh.dim()) return 1;
  const std::int64_t elements = mesh.num_elements();
  // At least kMinPartElements elements per part: smaller parts only add cut work.
  constexpr std::int64_t kMinPartElements = 64;
  std::int64_t parts = 1;
  if (so.partitions > 0)
    parts = so.partitions;
  else if (so.part_size > 0 && elements >= 2 * static_cast<std::int64_t>(so.part_size))
    parts = (elements + so.part_size - 1) / so.part_size;
  parts = std::min(parts, elements / kMinPartElements);
  return static_cast<int>(std::max<std::int64_t>(1, parts));
}

bool use_partitions(const Mesh& mesh, const StageSpec& spec) {
  return stage_num_parts(mesh, spec) >= 2;
}

namespace {

using Pieces = std::vector<std::vector<int>>;  // per part: its free vertices, ascending

// Candidate vertices grouped by the part that holds all their elements; those with elements in
// several parts are flagged in *cut_out (when given) and left out.
Pieces pieces_of(const Mesh& mesh, const VertexCells& vc, const std::vector<int>& part,
                 int num_parts, const std::vector<char>& candidate, std::vector<char>* cut) {
  Pieces pieces(num_parts);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!candidate[v] || vc.count(v) == 0) continue;
    const int p = part[*vc.begin(v)];
    bool inside = true;
    for (const std::int32_t* c = vc.begin(v); c != vc.end(v) && inside; ++c) inside = part[*c] == p;
    if (inside)
      pieces[p].push_back(v);
    else if (cut)
      (*cut)[v] = 1;
  }
  pieces.erase(std::remove_if(pieces.begin(), pieces.end(),
                              [](const std::vector<int>& p) { return p.empty(); }),
               pieces.end());
  return pieces;
}

// Marks the vertices within `rings` rings of elements around the vertices that moved after
// phase run `since` (moved_at: per vertex, the last phase run that changed its coordinates).
std::vector<char> near_moved(const Mesh& mesh, const VertexCells& vc,
                             const std::vector<int>& moved_at, int since, int rings) {
  const int n = mesh.num_vertices();
  std::vector<char> mark(n, 0);
  std::vector<int> front;
  for (int v = 0; v < n; ++v)
    if (moved_at[v] > since) {
      mark[v] = 1;
      front.push_back(v);
    }
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int v : front)
      for (const std::int32_t* c = vc.begin(v); c != vc.end(v); ++c)
        for (int i = 0; i < mesh.cell_size(*c); ++i) {
          const int u = mesh.cell(*c)[i];
          if (!mark[u]) {
            mark[u] = 1;
            next.push_back(u);
          }
        }
    front.swap(next);
  }
  return mark;
}

// The pieces' vertices that `keep` marks, empty pieces dropped. Solving only near what moved
// is an approximation (the far vertices' optimum moves a little too), so a piece is restricted
// only where that at least halves its vertices; otherwise it is solved whole again.
Pieces restrict_pieces(const Pieces& pieces, const std::vector<char>& keep) {
  Pieces out;
  for (const std::vector<int>& p : pieces) {
    std::vector<int> q;
    for (int v : p)
      if (keep[v]) q.push_back(v);
    if (2 * q.size() > p.size())
      out.push_back(p);
    else if (!q.empty())
      out.push_back(std::move(q));
  }
  return out;
}

struct PhaseTotals {
  double initial_cost = 0, final_cost = 0;
  int parts = 0, vertices = 0, min_iterations = 0, max_iterations = 0;
};

// Solves the pieces of one phase side by side on `threads` workers (largest first); each reads
// the coordinates of the phase's start. Outcomes are summed in piece order: the totals do not
// depend on the threads.
// moved_at (when given): the vertices the phase changed get `stamp`.
Status run_phase(Mesh* mesh, const StageContext& ctx, const IdealTable& table,
                 const VertexCells& vc, const CellPoints& cp, const Pieces& pieces, int threads,
                 double seconds, double function_tolerance, std::vector<PartScratch>* scratch,
                 StageResult* result, PhaseTotals* totals, std::vector<int>* moved_at, int stamp) {
  const std::vector<double> start = mesh->coords;
  std::vector<PartOutcome> outcomes(pieces.size());
  std::vector<int> order(pieces.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return pieces[a].size() > pieces[b].size(); });
  // With an exchange, this process solves its share: the parts dealt to the ranks in turn,
  // largest first, back and forth (rank 0 1 ... R-1 R-1 ... 0 ...), so the shares are even.
  PartExchange* exchange = ctx.spec->solver.exchange;
  const int ranks = exchange ? exchange->size() : 1, me = exchange ? exchange->rank() : 0;
  std::vector<int> owner(pieces.size(), 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int round = static_cast<int>(k) / ranks, at = static_cast<int>(k) % ranks;
    owner[order[k]] = round % 2 == 0 ? at : ranks - 1 - at;
  }
  std::vector<int> mine;
  for (int i : order)
    if (owner[i] == me) mine.push_back(i);
  std::atomic<std::size_t> next{0};
  // After a cancel no worker starts another part: the parts not solved stay at the phase's
  // start (each part moves only its own vertices, so the mix is a state a phase can leave).
  const ProgressCallback& progress = ctx.spec->solver.progress;
  auto work = [&](int w) {
    for (std::size_t k = next++; k < mine.size(); k = next++) {
      if (progress.cancelled()) break;
      const int i = mine[k];
      outcomes[i] = solve_part(*mesh, start, ctx, table, vc, cp, pieces[i], seconds,
                               function_tolerance, &(*scratch)[w], &mesh->coords);
    }
  };
  const int workers = std::max(1, std::min<int>(threads, static_cast<int>(mine.size())));
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  for (std::thread& t : pool) t.join();
  if (exchange) {
    const Status s = exchange->share(pieces, owner, mesh->space_dim, &outcomes, &mesh->coords);
    if (!s.ok()) return s;
  }
  if (moved_at) {
    const int sd = mesh->space_dim;
    for (const std::vector<int>& p : pieces)
      for (int v : p)
        if (!std::equal(mesh->vertex(v), mesh->vertex(v) + sd,
                        &start[static_cast<std::size_t>(v) * sd]))
          (*moved_at)[v] = stamp;
  }
  *totals = PhaseTotals();
  totals->parts = static_cast<int>(pieces.size());
  for (const std::vector<int>& p : pieces) totals->vertices += static_cast<int>(p.size());
  totals->min_iterations = pieces.empty() ? 0 : 1 << 30;
  for (const PartOutcome& o : outcomes) {
    if (!o.ok) return Status::Failure(o.error);
    totals->initial_cost += o.initial_cost;
    totals->final_cost += o.final_cost;
    totals->min_iterations = std::min(totals->min_iterations, o.iterations);
    totals->max_iterations = std::max(totals->max_iterations, o.iterations);
    result->iterations += o.iterations;
    result->part_element_iterations += static_cast<std::int64_t>(o.elements) * o.iterations;
    ++result->solves;
    StageResult::Times& t = result->times;
    t.preprocessor += o.times.preprocessor;
    t.minimizer += o.times.minimizer;
    t.residual_evaluation += o.times.residual_evaluation;
    t.jacobian_evaluation += o.times.jacobian_evaluation;
    t.linear_solver += o.times.linear_solver;
    t.residual_evaluations += o.times.residual_evaluations;
    t.jacobian_evaluations += o.times.jacobian_evaluations;
    t.linear_solves += o.times.linear_solves;
    t.recorded_linear_solves += o.times.recorded_linear_solves;
    t.linear_iterations += o.times.linear_iterations;
  }
  if (result->linear_solver.empty() && !outcomes.empty())
    result->linear_solver = "parts: " + outcomes[order[0]].linear_solver;
  return Status::Ok();
}

}  // namespace

Status solve_partitioned(Mesh* mesh, const StageContext& ctx, const IdealTable& table,
                         std::chrono::steady_clock::time_point start, std::vector<char>* in_problem,
                         StageResult* result, std::string* reason) {
  const StageSpec& spec = *ctx.spec;
  const SolverOptions& so = spec.solver;
  const int d = ctx.d;
  const VertexCells vc = vertex_cells(*mesh);
  const CellPoints cp = cell_points(*mesh, ctx.point_cell);
  // The vertices that can move: free, with an element. Every node of an element with one of
  // them is in the stage's problem.
  std::vector<char> candidate(mesh->num_vertices(), 0);
  for (int v = 0; v < mesh->num_vertices(); ++v) candidate[v] = !ctx.fixed[v] && vc.count(v) > 0;
  for (int c = 0; c < mesh->num_cells(); ++c) {
    if (!mesh->is_element(c, d)) continue;
    bool any = false;
    for (int i = 0; i < mesh->cell_size(c) && !any; ++i) any = candidate[mesh->cell(c)[i]];
    if (any)
      for (int i = 0; i < mesh->cell_size(c); ++i) (*in_problem)[mesh->cell(c)[i]] = 1;
  }
  result->num_free_vertices =
      static_cast<int>(std::count(candidate.begin(), candidate.end(), char(1)));
  if (result->num_free_vertices == 0) return Status::Ok();

  // P1 by the cost of the elements (their sample points); P2 avoids P1's cut vertices.
  std::vector<int> weight(mesh->num_cells(), 0);
  for (int c = 0; c < mesh->num_cells(); ++c)
    weight[c] = static_cast<int>(cp.offset[c + 1] - cp.offset[c]);
  const int num_parts = stage_num_parts(*mesh, spec);
  PartitionOptions popts;
  popts.num_parts = num_parts;
  popts.cell_weight = &weight;
  std::vector<int> part1, part2;
  ElementGraph graph;
  Status s = element_graph(*mesh, &graph, resolve_threads(so.threads));
  if (!s.ok()) return s;
  s = partition_elements(*mesh, graph, popts, &part1);

  if (!s.ok()) return s;
  std::vector<char> cut1(mesh->num_vertices(), 0);
  const Pieces phase_a = pieces_of(*mesh, vc, part1, num_parts, candidate, &cut1);
  // Phase B moves the cut vertices and their neighbours: a cut vertex moves with the ring of
  // elements around it, whose other nodes P1 held inside their parts.
  std::vector<char> band(mesh->num_vertices(), 0);
  for (int v = 0; v < mesh->num_vertices(); ++v) {
    if (!cut1[v]) continue;
    for (const std::int32_t* c = vc.begin(v); c != vc.end(v); ++c)
      for (int i = 0; i < mesh->cell_size(*c); ++i) {
        const int u = mesh->cell(*c)[i];
        band[u] = candidate[u];
      }
  }
  popts.avoid = &cut1;
  popts.seed = 2;
  s = partition_elements(*mesh, graph, popts, &part2);
  if (!s.ok()) return s;
  std::vector<char> cut2(mesh->num_vertices(), 0);
  const Pieces phase_b = pieces_of(*mesh, vc, part2, num_parts, band, &cut2);
  Pieces phase_c(1);
  for (int v = 0; v < mesh->num_vertices(); ++v)
    if (cut2[v]) phase_c[0].push_back(v);
  if (phase_c[0].empty()) phase_c.clear();
  graph = ElementGraph();
  std::vector<int>().swap(part1);
  std::vector<int>().swap(part2);

  const int threads = so.threads > 0
                          ? so.threads
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<PartScratch> scratch(std::max(1, threads));
  for (PartScratch& w : scratch) {
    w.local.assign(mesh->num_vertices(), -1);
    w.mark.assign(mesh->num_cells(), 0);
  }
  result->parts = static_cast<int>(phase_a.size());
  result->times.setup =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool report = so.verbose || static_cast<bool>(so.progress);
  const char* names[3] = {"A", "B", "C"};
  const Pieces* phases[3] = {&phase_a, &phase_b, &phase_c};
  *reason = "max_sweeps reached";
  int record = 0;
  // The solver's objective of the whole stage, kept up to date from the parts' decreases.
  double cost = stage_solver_cost(*mesh, ctx);
  {
    IterationRecord rec;
    rec.solver_objective = 2 * cost / std::max(1, ctx.num_elements);
    rec.min_quality = std::numeric_limits<double>::quiet_NaN();
    rec.inverted = -1;
    result->history.push_back(rec);
  }
  // Which vertices each phase run changed (a counter per run), and each phase's last run: a
  // later sweep re-solves only near what moved since (one int per vertex, not a copy of the
  // coordinates per phase).
  std::vector<int> moved_at(so.sweep_rings > 0 ? mesh->num_vertices() : 0, 0);
  int runs = 0, last_run[3] = {-1, -1, -1};
  bool out_of_time = false;
  // Time limits and cancels are decided by every process together (part_exchange.h).
  const auto agreed = [&so](bool local) {
    return so.exchange ? so.exchange->max_of(local ? 1.0 : 0.0) > 0 : local;
  };
  for (int sweep = 1; sweep <= std::max(1, so.max_sweeps) && !out_of_time; ++sweep) {
    const double sweep_initial = cost;
    double sweep_decrease = 0;
    for (int ph = 0; ph < 3; ++ph) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (agreed(elapsed >= so.max_seconds)) {
        *reason = "time limit reached";
        out_of_time = true;
        break;
      }
      if (phases[ph]->empty()) continue;
      Pieces restricted;
      const Pieces* pieces = phases[ph];
      if (last_run[ph] >= 0 && so.sweep_rings > 0) {
        restricted =
            restrict_pieces(*pieces, near_moved(*mesh, vc, moved_at, last_run[ph], so.sweep_rings));
        pieces = &restricted;
      }
      PhaseTotals totals;
      if (agreed(so.progress.cancelled())) {  // cancelled from another thread during the last phase
        *reason = "cancelled";
        out_of_time = true;
        break;
      }
      if (!pieces->empty()) {
        ++runs;
        // The first sweep's phase A may stop early (SolverOptions::first_sweep_tolerance): what
        // is left near its cuts is B's and C's, and later sweeps revisit it.
        const double ft = sweep == 1 && ph == 0 && so.first_sweep_tolerance > 0
                              ? std::max(so.first_sweep_tolerance, so.function_tolerance)
                              : so.function_tolerance;
        s = run_phase(mesh, ctx, table, vc, cp, *pieces, threads, so.max_seconds - elapsed, ft,
                      &scratch, result, &totals, so.sweep_rings > 0 ? &moved_at : nullptr, runs);
        if (!s.ok()) return s;
      }
      last_run[ph] = runs;
      sweep_decrease += totals.initial_cost - totals.final_cost;
      IterationRecord rec;
      rec.iteration = ++record;
      // Elements outside the phase's parts did not change: the decrease is the stage's.
      rec.solver_objective = 2 * (sweep_initial - sweep_decrease) / std::max(1, ctx.num_elements);
      rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (report) {
        IterationRecord m;
        side_by_side(
            so.threads != 1, [&] { m = measure(*mesh, table, ctx.frames); },
            [&] { rec.objective = stage_objective(*mesh, ctx); });
        rec.min_quality = m.min_quality;
        rec.inverted = m.inverted;
      } else {
        rec.min_quality = std::numeric_limits<double>::quiet_NaN();
        rec.inverted = -1;
      }
      result->history.push_back(rec);
      if (so.verbose)
        std::fprintf(stderr,
                     "  [%s] sweep %d %s: %4d parts, %7d vertices, %d-%d iterations  objective "
                     "%.6e  (solver "
                     "%.6e)  min quality %.4f  inverted %d  %.2f s\n",
                     spec.name.c_str(), sweep, names[ph], totals.parts, totals.vertices,
                     totals.min_iterations, totals.max_iterations, rec.objective,
                     rec.solver_objective, rec.min_quality, rec.inverted, rec.seconds);
      if (so.progress) {
        ProgressRecord pr;
        static_cast<IterationRecord&>(pr) = rec;
        pr.stage = spec.name;
        so.progress(pr);
      }
      if (agreed(so.progress.cancelled())) {  // the next phase does not start
        *reason = "cancelled";
        out_of_time = true;
        break;
      }
    }
    result->sweeps = sweep;
    cost = sweep_initial - sweep_decrease;
    if (out_of_time) break;
    if (!(sweep_decrease > so.sweep_tolerance * sweep_initial)) {
      *reason = "sweep decrease below sweep_tolerance";
      break;
    }
  }
  *reason = "partitioned (" + std::to_string(phase_a.size()) + " + " +
            std::to_string(phase_b.size()) + (phase_c.empty() ? "" : " + 1") + " parts, " +
            std::to_string(result->sweeps) + " sweeps): " + *reason;
  return Status::Ok();
}

}  // namespace tmop
