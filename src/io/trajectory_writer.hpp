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
  void write_frame(const World& world);
  void commit() { file_.commit(); }

 private:
  AtomicFileWriter file_;
};

}  // namespace dilatant
