#include "sweep/mpi_session.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "io/input_error.hpp"

#if DILATANT_WITH_MPI
#include <mpi.h>
#endif

namespace dilatant::sweep {
namespace {

const char* env(const char* name) { return std::getenv(name); }

bool launched_by_mpi() {
  return env("OMPI_COMM_WORLD_SIZE") != nullptr || env("PMIX_RANK") != nullptr ||
         env("PMI_RANK") != nullptr;
}

}  // namespace

bool built_with_mpi() { return DILATANT_WITH_MPI != 0; }

#if DILATANT_WITH_MPI

MpiSession::MpiSession() {
  if (!launched_by_mpi()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    initialised_ = false;
    throw std::runtime_error(
        "the MPI library does not support threads (MPI_THREAD_FUNNELED): an MPI sweep runs its "
        "points on threads");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() { finalize(); }

void MpiSession::finalize() {
  if (initialised_) MPI_Finalize();
  initialised_ = false;
}

bool MpiSession::on_rank0(bool ok) const {
  if (!initialised_) return ok;
  int value = ok ? 1 : 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value == 1;
}

bool MpiSession::all_ranks(bool ok) const {
  if (!initialised_) return ok;
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

#else

namespace {

// Whether a launcher started more than this one rank, as far as its
// environment says.
bool started_as_one_of_many() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"})
    if (const char* v = env(name); v != nullptr && std::atoi(v) > 1) return true;
  for (const char* name : {"PMIX_RANK", "PMI_RANK"})
    if (const char* v = env(name); v != nullptr && std::atoi(v) > 0) return true;
  return false;
}

}  // namespace

MpiSession::MpiSession() {
  if (launched_by_mpi() && started_as_one_of_many())
    throw InputError(
        "started by an MPI launcher with several ranks, but this dilatant was built without MPI "
        "(cmake -DDILATANT_WITH_MPI=ON needs libopenmpi-dev): each rank would run the whole "
        "sweep; run `dilatant sweep` without mpirun, or rebuild");
}

MpiSession::~MpiSession() = default;

bool MpiSession::all_ranks(bool ok) const { return ok; }
bool MpiSession::on_rank0(bool ok) const { return ok; }
void MpiSession::finalize() {}

#endif

}  // namespace dilatant::sweep
