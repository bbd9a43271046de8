#pragma once
// ParaView output: VTK XML PolyData (.vtp) snapshots of the particles and of the
// contact network, and a .pvd collection that lists them by time. The XML is
// written by hand (ASCII data arrays, no VTK library needed) and every file is
// published atomically (io/atomic_file.hpp).
//
// Particles (write_particles_vtp): one point and one vertex cell per sphere.
//   PointData  radius            Float64
//              velocity          Float64 x3
//              angular_velocity  Float64 x3
//              id                Int64    user-facing id
//              group             UInt8    0 mobile, 1 bottom wall, 2 top wall
//              wall              UInt8    1 if group != 0
//
// Contacts (write_contacts_vtp): one line cell per loaded sphere-sphere contact
// (p_n > 0; contacts with a plane are left out), from the centre of sphere i to
// the centre of the nearest periodic image of sphere j, so no line spans the box.
// Each line has its own two points.
//   CellData   normal_force         Float64  p_n / dt
//              tangential_force     Float64  |p_t| / dt
//              sliding_speed        Float64
//              sommerfeld           Float64
//              regime               Int32    0 open, 1 stick, 2 bl, 3 hd, 4 frictionless
//              (vtk_regime_code) boundary_lubricated  UInt8    1 if stick or bl (s < s_c)
//
// ASCII VTK cannot carry inf or NaN (the reader then rejects the whole array), so
// +inf and NaN are written as the largest double and -inf as its negative.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

// The `regime` cell value: 0 open, 1 stick, 2 bl (boundary lubricated), 3 hd (hydrodynamic),
// 4 frictionless (below the critical load, friction/critical_load_law.hpp).
std::int32_t vtk_regime_code(Regime r);

// body_group[i] is sphere i's group (0 mobile, 1 bottom wall, 2 top wall); when empty,
// fixed spheres (inv_mass == 0) get group 1 and the others 0. Throws
// std::invalid_argument if body_group is neither empty nor one entry per sphere.
void write_particles_vtp(const std::filesystem::path& file, const World& world,
                         const std::vector<std::uint8_t>& body_group);

// Forces are the step's impulses divided by dt.
void write_contacts_vtp(const std::filesystem::path& file, const World& world,
                        const std::vector<Contact>& contacts, double dt);

// A ParaView collection (.pvd) of snapshot files. Each add() records one data
// set; write() rewrites the whole .pvd atomically, so calling it after every
// snapshot keeps a valid collection on disk throughout a run.
class PvdCollection {
 public:
  explicit PvdCollection(std::filesystem::path pvd_file);

  // relative_file is relative to the .pvd's directory; part distinguishes data
  // sets of the same time step (e.g. 0 particles, 1 contacts).
  void add(double time, const std::string& relative_file, int part = 0);
  void write() const;

  const std::filesystem::path& path() const { return pvd_file_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double time;
    std::string file;
    int part;
  };
  std::filesystem::path pvd_file_;
  std::vector<Entry> entries_;
};

}  // namespace dilatant
