#pragma once
// A sweep over the ranks of an MPI job (`mpirun -n K dilatant sweep ...`,
// docs/cluster.md): the same units of work as the local sweep (sweep_work.hpp:
// a point, or a whole continuation chain), handed out one at a time to
// whichever rank asks first, so that cheap points (a ramp stopped at its jam)
// and expensive ones (a thickened flow) balance by themselves.
//
//   rank 0                                  rank r > 0
//   ──────                                  ──────────
//   inspect folders, write sweep.toml       `jobs` threads; a free one makes
//   `jobs` threads take units itself          the main thread send kRequest
//   main thread, every 10 ms:               main thread, every 10 ms:
//     answer kRequest: kAssign / kNoMore      kAssign -> a thread runs the unit
//     kRecord -> table; kNote -> stderr       (reading its chain's folders first)
//     progress line, SIGINT -> kHalt          changed records -> kRecord
//   until its threads and every rank ended    until its threads ended: kFinished
//
// Rank 0 works too (its main thread only coordinates, which costs nothing):
// with two ranks on two cores both run points. Every rank reads and writes
// the point folders directly, so DIR must be on a filesystem all ranks share
// (a cluster's shared home or scratch); rank 0 alone writes sweep.toml and
// flowcurves.csv. Results, resume and failures are those of the local sweep:
// the points run the same code on the same folders.
#include "sweep/mpi_session.hpp"
#include "sweep/sweep_runner.hpp"

namespace dilatant::sweep {

// Call on every rank of `session` (size > 1). Rank 0 returns the outcome of
// the whole sweep; the other ranks return an outcome to ignore. Rank 0 throws
// InputError, as the local sweep does, for a folder of another configuration,
// after telling the other ranks that there is no work.
SweepOutcome run_sweep_on_ranks(const SweepPlan& plan, const SweepRunOptions& options,
                                const MpiSession& session);

}  // namespace dilatant::sweep
