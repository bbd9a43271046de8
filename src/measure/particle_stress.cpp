#include "measure/particle_stress.hpp"

namespace dilatant {

Tensor3 contact_impulse_moment(const std::vector<Contact>& contacts) {
  Tensor3 m{};
  for (const Contact& c : contacts) {
    if (c.p_n <= 0.0 && c.p_lub == 0.0 && c.p_t.squaredNorm() == 0.0) continue;
    const Vec3 r = (c.arm_i + c.arm_j + c.gap) * c.normal;
    const Vec3 impulse = (c.p_n + c.p_lub) * c.normal + c.p_t;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) m[tensor_index(a, b)] += r[a] * impulse[b];
  }
  return m;
}

Tensor3 velocity_fluctuation_moment(const Bodies& bodies, ShearFlow flow) {
  Tensor3 m{};
  for (std::size_t n = 0; n < bodies.size(); ++n) {
    if (bodies.is_fixed(n)) continue;
    Vec3 v = bodies.velocity[n];
    v[kX] -= flow.shear_rate * (bodies.position[n][kZ] - flow.z0);
    const double mass = bodies.mass(n);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) m[tensor_index(a, b)] += mass * v[a] * v[b];
  }
  return m;
}

StressInvariants invariants(const Tensor3& s) {
  const double xx = s[tensor_index(kX, kX)], yy = s[tensor_index(kY, kY)];
  const double zz = s[tensor_index(kZ, kZ)];
  return {.shear = s[tensor_index(kZ, kX)],
          .pressure = -(xx + yy + zz) / 3.0,
          .n1 = xx - zz,
          .n2 = zz - yy};
}

}  // namespace dilatant
