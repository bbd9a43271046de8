// The [sediment] section of the table of keys (io/config_keys.hpp): the
// simulated centrifugation of `dilatant jam` (drivers/sediment.hpp).
#include "io/config_key_builders.hpp"

namespace dilatant {

using namespace config_key_builders;

void add_sediment_keys(std::vector<ConfigKey>& k) {
  using enum RunMode;
  const auto positive = [](const Vec3& v) { return (v.array() > 0.0).all(); };
  k.push_back(vec3("sediment", "size", Sediment, &sediment, &SedimentConfig::size, +positive,
                   "every length must be > 0", "> 0 each", "R",
                   "Lx, Ly (periodic), and the height from the floor to the lid"));
  k.push_back(integer("sediment", "max_spheres", Sediment, &sediment, &SedimentConfig::max_spheres,
                      1, std::numeric_limits<int>::max(), "must be >= 1", ">= 1",
                      "a sediment.size and sediment.phi estimated to hold more spheres are "
                      "refused before the set-up; raise it to run a larger sediment"));
  k.push_back(number("sediment", "phi", Sediment, &sediment, &SedimentConfig::phi, open(0.0, 0.55),
                     "",
                     "volume fraction of the suspension before it settles (the paper "
                     "centrifuges at 0.47)"));
  k.push_back(number("sediment", "radius_min", Sediment, &sediment, &SedimentConfig::radius_min,
                     Range{0.0, 1.0, false, true, {}, {}}, "R",
                     "radii are uniform in [radius_min, 1]"));
  k.push_back(
      ConfigKey{"sediment", "seed", Sediment, "integer", "", ">= 0",
                "random seed of the first sample; sample i uses seed + i",
                [](const Section& s, Config& c, const std::filesystem::path&) {
                  std::int64_t& v = sediment(c).seed;
                  v = s.integer("seed", v);
                  config_detail::check(s, "seed", v, v >= 0, "must be >= 0");
                },
                [](const Config& c, toml::table& t) { t.insert("seed", sediment(mut(c)).seed); }});
  k.push_back(integer("sediment", "samples", Sediment, &sediment, &SedimentConfig::samples, 1, 1000,
                      "must be in [1, 1000]", "[1, 1000]",
                      "independent packings averaged (the error bar is their scatter)"));
  k.push_back(number("sediment", "stokes_number", Sediment, &sediment,
                     &SedimentConfig::stokes_number, above(0.0), "",
                     "g tau^2 / R with tau = 2 rho_p R^2 / (9 eta_f): how inertial the "
                     "settling is (small: overdamped, as fine powders settle)"));
  k.push_back(number("sediment", "exclusion", Sediment, &sediment, &SedimentConfig::exclusion,
                     at_least(0.0), "R",
                     "left out of the measured fraction at the floor and at the free surface"));
}

}  // namespace dilatant
