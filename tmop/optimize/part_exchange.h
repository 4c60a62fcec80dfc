// tmop/optimize/part_exchange.h
// How a partitioned stage (partitioned_stage.h) shares its parts among processes: DESIGN.md
// section 12, MPI. Every process holds the mesh and builds the same partitions (METIS with a
// fixed seed); the exchange says which process solves which part and, after each phase, gives
// every process the coordinates and outcomes of the parts the others solved, so that all of them
// continue from the same state and take the same decisions (stopping rules, time limits,
// cancels). Without one (SolverOptions::exchange null) this process solves every part. The
// interface knows nothing of MPI: tmop/parallel/ implements it.
#ifndef TMOP_OPTIMIZE_PART_EXCHANGE_H_
#define TMOP_OPTIMIZE_PART_EXCHANGE_H_

#include <vector>

#include "tmop/core/status.h"

namespace tmop {

struct PartOutcome;

class PartExchange {
 public:
  virtual ~PartExchange() = default;
  virtual int rank() const = 0;  // this process, in [0, size())
  virtual int size() const = 0;

  // After a phase. pieces[k]: the free vertices of part k; owner[k]: the rank that solved it;
  // (*outcomes)[k] is filled for this rank's parts and `coords` (the mesh's coordinates,
  // space_dim per vertex) holds their moved vertices. On return every process has every part's
  // outcome and moved vertices. Fails on every process, with the first failed part's message
  // (by rank), when a part failed anywhere.
  virtual Status share(const std::vector<std::vector<int>>& pieces, const std::vector<int>& owner,
                       int space_dim, std::vector<PartOutcome>* outcomes,
                       std::vector<double>* coords) = 0;

  // The largest of every process's `value`: decisions all processes must take together (a time
  // limit reached, a cancel seen) are made on it.
  virtual double max_of(double value) = 0;
};

}  // namespace tmop

#endif  // TMOP_OPTIMIZE_PART_EXCHANGE_H_
