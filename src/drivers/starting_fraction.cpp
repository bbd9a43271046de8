#include "drivers/starting_fraction.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "drivers/shear_cell.hpp"
#include "drivers/shear_cell_state.hpp"
#include "drivers/shear_cell_summary.hpp"

namespace dilatant {

namespace {

double scan_offset(int k, double step) {
  // 0, +step, -step, +2 step, -2 step, ...
  const int n = (k + 1) / 2;
  return (k % 2 == 1 ? 1.0 : -1.0) * n * step;
}

}  // namespace

double starting_bulk_fraction(const Config& config) {
  return bulk_fraction(ShearCell(config).state());
}

double checkpoint_bulk_fraction(const std::filesystem::path& checkpoint) {
  return bulk_fraction(load_checkpoint(checkpoint));
}

StartingFractionMatch match_starting_bulk(Config config, double target, double tolerance,
                                          int max_packings, const std::atomic<bool>* stop) {
  StartingFractionMatch best;
  best.phi_bulk_start = std::numeric_limits<double>::quiet_NaN();
  const double phi_0 = config.cell()->phi;
  double estimate = phi_0;
  for (int k = 0; k < max_packings; ++k) {
    if (stop != nullptr && stop->load()) break;
    const double phi = k == 0 ? phi_0 : estimate + scan_offset(k - 1, tolerance);
    config.cell()->phi = phi;
    double bulk = std::numeric_limits<double>::quiet_NaN();
    try {
      bulk = starting_bulk_fraction(config);
    } catch (const std::runtime_error&) {
      // This phi does not pack (too dense): recorded, and the search goes on.
    }
    best.tried.emplace_back(phi, bulk);
    if (!std::isfinite(bulk)) continue;  // the estimate stays phi_0 if the first fails
    if (k == 0) estimate = phi_0 + target - bulk;
    if (!std::isfinite(best.phi_bulk_start) ||
        std::abs(bulk - target) < std::abs(best.phi_bulk_start - target)) {
      best.phi = phi;
      best.phi_bulk_start = bulk;
    }
    if (std::abs(bulk - target) <= tolerance) break;
  }
  best.within_tolerance = std::abs(best.phi_bulk_start - target) <= tolerance;
  return best;
}

}  // namespace dilatant
