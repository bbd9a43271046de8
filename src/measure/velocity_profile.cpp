#include "measure/velocity_profile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace dilatant {

void VelocityProfile::add(const World& world, double weight) {
  const Bodies& b = world.bodies;
  // A Lees–Edwards box whose height follows a pressure (boundary/image_drive.hpp)
  // is binned in z / Lz, its velocities scaled alike: the profile of the
  // reduced coordinates z lz / Lz, v_x lz / Lz, whose slope is gamma_dot.
  const double height = world.box.lees_edwards ? world.box.length[2] : lz_;
  const double scale = lz_ / height;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.is_driven(i)) continue;
    const int k = static_cast<int>(b.position[i][2] / height * bins());
    if (k < 0 || k >= bins()) continue;
    sum_vx_[k] += weight * b.velocity[i][0] * scale;
    weight_[k] += weight;
  }
}

LinearFit VelocityProfile::fit(double z_lo, double z_hi) const {
  double n = 0, sz = 0, sv = 0, szz = 0, szv = 0;
  for (int k = 0; k < bins(); ++k) {
    const double z = bin_centre(k);
    if (z < z_lo || z > z_hi || weight_[k] <= 0.0) continue;
    const double v = mean_vx(k);
    n += 1;
    sz += z;
    sv += v;
    szz += z * z;
    szv += z * v;
  }
  LinearFit f;
  const double det = n * szz - sz * sz;
  if (n < 2 || det <= 0.0) return f;
  f.slope = (n * szv - sz * sv) / det;
  f.intercept = (sv - f.slope * sz) / n;
  for (int k = 0; k < bins(); ++k) {
    const double z = bin_centre(k);
    if (z < z_lo || z > z_hi || weight_[k] <= 0.0) continue;
    f.max_deviation = std::max(f.max_deviation, std::abs(mean_vx(k) - (f.intercept + f.slope * z)));
  }
  return f;
}

std::string VelocityProfile::csv() const {
  std::string out = "z,vx,weight\n";
  for (int k = 0; k < bins(); ++k) {
    fmt::format_to(std::back_inserter(out), "{:.6g},{:.8g},{:.6g}\n", bin_centre(k), mean_vx(k),
                   weight_[k]);
  }
  return out;
}

}  // namespace dilatant
