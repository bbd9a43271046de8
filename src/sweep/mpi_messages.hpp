#pragma once
// The messages of an MPI sweep (mpi_scheduler.cpp) between rank 0, which keeps
// the table and hands out units, and the other ranks, which run them. Every
// message is a byte string on MPI_COMM_WORLD; its tag says what it is:
//
//   worker -> 0   kRequest   a worker thread is free (empty)
//   0 -> worker   kAssign    a unit for it: point indices, text "3 4 5"
//   0 -> worker   kNoMore    nothing left for that request (empty)
//   0 -> worker   kHalt      stop: running points checkpoint, none starts (empty)
//   worker -> 0   kRecord    a point's record changed (JSON: record_json)
//   worker -> 0   kNote      a line for stderr (a failed point)
//   worker -> 0   kProgress  the fractions of its running points (JSON)
//   worker -> 0   kFinished  its threads all ended: "halted" when it stopped
//                            on its own signal (SIGTERM), else empty
//   0 -> worker   kFinished  every rank ended: the sweep is over (empty)
//
// Messages from one rank arrive in the order sent (MPI's non-overtaking rule
// for one source and one communicator), so kFinished comes after the rank's
// last kRecord. Only small messages go from rank 0 (a unit's indices), so its
// blocking sends return at once while the workers' larger records wait until
// rank 0 polls.
#include <mpi.h>

#include <cstddef>
#include <string>

#include "sweep/flow_table.hpp"
#include "sweep/sweep_work.hpp"

namespace dilatant::sweep::mpi {

enum Tag : int {
  kRequest = 1,
  kAssign,
  kNoMore,
  kHalt,
  kRecord,
  kNote,
  kProgress,
  kFinished,
};

void send(int to, Tag tag, const std::string& payload = {});

struct Message {
  int from = -1;
  int tag = 0;
  std::string payload;
};

// The next message from `from` (MPI_ANY_SOURCE: from anyone) if one has
// arrived; never blocks.
bool try_receive(int from, Message& message);

std::string unit_text(const WorkUnit& unit);
WorkUnit parse_unit(const std::string& text);

// A point's record with its index, and back.
std::string record_json(std::size_t point, const PointRecord& record);
std::pair<std::size_t, PointRecord> parse_record(const std::string& text);

}  // namespace dilatant::sweep::mpi
