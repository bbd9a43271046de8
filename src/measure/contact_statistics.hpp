#pragma once
// Friction-regime statistics of the particle–particle contacts that carry load
// (contacts with a plane or a driven body, world/bodies.hpp, obey the
// boundary's law and are left out): the fraction of
// boundary-lubricated contacts P_BL (sticking or sliding with s < s_c), the
// fraction beyond s_lim, and the distribution P(s) in logarithmic bins.
#include <array>
#include <cstddef>
#include <vector>

#include "detection/contact.hpp"
#include "world/world.hpp"

namespace dilatant {

struct SommerfeldHistogram {
  // Bins of log10(s) from kLogMin to kLogMax, kBinsPerDecade per decade.
  static constexpr double kLogMin = -10.0;
  static constexpr double kLogMax = 2.0;
  static constexpr int kBinsPerDecade = 5;
  static constexpr int kBins = static_cast<int>((kLogMax - kLogMin) * kBinsPerDecade);
  std::array<double, kBins> count{};
  double sticking = 0.0;  // s = 0
  double below = 0.0;     // 0 < s < 10^kLogMin
  double above = 0.0;     // s >= 10^kLogMax

  void add(double s);
  static double bin_lower_edge(int k);
};

struct ContactCounts {
  double closed = 0.0;
  double boundary = 0.0;  // stick or BL
  double over_s_lim = 0.0;
  // Impulsive contacts: closed now, not in the previous step (a collision within
  // the step). Their N = p_n/dt, hence s, depends on dt (docs/model.md "Friction").
  double impulsive = 0.0;
  double impulsive_boundary = 0.0;
  double sliding_power_bl = 0.0;  // sum of |F_t| v_s over BL contacts
  double sliding_power_hd = 0.0;
};

// Counts over the contacts of one step between two dynamic bodies (dt converts
// impulses to forces); adds their s values to `histogram` if given.
ContactCounts count_contacts(const Bodies& bodies, const std::vector<Contact>& contacts, double dt,
                             double s_lim, SommerfeldHistogram* histogram);

}  // namespace dilatant
