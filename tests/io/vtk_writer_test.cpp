#include "io/vtk_writer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "io/io_test_files.hpp"

// The ParaView files are checked by VTK's own XML reader, run from Debian's
// /usr/bin/python3 (python3-vtk9, installed by the project's install script).

namespace dilatant::vtk_writer_test {
namespace {

using nlohmann::json;

constexpr const char* kPython = "/usr/bin/python3";
constexpr double kDt = 1e-3;
constexpr double kMax = std::numeric_limits<double>::max();

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Six spheres in a box periodic along x and y; spheres 0 and 1 touch across the
// x boundary, 3 and 4 are fixed (bottom and top wall).
World make_world() {
  World w;
  w.box.length = Vec3(10.0, 10.0, 0.0);
  w.box.periodic = {true, true, false};
  w.planes.push_back(Plane{Vec3::Zero(), Vec3::UnitZ()});
  Bodies& b = w.bodies;
  b.add_sphere(10, Vec3(0.5, 5.0, 1.0), 0.5, 1.0, false, Vec3(1.0, -2.0, 0.25),
               Vec3(0.0, 0.5, -3.0));
  b.add_sphere(11, Vec3(9.6, 5.0, 1.0), 0.5, 1.0, false, Vec3(-1e-3, 0.0, 0.0));
  b.add_sphere(12, Vec3(3.0, 3.0, 1.0), 0.5, 1.0, false);
  b.add_sphere(13, Vec3(3.0, 3.0, 0.0), 0.5, 1.0, true);
  b.add_sphere(14, Vec3(3.0, 3.0, 3.0), 0.75, 1.0, true);
  b.add_sphere(9007199254740993, Vec3(4.0, 3.0, 1.0), 0.5, 1.0, false);  // 2^53 + 1
  return w;
}

Contact make_contact(int i, int other, double p_n, const Vec3& p_t, Regime regime,
                     double sliding_speed, double sommerfeld) {
  Contact c;
  c.i = i;
  c.other = other;
  c.p_n = p_n;
  c.p_t = p_t;
  c.regime = regime;
  c.sliding_speed = sliding_speed;
  c.sommerfeld = sommerfeld;
  return c;
}

// Three loaded sphere-sphere contacts (the first across the periodic boundary),
// one without load and one with the plane: the last two are not drawn.
std::vector<Contact> make_contacts() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  return {
      make_contact(0, 1, 2e-3, Vec3(0.0, 3e-4, 4e-4), Regime::Stick, 0.0, 0.0),
      make_contact(2, 3, 1e-3, Vec3(2e-4, 0.0, 0.0), Regime::BoundaryLubricated, 0.01, 1e-4),
      make_contact(5, 2, 5e-4, Vec3::Zero(), Regime::Hydrodynamic, nan, inf),
      make_contact(0, 2, 0.0, Vec3::Zero(), Regime::Open, 0.0, 0.0),
      make_contact(2, -1, 1e-3, Vec3::Zero(), Regime::BoundaryLubricated, 0.0, 0.0),
  };
}

json array_spec(const char* type, int components, json values) {
  return {{"type", type}, {"components", components}, {"values", std::move(values)}};
}

json particles_spec(const std::filesystem::path& file, const World& w,
                    const std::vector<int>& group) {
  const Bodies& b = w.bodies;
  json xyz = json::array(), v = json::array(), omega = json::array();
  for (std::size_t i = 0; i < b.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      xyz.push_back(b.position[i][k]);
      v.push_back(b.velocity[i][k]);
      omega.push_back(b.angular_velocity[i][k]);
    }
  }
  json wall = json::array();
  for (const int g : group) wall.push_back(g != 0 ? 1 : 0);
  return {{"file", file.string()},
          {"points", b.size()},
          {"verts", b.size()},
          {"lines", 0},
          {"points_xyz", xyz},
          {"point_data",
           {{"radius", array_spec("Float64", 1, b.radius)},
            {"velocity", array_spec("Float64", 3, v)},
            {"angular_velocity", array_spec("Float64", 3, omega)},
            {"id", array_spec("Int64", 1, b.id)},
            {"group", array_spec("UInt8", 1, group)},
            {"wall", array_spec("UInt8", 1, wall)}}},
          {"cell_data", json::object()}};
}

json contacts_spec(const std::filesystem::path& file, json normal_force, json tangential_force,
                   json sliding_speed, json sommerfeld, json regime, json bl, json points_xyz,
                   json line_lengths) {
  const std::size_t n = normal_force.size();
  return {{"file", file.string()},
          {"points", 2 * n},
          {"verts", 0},
          {"lines", n},
          {"points_xyz", std::move(points_xyz)},
          {"line_lengths", std::move(line_lengths)},
          {"point_data", json::object()},
          {"cell_data",
           {{"normal_force", array_spec("Float64", 1, std::move(normal_force))},
            {"tangential_force", array_spec("Float64", 1, std::move(tangential_force))},
            {"sliding_speed", array_spec("Float64", 1, std::move(sliding_speed))},
            {"sommerfeld", array_spec("Float64", 1, std::move(sommerfeld))},
            {"regime", array_spec("Int32", 1, std::move(regime))},
            {"boundary_lubricated", array_spec("UInt8", 1, std::move(bl))}}}};
}

json dataset(double t, int part, const std::string& file) {
  return {{"timestep", t}, {"group", ""}, {"part", part}, {"file", file}};
}

bool python_has_vtk() {
  const std::string cmd = std::string(kPython) +
                          " -c 'from vtkmodules.vtkIOXML import vtkXMLPolyDataReader'"
                          " >/dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

int run_checker(const std::filesystem::path& spec) {
  const std::string cmd = std::string(kPython) +
                          " '" DILATANT_SOURCE_DIR "/tests/io/check_vtk.py' '" + spec.string() +
                          "'";
  return std::system(cmd.c_str());
}

TEST(VtkWriter, RegimeCodes) {
  EXPECT_EQ(vtk_regime_code(Regime::Open), 0);
  EXPECT_EQ(vtk_regime_code(Regime::Stick), 1);
  EXPECT_EQ(vtk_regime_code(Regime::BoundaryLubricated), 2);
  EXPECT_EQ(vtk_regime_code(Regime::Hydrodynamic), 3);
}

TEST(VtkWriter, RejectsGroupsOfTheWrongSize) {
  test::TempDir dir;
  const World w = make_world();
  EXPECT_THROW(write_particles_vtp(dir.path() / "p.vtp", w, {0, 1}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "p.vtp"));
}

TEST(VtkWriter, PeriodicContactJoinsTheNearestImage) {
  const World w = make_world();
  const Vec3 d = w.box.minimum_image(w.bodies.position[0], w.bodies.position[1]);
  EXPECT_NEAR(d.norm(), 0.9, 1e-12);
  EXPECT_NEAR((w.bodies.position[0] - w.bodies.position[1]).norm(), 9.1, 1e-12);
}

TEST(VtkWriter, VtkReaderLoadsParticlesContactsAndCollection) {
  ASSERT_TRUE(python_has_vtk())
      << kPython << " cannot import VTK (vtkmodules.vtkIOXML): install Debian's python3-vtk9 "
      << "(apt-get install python3-vtk9, done by the project's install script)";

  test::TempDir dir;
  const auto& root = dir.path();
  std::filesystem::create_directories(root / "snap&1");
  PvdCollection pvd(root / "run.pvd");
  World w = make_world();

  // Snapshot 0: explicit groups, three drawn contacts.
  const std::vector<std::uint8_t> groups = {0, 0, 0, 1, 2, 0};
  write_particles_vtp(root / "particles_0.vtp", w, groups);
  write_contacts_vtp(root / "contacts_0.vtp", w, make_contacts(), kDt);
  pvd.add(0.0, "particles_0.vtp", 0);
  pvd.add(0.0, "contacts_0.vtp", 1);
  pvd.write();
  EXPECT_EQ(pvd.size(), 2u);
  const std::string first = read_text(root / "run.pvd");
  EXPECT_NE(first.find("file=\"contacts_0.vtp\""), std::string::npos) << first;

  const json spec0_particles = particles_spec(root / "particles_0.vtp", w, {0, 0, 0, 1, 2, 0});
  const json spec0_contacts = contacts_spec(
      root / "contacts_0.vtp", {2.0, 1.0, 0.5}, {0.5, 0.2, 0.0}, {0.0, 0.01, kMax},
      {0.0, 1e-4, kMax}, {1, 2, 3}, {1, 1, 0},
      // sphere 0 to the image of sphere 1 at x = -0.4, not to x = 9.6
      {0.5, 5.0, 1.0, -0.4, 5.0, 1.0, 3.0, 3.0, 1.0, 3.0, 3.0, 0.0, 4.0, 3.0, 1.0, 3.0, 3.0, 1.0},
      {0.9, 1.0, 1.0});

  // Snapshot 1: the spheres have moved, groups from inv_mass, no contacts.
  w.bodies.position[2] = Vec3(3.0, 3.5, 1.25);
  w.bodies.velocity[2] = Vec3(-0.125, 1e-7, 3.0);
  w.time = 0.25;
  write_particles_vtp(root / "snap&1" / "particles_1.vtp", w, {});
  write_contacts_vtp(root / "contacts_1.vtp", w, {}, kDt);
  pvd.add(w.time, "snap&1/particles_1.vtp", 0);
  pvd.add(w.time, "contacts_1.vtp", 1);
  pvd.write();

  const json spec1_particles =
      particles_spec(root / "snap&1" / "particles_1.vtp", w, {0, 0, 0, 1, 1, 0});
  const json spec1_contacts =
      contacts_spec(root / "contacts_1.vtp", json::array(), json::array(), json::array(),
                    json::array(), json::array(), json::array(), json::array(), json::array());

  const json spec = {
      {"polydata", {spec0_particles, spec0_contacts, spec1_particles, spec1_contacts}},
      {"pvd",
       {{{"file", (root / "run.pvd").string()},
         {"datasets",
          {dataset(0.0, 0, "particles_0.vtp"), dataset(0.0, 1, "contacts_0.vtp"),
           dataset(0.25, 0, "snap&1/particles_1.vtp"), dataset(0.25, 1, "contacts_1.vtp")}}}}}};
  const auto spec_file = root / "spec.json";
  std::ofstream(spec_file) << spec.dump(2);

  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();
  }
  EXPECT_EQ(run_checker(spec_file), 0)
      << "check_vtk.py found mismatches (printed above); spec " << spec_file << ":\n"
      << spec.dump(2);
}

}  // namespace
}  // namespace dilatant::vtk_writer_test
