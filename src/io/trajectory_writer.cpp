#include "io/trajectory_writer.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace dilatant {

TrajectoryWriter::TrajectoryWriter(const std::filesystem::path& path) : file_(path) {
  file_.write("t,id,x,y,z,vx,vy,vz,wx,wy,wz\n");
}

void TrajectoryWriter::write_frame(const World& world) {
  const Bodies& b = world.bodies;
  std::string rows;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec3 &x = b.position[i], &v = b.velocity[i], &w = b.angular_velocity[i];
    fmt::format_to(
        std::back_inserter(rows),
        "{:.10g},{},{:.12g},{:.12g},{:.12g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n",
        world.time, b.id[i], x[0], x[1], x[2], v[0], v[1], v[2], w[0], w[1], w[2]);
  }
  file_.write(rows);
}

}  // namespace dilatant
