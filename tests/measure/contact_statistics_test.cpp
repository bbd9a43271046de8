// Contact counts and the Sommerfeld histogram (measure/contact_statistics.hpp)
// on hand-made contacts whose answer is known.
#include "measure/contact_statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace dilatant::contact_statistics_test {
namespace {

Contact between(int i, int j, Regime regime, Regime previous, double s, double v = 0.0) {
  Contact c;
  c.i = i;
  c.other = j;
  c.p_n = 1.0;
  c.p_t = Vec3(0.2, 0.0, 0.0);
  c.regime = regime;
  c.previous_regime = previous;
  c.sommerfeld = s;
  c.sliding_speed = v;
  return c;
}

// n dynamic spheres; the last `driven` of them are driven (a boundary's).
Bodies spheres(int n, int driven = 0) {
  Bodies b;
  for (int i = 0; i < n; ++i) b.add_sphere(i, Vec3(0.0, 0.0, 2.0 * i), 1.0, 1.0, i >= n - driven);
  for (int i = n - driven; i < n; ++i) b.set_driven(static_cast<std::size_t>(i), 1);
  return b;
}

TEST(ContactCounts, CountParticleContactsByRegime) {
  // Bodies 0-3 dynamic, 4 driven (a wall sphere).
  const Bodies bodies = spheres(5, 1);
  std::vector<Contact> c = {
      between(0, 1, Regime::Stick, Regime::Stick, 0.0),
      between(1, 2, Regime::BoundaryLubricated, Regime::Open, 1e-6, 2.0),   // impulsive BL
      between(2, 3, Regime::Hydrodynamic, Regime::Hydrodynamic, 0.2, 3.0),  // beyond s_lim
      between(0, 3, Regime::Hydrodynamic, Regime::Open, 1e-3, 1.0),         // impulsive HD
      between(3, 4, Regime::Stick, Regime::Stick, 0.0),                     // driven: not counted
  };
  c.push_back(between(0, -1, Regime::Stick, Regime::Stick, 0.0));  // plane: not counted
  Contact open = between(1, 3, Regime::Open, Regime::Open, 0.0);
  open.p_n = 0.0;
  c.push_back(open);
  const double dt = 0.1;
  const ContactCounts n = count_contacts(bodies, c, dt, 0.1, nullptr);
  EXPECT_EQ(n.closed, 4.0);
  EXPECT_EQ(n.boundary, 2.0);
  EXPECT_EQ(n.over_s_lim, 1.0);
  EXPECT_EQ(n.impulsive, 2.0);
  EXPECT_EQ(n.impulsive_boundary, 1.0);
  // |F_t| v_s with |F_t| = 0.2 / dt = 2.
  EXPECT_NEAR(n.sliding_power_bl, 2.0 * 2.0, 1e-14);
  EXPECT_NEAR(n.sliding_power_hd, 2.0 * 3.0 + 2.0 * 1.0, 1e-14);
}

TEST(SommerfeldHistogram, BinsByDecadeWithStickingBelowAndAbove) {
  SommerfeldHistogram h;
  h.add(0.0);    // sticking
  h.add(1e-11);  // below 1e-10
  h.add(1e3);    // above 1e2
  h.add(1e-10);  // first bin: [1e-10, 1e-9.8)
  h.add(3e-5);   // log10 = -4.52: bin (5.48) * 5 = 27
  EXPECT_EQ(h.sticking, 1.0);
  EXPECT_EQ(h.below, 1.0);
  EXPECT_EQ(h.above, 1.0);
  EXPECT_EQ(h.count[0], 1.0);
  EXPECT_EQ(h.count[27], 1.0);
  EXPECT_NEAR(SommerfeldHistogram::bin_lower_edge(0), 1e-10, 1e-24);
  EXPECT_NEAR(SommerfeldHistogram::bin_lower_edge(5), 1e-9, 1e-23);
  EXPECT_NEAR(SommerfeldHistogram::bin_lower_edge(SommerfeldHistogram::kBins), 1e2, 1e-12);
  // count_contacts fills it with s, and s = 0 for sticking contacts.
  SommerfeldHistogram g;
  count_contacts(spheres(2), {between(0, 1, Regime::Stick, Regime::Stick, 0.5)}, 0.1, 0.1, &g);
  EXPECT_EQ(g.sticking, 1.0);
}

}  // namespace
}  // namespace dilatant::contact_statistics_test
