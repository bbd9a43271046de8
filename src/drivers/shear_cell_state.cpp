#include "drivers/shear_cell_state.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "boundary/drive_record.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_archive.hpp"
#include "io/checksum.hpp"
#include "io/contact_memory_archive.hpp"
#include "io/text.hpp"

namespace dilatant {

namespace {

// "DILATNT9": the file ends with the CRC-32 of every byte before it, 4 bytes
// in the machine's order (io/checksum.hpp), checked before anything is read
// (9: the Lees–Edwards pressure control's fields after the images' control;
// format 8, the same without them, still reads, as a state without pressure
// control; 7: rows with where the largest contact residual was; 6: the
// Lees–Edwards boundary's drive; 5: rows with the particle
// stress tensor, the box's Lees–Edwards state; 4: rows with the fluid
// forces' powers, geometry with phi_box; 3: rows with the contact residual;
// 2: contact memory with regime)
constexpr std::uint64_t kMagic = 0x39544e54414c4944ULL;
constexpr std::uint64_t kMagic8 = 0x38544e54414c4944ULL;

// One function serves both directions so the field order cannot diverge. The
// drive is written as its record (boundary/drive_record.hpp), whose fields
// keep their places in the format.
template <class Archive, class State>
void visit_state(Archive& a, State& s, DriveRecord& d, bool format8 = false) {
  auto& b = s.world.bodies;
  a.vector(b.position);
  a.vector(b.velocity);
  a.vector(b.angular_velocity);
  a.vector(b.radius);
  a.vector(b.inv_mass);
  a.vector(b.inv_inertia);
  a.vector(b.id);
  a.vector(d.owners);
  std::uint64_t planes = s.world.planes.size();
  a.count(planes, 2 * sizeof(Vec3));
  s.world.planes.resize(planes);
  for (auto& plane : s.world.planes) {
    a.value(plane.point);
    a.value(plane.normal);
  }
  a.value(s.world.box.length);
  a.value(s.world.box.periodic);
  a.value(s.world.box.lees_edwards);
  a.value(s.world.box.shear_offset);
  a.value(s.world.box.shear_velocity);
  a.value(s.world.gravity);
  a.value(s.world.time);
  a.vector(d.wall.spheres);
  a.value(d.wall.mass);
  a.value(d.wall.drive_force);
  a.value(d.wall.velocity);
  a.value(d.images.mass);
  a.value(d.images.drive_force);
  a.value(d.images.area);
  a.value(d.images.rate);
  a.value(d.images.rate_controlled);
  if (!format8) {
    a.value(d.images.pressure_controlled);
    a.value(d.images.normal_force);
    a.value(d.images.height_speed);
  }
  a.value(s.geometry);
  a.value(s.dt);
  a.value(s.steps);
  a.value(s.strain);
  a.value(s.schedules.rows.next);
  a.value(s.schedules.snapshots.next);
  a.value(s.schedules.checkpoints.next);
  a.vector(s.snapshot_strains);
  auto& m = s.measurements;
  a.value(m.interval);
  a.vector(m.rows);
  a.value(m.profile.height());
  a.vector(m.profile.sums());
  a.vector(m.profile.weights());
  a.value(m.histogram);
  a.value(s.jam.window_strain);
  a.value(s.jam.window_time);
  a.value(s.jam.jammed);
}

}  // namespace

void save_checkpoint(const std::filesystem::path& file, const ShearCellState& state) {
  write_file_atomically(file, checkpoint_bytes(state));
}

std::string checkpoint_bytes(const ShearCellState& state) {
  BinaryWriter w;
  w.value(kMagic);
  // visit_state needs mutable access for the reader; the writer only reads.
  DriveRecord drive = state.drive->record(state.world);
  visit_state(w, const_cast<ShearCellState&>(state), drive);
  write_contact_memory(w, state.contact_memory);
  std::string bytes = w.release();
  append_crc_trailer(bytes);
  return bytes;
}

void seal_checkpoint(std::string& bytes) { reseal_crc_trailer(bytes); }

ShearCellState load_checkpoint(const std::filesystem::path& file) {
  // A missing or unreadable one is named with its file (InputError).
  std::string bytes = read_input_file(file, "checkpoint");
  try {
    return read_checkpoint(std::move(bytes), file);
  } catch (const std::runtime_error& e) {
    // The archive's own messages ("checkpoint is truncated") name no file.
    const std::string what = e.what();
    if (what.rfind(file.string(), 0) == 0) throw;
    throw std::runtime_error(
        fmt::format("{}: {} (a run killed while writing it leaves the "
                    "previous checkpoint, so this file was damaged later)",
                    file.string(), what));
  }
}

namespace {

// A state that read without error can still be one no run wrote (a damaged
// file of the right length): arrays of different lengths or indices out of
// range would be read out of bounds by the first step. Refused here, named.
void check_consistent(const ShearCellState& s, const DriveRecord& drive,
                      const std::filesystem::path& file) {
  const Bodies& b = s.world.bodies;
  const std::size_t n = b.position.size();
  const auto fail = [&](const char* what) {
    throw std::runtime_error(fmt::format("{}: corrupt checkpoint ({})", file.string(), what));
  };
  if (b.velocity.size() != n || b.angular_velocity.size() != n || b.radius.size() != n ||
      b.inv_mass.size() != n || b.inv_inertia.size() != n || b.id.size() != n)
    fail("body arrays of different lengths");
  if (const char* fault = drive.fault(s.world.box, n)) fail(fault);
  if (s.geometry.first_mobile > n || s.geometry.mobile_count > n - s.geometry.first_mobile)
    fail("mobile range");
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(s.world.box.length[k]) || s.world.box.length[k] < 0.0 ||
        (s.world.box.periodic[k] && s.world.box.length[k] == 0.0))
      fail("box");
}

}  // namespace

ShearCellState read_checkpoint(std::string bytes, const std::filesystem::path& file) {
  // "DILATNT" and a format digit first, so that an older format (which has no
  // checksum, or another layout) is named as such.
  std::uint64_t magic = 0;
  if (bytes.size() < sizeof(magic)) throw std::runtime_error("checkpoint is truncated");
  std::memcpy(&magic, bytes.data(), sizeof(magic));
  constexpr std::uint64_t kFormatMask = 0x00ffffffffffffffULL;
  const bool format8 = magic == kMagic8;
  if (magic != kMagic && !format8 && (magic & kFormatMask) == (kMagic & kFormatMask))
    throw std::runtime_error(fmt::format(
        "{}: checkpoint of an older dilatant (format {}; this version reads format {}): run "
        "this point anew without --resume",
        file.string(), static_cast<char>(magic >> 56), static_cast<char>(kMagic >> 56)));
  if (magic != kMagic && !format8)
    throw std::runtime_error(file.string() + ": not a dilatant checkpoint");
  check_crc_trailer(bytes, sizeof(kMagic), file);
  BinaryReader r(std::move(bytes));
  r.end_before(kCrcTrailerBytes);
  r.value(magic);
  ShearCellState s;
  DriveRecord drive;
  visit_state(r, s, drive, format8);
  s.contact_memory = read_contact_memory(r, file);
  if (!r.at_end()) throw std::runtime_error(file.string() + ": checkpoint has trailing data");
  check_consistent(s, drive, file);
  s.drive = restore_drive(std::move(drive), s.world, s.geometry.wall_gap());
  return s;
}

}  // namespace dilatant
