// tmop/parallel/mpi_exchange.h
// Partitioned stages over MPI ranks (DESIGN.md section 12; the library without MPI is unchanged
// and all MPI code lives in this folder, built when CMake finds MPI: TMOP_WITH_MPI).
//
// This first form replicates the mesh: every rank reads it, computes the same StageContext and
// the same partitions, solves only its share of each phase's parts (optimize/part_exchange.h)
// and then receives the others' moved vertices (MPI_Allgatherv), so that every rank holds the
// whole result and takes the same decisions; the result equals the single-process result for
// the same partitions bit for bit. Not yet: ranks holding only their parts and halos, per-rank
// input and output (docs/parallel.md).
#ifndef TMOP_PARALLEL_MPI_EXCHANGE_H_
#define TMOP_PARALLEL_MPI_EXCHANGE_H_

#include <mpi.h>

#include <vector>

#include "tmop/optimize/part_exchange.h"

namespace tmop {

// MPI_Init / MPI_Finalize for a program that may or may not have been started by mpirun: active()
// only when it was (OpenMPI's or PMIx's rank variables are set), so a plain run needs no MPI
// runtime. One per program, in main.
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank with `code` (MPI_Abort): for a rank that must stop while others may wait in
  // a collective (a signal under mpirun).
  [[noreturn]] void abort(int code) const;

 private:
  bool active_ = false;
  int rank_ = 0, size_ = 1;
};

class MpiExchange : public PartExchange {
 public:
  explicit MpiExchange(MPI_Comm comm);
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  Status share(const std::vector<std::vector<int>>& pieces, const std::vector<int>& owner,
               int space_dim, std::vector<PartOutcome>* outcomes,
               std::vector<double>* coords) override;
  double max_of(double value) override;

 private:
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

}  // namespace tmop

#endif  // TMOP_PARALLEL_MPI_EXCHANGE_H_
