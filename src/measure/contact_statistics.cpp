#include "measure/contact_statistics.hpp"

#include <cmath>

namespace dilatant {

void SommerfeldHistogram::add(double s) {
  if (s <= 0.0) {
    sticking += 1.0;
    return;
  }
  const double x = (std::log10(s) - kLogMin) * kBinsPerDecade;
  if (x < 0.0) {
    below += 1.0;
    return;
  }
  if (x >= kBins) {
    above += 1.0;
    return;
  }
  count[static_cast<std::size_t>(x)] += 1.0;
}

double SommerfeldHistogram::bin_lower_edge(int k) {
  return std::pow(10.0, kLogMin + double(k) / kBinsPerDecade);
}

ContactCounts count_contacts(const Bodies& bodies, const std::vector<Contact>& contacts, double dt,
                             double s_lim, SommerfeldHistogram* histogram) {
  ContactCounts n;
  for (const Contact& c : contacts) {
    if (c.p_n <= 0.0 || c.with_plane()) continue;
    if (bodies.is_driven(static_cast<std::size_t>(c.i)) ||
        bodies.is_driven(static_cast<std::size_t>(c.other))) {
      continue;
    }
    n.closed += 1.0;
    const double power = c.p_t.norm() / dt * c.sliding_speed;
    if (c.regime == Regime::Stick || c.regime == Regime::BoundaryLubricated) {
      n.boundary += 1.0;
      n.sliding_power_bl += power;
    } else {
      n.sliding_power_hd += power;
    }
    if (c.sommerfeld >= s_lim) n.over_s_lim += 1.0;
    if (c.previous_regime == Regime::Open) {
      n.impulsive += 1.0;
      if (c.regime == Regime::Stick || c.regime == Regime::BoundaryLubricated) {
        n.impulsive_boundary += 1.0;
      }
    }
    if (histogram != nullptr) histogram->add(c.regime == Regime::Stick ? 0.0 : c.sommerfeld);
  }
  return n;
}

}  // namespace dilatant
