// tmop_optimize: improve a mesh by moving its nodes (Target-Matrix Optimization Paradigm).
//
//   tmop_optimize --input=IN --output=OUT [--recipe=NAME] [--boundary=fixed|slide]
//                 [--geometry=SPEC] [--metric=NAME]
//                 [--target=NAME] [--reference=FILE] [--sample_points=RULE] [--power=P]
//                 [--target=composed --target_size=SRC --target_orientation=SRC
//                  --target_shape=ideal|initial --target_skew=SRC --target_aspect=SRC]
//                 [--solver=lm|dogleg] [--linear_solver=auto|cholesky|cgnr]
//                 [--max_iterations=N] [--threads=N] [--report=FILE.json] [--verbose]
//                 [--orientation=auto|gmsh|opposite] [--fixed_nodes=FILE|field:NAME]
//                 [--from_report=FILE.json]
//
// A thin layer over the recipe registry (tmop/recipes/recipe.h: run_recipe): flags become
// RecipeOptions (tools/optimize/flags.h), the files are read and checked (inputs.h), the result
// is checked against the guarantees, written and reported (run.h, run_report.h). A cancelled run
// ends as SIGINT does.
// Exit status: 0 success; 1 the optimization could not reach its goal; 2 bad input or usage.
// Errors are one line on stderr. OUT is written atomically and only on success; IN is never
// opened for writing.
#include <gflags/gflags.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <glog/logging.h>

#include <atomic>
#include <cstdio>
#include <string>

#include "tmop/io/atomic_file.h"
#include "tmop/metric/metric.h"
#include "tmop/recipes/recipe.h"
#include "tools/optimize/flags.h"
#include "tools/optimize/inputs.h"
#include "tools/optimize/run.h"
#include "tools/optimize/run_report.h"
#include "tools/parse_flags.h"

#ifdef TMOP_WITH_MPI
#include <memory>

#include "tmop/parallel/mpi_exchange.h"
#endif

int main(int argc, char** argv) {
  gflags::SetUsageMessage(
      "improve a mesh by node movement\n"
      "  tmop_optimize --input=IN --output=OUT [--recipe=" +
      tmop::recipe_names() + "] [flags]");
#ifdef __GLIBC__
  // A fixed mmap threshold: glibc's adaptive one rises to the size of freed buffers (reading,
  // the quality report), after which multi-MB vectors land in the heap and leave it fragmented;
  // 1M tets: peak 1,029 -> 988 MB, the same time (docs/benchmarks.md).
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
#endif
#ifdef TMOP_WITH_MPI
  // Under mpirun every rank runs the same recipe on the same mesh and solves its share of the
  // parts of partitioned stages (tmop/parallel/mpi_exchange.h); rank 0 alone prints and writes.
  tmop::MpiSession mpi(&argc, &argv);
  std::unique_ptr<tmop::MpiExchange> exchange;
  if (mpi.active() && mpi.size() > 1) exchange.reset(new tmop::MpiExchange(MPI_COMM_WORLD));
  if (mpi.rank() != 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr))
      return 2;
  }
#endif
  tmop_tools::parse_flags(&argc, &argv);
  if (!FLAGS_from_report.empty()) {
    const tmop::Status s = tmop_tools::apply_report_flags(FLAGS_from_report);
    if (!s.ok()) return tmop_tools::fail(2, s.message());
  }
  // Ctrl-C or a SIGTERM mid-run cancels the recipe (the next iteration stops it), nothing is
  // written, one line on stderr, exit 130; a second signal exits at once (temporaries removed).
  const std::atomic<bool>* cancel = tmop::cancel_on_signal("tmop_optimize");
  // Ceres reports through glog; the tool reports itself (one line on failure).
  FLAGS_minloglevel = FLAGS_verbose ? 1 : 3;
  google::InitGoogleLogging(argv[0]);
  if (FLAGS_list_metrics) {
    for (int d = 2; d <= 3; ++d) {
      std::printf("%dD:", d);
      for (const std::string& n : tmop::metric_names(d)) std::printf(" %s", n.c_str());
      std::printf("\n");
    }
    std::printf("weighted combinations of two: W1*NAME1+W2*NAME2 (weights >= 0, default 1)\n");
    return 0;
  }
  if (const int rc = tmop_tools::check_flags(argc, argv)) return rc;
  tmop::RecipeOptions options;
  bool composed = false;
  if (const int rc = tmop_tools::options_from_flags(&options, &composed)) return rc;
  tmop_tools::Inputs in;
  if (const int rc = tmop_tools::load_inputs(composed, &options, &in)) return rc;
  options.cancel = cancel;
  options.solver.progress = tmop_tools::remembering_last_iteration(options.solver.progress);
#ifdef TMOP_WITH_MPI
  options.solver.exchange = exchange.get();
  in.writes = mpi.rank() == 0;
  in.piece = mpi.rank();
  in.pieces = mpi.size();
  const int rc = tmop_tools::run(options, &in);
  // A rank cancelled by a signal may stop where the others wait for it: end them all.
  if (rc == 130 && exchange) mpi.abort(130);
  return rc;
#else
  return tmop_tools::run(options, &in);
#endif
}
