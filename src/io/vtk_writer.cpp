#include "io/vtk_writer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "io/atomic_file.hpp"

namespace dilatant {

namespace {

// The reader parses ASCII arrays with operator>>, which rejects inf and nan.
double representable(double v) {
  constexpr double kMax = std::numeric_limits<double>::max();
  if (std::isnan(v)) return kMax;
  if (std::isinf(v)) return v > 0.0 ? kMax : -kMax;
  return v;
}

// Shortest text that reads back as the same double.
void append_double(std::string& out, double v) {
  fmt::format_to(std::back_inserter(out), "{}", representable(v));
}

void append_vec(std::string& out, const Vec3& v) {
  append_double(out, v[0]);
  out += ' ';
  append_double(out, v[1]);
  out += ' ';
  append_double(out, v[2]);
}

// One ASCII <DataArray> of n tuples; tuple(k, out) appends tuple k's components.
template <class Tuple>
void data_array(std::string& out, std::string_view type, std::string_view name, int components,
                std::size_t n, Tuple&& tuple) {
  fmt::format_to(std::back_inserter(out),
                 "        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" "
                 "format=\"ascii\">",
                 type, name, components);
  for (std::size_t k = 0; k < n; ++k) {
    out += "\n          ";
    tuple(k, out);
  }
  if (n > 0) out += "\n        ";
  out += "</DataArray>\n";
}

template <class Value>
void scalar_array(std::string& out, std::string_view type, std::string_view name, std::size_t n,
                  Value&& value) {
  data_array(out, type, name, 1, n, [&](std::size_t k, std::string& o) {
    using T = decltype(value(k));
    if constexpr (std::is_floating_point_v<T>) {
      append_double(o, value(k));
    } else {
      fmt::format_to(std::back_inserter(o), "{}", static_cast<long long>(value(k)));
    }
  });
}

// A cell block (<Verts>, <Lines>) of n cells with `size` consecutive points each.
void cell_block(std::string& out, std::string_view element, std::size_t n, std::size_t size) {
  fmt::format_to(std::back_inserter(out), "      <{}>\n", element);
  data_array(out, "Int64", "connectivity", 1, n, [&](std::size_t k, std::string& o) {
    for (std::size_t p = 0; p < size; ++p) {
      if (p > 0) o += ' ';
      fmt::format_to(std::back_inserter(o), "{}", k * size + p);
    }
  });
  data_array(out, "Int64", "offsets", 1, n, [&](std::size_t k, std::string& o) {
    fmt::format_to(std::back_inserter(o), "{}", (k + 1) * size);
  });
  fmt::format_to(std::back_inserter(out), "      </{}>\n", element);
}

std::string polydata_header(std::size_t points, std::size_t verts, std::size_t lines) {
  return fmt::format(
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <PolyData>\n"
      "    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" "
      "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
      points, verts, lines);
}

constexpr std::string_view kPolydataFooter =
    "    </Piece>\n"
    "  </PolyData>\n"
    "</VTKFile>\n";

std::string xml_attribute(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::int32_t vtk_regime_code(Regime r) {
  switch (r) {
    case Regime::Open:
      return 0;
    case Regime::Stick:
      return 1;
    case Regime::BoundaryLubricated:
      return 2;
    case Regime::Hydrodynamic:
      return 3;
    case Regime::Frictionless:
      return 4;
  }
  return -1;
}

void write_particles_vtp(const std::filesystem::path& file, const World& world,
                         const std::vector<std::uint8_t>& body_group) {
  const Bodies& b = world.bodies;
  const std::size_t n = b.size();
  if (!body_group.empty() && body_group.size() != n) {
    throw std::invalid_argument(
        fmt::format("{}: {} body groups for {} spheres", file.string(), body_group.size(), n));
  }
  const auto group = [&](std::size_t i) -> std::uint8_t {
    if (!body_group.empty()) return body_group[i];
    return b.is_fixed(i) ? 1 : 0;
  };

  std::string out = polydata_header(n, n, 0);
  out += "      <!-- group: 0 mobile, 1 bottom wall, 2 top wall; wall: 1 if group != 0 -->\n";
  out += "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
  scalar_array(out, "Float64", "radius", n, [&](std::size_t i) { return b.radius[i]; });
  data_array(out, "Float64", "velocity", 3, n,
             [&](std::size_t i, std::string& o) { append_vec(o, b.velocity[i]); });
  data_array(out, "Float64", "angular_velocity", 3, n,
             [&](std::size_t i, std::string& o) { append_vec(o, b.angular_velocity[i]); });
  scalar_array(out, "Int64", "id", n, [&](std::size_t i) { return b.id[i]; });
  scalar_array(out, "UInt8", "group", n, group);
  scalar_array(out, "UInt8", "wall", n, [&](std::size_t i) { return group(i) != 0 ? 1 : 0; });
  out += "      </PointData>\n";
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, n,
             [&](std::size_t i, std::string& o) { append_vec(o, b.position[i]); });
  out += "      </Points>\n";
  cell_block(out, "Verts", n, 1);
  out += kPolydataFooter;
  write_file_atomically(file, out);
}

void write_contacts_vtp(const std::filesystem::path& file, const World& world,
                        const std::vector<Contact>& contacts, double dt) {
  const Bodies& b = world.bodies;
  std::vector<const Contact*> shown;
  for (const Contact& c : contacts) {
    if (c.with_plane() || !(c.p_n > 0.0)) continue;
    if (c.i < 0 || static_cast<std::size_t>(c.i) >= b.size() ||
        static_cast<std::size_t>(c.other) >= b.size()) {
      throw std::out_of_range(fmt::format("{}: contact between spheres {} and {} of {}",
                                          file.string(), c.i, c.other, b.size()));
    }
    shown.push_back(&c);
  }
  const std::size_t n = shown.size();

  std::string out = polydata_header(2 * n, 0, n);
  out +=
      "      <!-- regime: 0 open, 1 stick, 2 bl, 3 hd, 4 frictionless; boundary_lubricated: 1 if "
      "stick or bl "
      "-->\n";
  out += "      <CellData Scalars=\"normal_force\">\n";
  scalar_array(out, "Float64", "normal_force", n,
               [&](std::size_t k) { return shown[k]->p_n / dt; });
  scalar_array(out, "Float64", "tangential_force", n,
               [&](std::size_t k) { return shown[k]->p_t.norm() / dt; });
  scalar_array(out, "Float64", "sliding_speed", n,
               [&](std::size_t k) { return shown[k]->sliding_speed; });
  scalar_array(out, "Float64", "sommerfeld", n,
               [&](std::size_t k) { return shown[k]->sommerfeld; });
  scalar_array(out, "Int32", "regime", n,
               [&](std::size_t k) { return vtk_regime_code(shown[k]->regime); });
  scalar_array(out, "UInt8", "boundary_lubricated", n, [&](std::size_t k) {
    const Regime r = shown[k]->regime;
    return r == Regime::Stick || r == Regime::BoundaryLubricated ? 1 : 0;
  });
  out += "      </CellData>\n";
  out += "      <Points>\n";
  data_array(out, "Float64", "Points", 3, 2 * n, [&](std::size_t p, std::string& o) {
    const Contact& c = *shown[p / 2];
    const Vec3& xi = b.position[c.i];
    if (p % 2 == 0) {
      append_vec(o, xi);
    } else {
      append_vec(o, xi - world.box.minimum_image(xi, b.position[c.other]));
    }
  });
  out += "      </Points>\n";
  cell_block(out, "Lines", n, 2);
  out += kPolydataFooter;
  write_file_atomically(file, out);
}

PvdCollection::PvdCollection(std::filesystem::path pvd_file) : pvd_file_(std::move(pvd_file)) {}

void PvdCollection::add(double time, const std::string& relative_file, int part) {
  entries_.push_back({time, relative_file, part});
}

void PvdCollection::write() const {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& e : entries_) {
    out += "    <DataSet timestep=\"";
    append_double(out, e.time);
    fmt::format_to(std::back_inserter(out), "\" group=\"\" part=\"{}\" file=\"{}\"/>\n", e.part,
                   xml_attribute(e.file));
  }
  out +=
      "  </Collection>\n"
      "</VTKFile>\n";
  write_file_atomically(pvd_file_, out);
}

}  // namespace dilatant
