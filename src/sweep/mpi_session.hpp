#pragma once
// MPI for `dilatant sweep` started by an MPI launcher (mpirun, mpiexec, srun;
// docs/cluster.md). MPI is initialised only when the environment says that a
// launcher started the process (OMPI_COMM_WORLD_SIZE of Open MPI's mpirun,
// PMIX_RANK of PMIx launchers such as `srun --mpi=pmix`, PMI_RANK of MPICH's
// Hydra and `srun --mpi=pmi2`): `dilatant sweep` alone, and every other
// command, never touch MPI, so a plain run pays nothing for it and needs no
// MPI runtime that works (an Open MPI singleton would start a daemon).
//
// MPI is optional at build time (CMake option DILATANT_WITH_MPI, on when
// find_package(MPI) finds it). A binary built without it, started by a
// launcher with more than one rank, refuses (InputError): every rank would
// run the whole sweep in the same folder.
//
// Only the thread that created the session calls MPI (MPI_THREAD_FUNNELED);
// the destructor finalises.
namespace dilatant::sweep {

class MpiSession {
 public:
  MpiSession();  // initialises MPI when launched by an MPI launcher
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ranks on this machine (MPI_COMM_TYPE_SHARED): they share its cores.
  int ranks_on_this_node() const { return local_size_; }
  // Collective: whether `ok` holds on every rank (all ranks must call it).
  bool all_ranks(bool ok) const;
  // Collective: rank 0's `ok`, on every rank.
  bool on_rank0(bool ok) const;
  // Ends MPI early (collective), e.g. before rank 0's analysis, so that the
  // other ranks exit instead of waiting in MPI_Finalize; idempotent.
  void finalize();

 private:
  bool initialised_ = false;
  int rank_ = 0;
  int size_ = 1;
  int local_size_ = 1;
};

// Whether this binary was built with MPI (DILATANT_WITH_MPI).
bool built_with_mpi();

}  // namespace dilatant::sweep
