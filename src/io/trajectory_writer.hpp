#pragma once
// trajectory.csv (README "Using it"): one row per particle per output time,
//   t,id,x,y,z,vx,vy,vz,wx,wy,wz
#include <filesystem>

#include "io/atomic_file.hpp"
#include "world/world.hpp"

namespace dilatant {

class TrajectoryWriter {
 public:
  explicit TrajectoryWriter(const std::filesystem::path& path);
  // Continues an interrupted run's file from its first `bytes` bytes
  // (io/atomic_file.hpp).
  TrajectoryWriter(const std::filesystem::path& path, std::uintmax_t bytes) : file_(path, bytes) {}
  void write_frame(const World& world);
  std::uintmax_t flushed_size() { return file_.flushed_size(); }
  void keep() { file_.keep(); }
  void commit() { file_.commit(); }

 private:
  AtomicFileWriter file_;
};

}  // namespace dilatant
