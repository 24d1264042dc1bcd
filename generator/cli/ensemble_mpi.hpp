/**
 * @file ensemble_mpi.hpp  An `eomgen run` ensemble across the ranks of an MPI job (`mpirun -n R eomgen run
 * ... --sweep ...`), built only where CMake finds MPI (EOMGEN_HAVE_MPI).
 *
 * Rank 0 hands out chunks of consecutive members on request (dynamic assignment: a rank that drew slow
 * members asks less often), integrates chunks of its own on its threads meanwhile, and receives every other
 * rank's results with its next request; its sink sees every member in index order, so it writes the table a
 * single process writes, byte for byte. Other ranks integrate each chunk on their threads. Only the main
 * thread of each rank calls MPI (MPI_THREAD_FUNNELED); rank 0's waits for requests by polling every 0.2 ms
 * rather than in a blocking receive, which spins a core in Open MPI. Results travel as raw bytes: the ranks
 * must share one architecture (as the nodes of a cluster do).
 */
#pragma once

#include "eomgen/ensemble.hpp"
#include "eomgen/model_table.hpp"

#include <cstddef>
#include <functional>

namespace eomgen::cli {

/**
 * MPI for the lifetime of the object when this process was started by an MPI launcher (Open MPI's
 * OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_RANK of MPICH and PMIx launchers, in the environment);
 * otherwise rank 0 of 1, and MPI is never started (a plain `eomgen run` pays nothing for it).
 */
class MpiSession {
  public:
    MpiSession();
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    /// How many ranks share this rank's node (MPI_COMM_TYPE_SHARED): the cores are divided among them.
    int node_size() const { return node_size_; }
    /// The threads of each rank: `requested`, or for 0 this node's cores divided among its ranks.
    unsigned threads(unsigned requested) const;

  private:
    bool started_ = false;
    int rank_ = 0, size_ = 1, node_size_ = 1;
};

using MemberFunction = std::function<eomgen::Member<eomgen::TableModel>(std::size_t)>;
using ResultSink = std::function<void(const eomgen::MemberResult<eomgen::TableModel>&)>;

/**
 * Members 0 … count − 1 across the ranks of `mpi`, each rank on mpi.threads(options.threads) threads. On rank 0 `sink` gets every result in index order; other ranks never call
 * it. Options no member can take throw sim::UsageError on every rank alike, before any member runs. An
 * error after that (a sink that cannot write, a member function that throws) is reported on stderr and ends
 * the whole job through MPI_Abort, since the other ranks would wait for ever.
 */
void mpi_ensemble(const MpiSession& mpi, std::size_t count, const MemberFunction& member,
                  const eomgen::EnsembleOptions& options, const ResultSink& sink);

}  // namespace eomgen::cli
