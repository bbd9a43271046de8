#include "io/contacts_csv.hpp"

#include <fmt/format.h>

namespace dilatant {

std::string contacts_csv(const Bodies& bodies, const std::vector<Contact>& contacts, double dt) {
  std::string out = "i,j,normal_force,tangential_force,sliding_speed,sommerfeld,regime\n";
  for (const Contact& c : contacts) {
    if (c.p_n <= 0.0) continue;
    const long long j = c.with_plane() ? static_cast<long long>(c.other)
                                       : static_cast<long long>(bodies.id[c.other]);
    fmt::format_to(std::back_inserter(out), "{},{},{:.10g},{:.10g},{:.10g},{:.10g},{}\n",
                   bodies.id[c.i], j, c.p_n / dt, c.p_t.norm() / dt, c.sliding_speed, c.sommerfeld,
                   regime_name(c.regime));
  }
  return out;
}

}  // namespace dilatant
