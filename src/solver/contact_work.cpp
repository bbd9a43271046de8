#include "solver/contact_work.hpp"

namespace dilatant {

ContactWork contact_work(const std::vector<Contact>& contacts,
                         const std::vector<Vec3>& free_velocity,
                         const std::vector<Vec3>& end_velocity) {
  ContactWork w;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& c = contacts[k];
    if (c.p_n <= 0.0 && c.p_lub == 0.0 && c.p_t.squaredNorm() == 0.0) continue;
    const Vec3 mean = 0.5 * (free_velocity[k] + end_velocity[k]);
    const double mean_n = c.normal.dot(mean);
    w.normal += c.p_n * mean_n;
    w.lubrication += c.p_lub * mean_n;
    const double tangential = c.p_t.dot(mean);
    if (c.regime == Regime::Hydrodynamic) {
      w.tangential_hd += tangential;
    } else {
      w.tangential_bl += tangential;
    }
  }
  return w;
}

}  // namespace dilatant
