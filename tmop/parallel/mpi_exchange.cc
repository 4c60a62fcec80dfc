#include "tmop/parallel/mpi_exchange.h"

#include <cstdlib>
#include <string>

#include "tmop/optimize/part_solve.h"

namespace tmop {

namespace {

// Set by mpirun / a PMIx launcher in every rank it starts.
bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

// A part's outcome as doubles (its error text travels separately).
constexpr int kOutcomeDoubles = 16;
void pack(const PartOutcome& o, std::vector<double>* out) {
  const StageResult::Times& t = o.times;
  const double v[kOutcomeDoubles] = {o.ok ? 1.0 : 0.0,
                                     o.initial_cost,
                                     o.final_cost,
                                     static_cast<double>(o.iterations),
                                     static_cast<double>(o.elements),
                                     t.preprocessor,
                                     t.minimizer,
                                     t.residual_evaluation,
                                     t.jacobian_evaluation,
                                     t.linear_solver,
                                     static_cast<double>(t.residual_evaluations),
                                     static_cast<double>(t.jacobian_evaluations),
                                     static_cast<double>(t.linear_solves),
                                     static_cast<double>(t.recorded_linear_solves),
                                     static_cast<double>(t.linear_iterations),
                                     0.0};
  out->insert(out->end(), v, v + kOutcomeDoubles);
}
void unpack(const double* v, PartOutcome* o) {
  StageResult::Times& t = o->times;
  o->ok = v[0] != 0;
  o->initial_cost = v[1];
  o->final_cost = v[2];
  o->iterations = static_cast<int>(v[3]);
  o->elements = static_cast<int>(v[4]);
  t.preprocessor = v[5];
  t.minimizer = v[6];
  t.residual_evaluation = v[7];
  t.jacobian_evaluation = v[8];
  t.linear_solver = v[9];
  t.residual_evaluations = static_cast<int>(v[10]);
  t.jacobian_evaluations = static_cast<int>(v[11]);
  t.linear_solves = static_cast<int>(v[12]);
  t.recorded_linear_solves = static_cast<int>(v[13]);
  t.linear_iterations = static_cast<long>(v[14]);
}

// Every rank's `local` block, concatenated in rank order; *at[r] = where rank r's block starts.
template <typename T>
std::vector<T> gather_all(MPI_Comm comm, MPI_Datatype type, int size, const std::vector<T>& local,
                          std::vector<int>* at) {
  const int n = static_cast<int>(local.size());
  std::vector<int> counts(size);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  at->assign(size + 1, 0);
  for (int r = 0; r < size; ++r) (*at)[r + 1] = (*at)[r] + counts[r];
  std::vector<T> all(static_cast<std::size_t>((*at)[size]));
  MPI_Allgatherv(local.data(), n, type, all.data(), counts.data(), at->data(), type, comm);
  return all;
}

}  // namespace

MpiSession::MpiSession(int* argc, char*** argv) {
  if (!launched_by_mpirun()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) MPI_Init(argc, argv);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (!active_) return;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

void MpiSession::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

MpiExchange::MpiExchange(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

Status MpiExchange::share(const std::vector<std::vector<int>>& pieces,
                          const std::vector<int>& owner, int space_dim,
                          std::vector<PartOutcome>* outcomes, std::vector<double>* coords) {
  // This rank's parts in increasing part order: outcome, then the moved vertices' coordinates.
  std::vector<double> local;
  std::string error;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (owner[k] != rank_) continue;
    const PartOutcome& o = (*outcomes)[k];
    pack(o, &local);
    if (!o.ok && error.empty()) error = o.error;
    for (int v : pieces[k])
      for (int a = 0; a < space_dim; ++a)
        local.push_back((*coords)[static_cast<std::size_t>(v) * space_dim + a]);
  }
  std::vector<int> at, text_at;
  const std::vector<double> all = gather_all(comm_, MPI_DOUBLE, size_, local, &at);
  const std::vector<char> text =
      gather_all(comm_, MPI_CHAR, size_, std::vector<char>(error.begin(), error.end()), &text_at);
  for (int r = 0; r < size_; ++r) {
    const double* p = all.data() + at[r];
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (owner[k] != r) continue;
      if (r != rank_) unpack(p, &(*outcomes)[k]);
      p += kOutcomeDoubles;
      for (int v : pieces[k])
        for (int a = 0; a < space_dim; ++a)
          (*coords)[static_cast<std::size_t>(v) * space_dim + a] = *p++;
    }
  }
  for (int r = 0; r < size_; ++r)
    if (text_at[r + 1] > text_at[r])
      return Status::Failure("rank " + std::to_string(r) + ": " +
                             std::string(text.data() + text_at[r], text.data() + text_at[r + 1]));
  for (const PartOutcome& o : *outcomes)
    if (!o.ok) return Status::Failure("a part failed on another rank");
  return Status::Ok();
}

double MpiExchange::max_of(double value) {
  double out = value;
  MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return out;
}

}  // namespace tmop
