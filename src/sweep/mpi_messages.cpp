#include "sweep/mpi_messages.hpp"

#include <sstream>

namespace dilatant::sweep::mpi {

void send(int to, Tag tag, const std::string& payload) {
  MPI_Send(payload.data(), static_cast<int>(payload.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

bool try_receive(int from, Message& message) {
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(from, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
  if (arrived == 0) return false;
  int size = 0;
  MPI_Get_count(&status, MPI_CHAR, &size);
  message.from = status.MPI_SOURCE;
  message.tag = status.MPI_TAG;
  message.payload.assign(static_cast<std::size_t>(size), '\0');
  // Receives the very message probed: same source and tag, and MPI keeps the
  // order of one source's messages.
  MPI_Recv(message.payload.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG,
           MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

std::string unit_text(const WorkUnit& unit) {
  std::string text;
  for (std::size_t i : unit) text += (text.empty() ? "" : " ") + std::to_string(i);
  return text;
}

WorkUnit parse_unit(const std::string& text) {
  WorkUnit unit;
  std::istringstream in(text);
  for (std::size_t i; in >> i;) unit.push_back(i);
  return unit;
}

// Summaries travel as JSON text: nlohmann writes each double as the shortest
// text that reads back exactly, so rank 0's table has the bits the worker read.
std::string record_json(std::size_t point, const PointRecord& record) {
  nlohmann::json j;
  j["point"] = point;
  j["status"] = static_cast<int>(record.status);
  j["error"] = record.error;
  j["summary"] = record.summary;
  j["cold_start"] = record.cold_start;
  j["cold_start_choice"] = record.cold_start_choice;
  return j.dump();
}

std::pair<std::size_t, PointRecord> parse_record(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  PointRecord record;
  record.status = static_cast<PointStatus>(j.at("status").get<int>());
  record.error = j.at("error").get<std::string>();
  record.summary = j.at("summary");
  record.cold_start = j.at("cold_start");
  record.cold_start_choice = j.at("cold_start_choice");
  return {j.at("point").get<std::size_t>(), std::move(record)};
}

}  // namespace dilatant::sweep::mpi
