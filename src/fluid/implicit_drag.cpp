#include "fluid/implicit_drag.hpp"

#include <stdexcept>
#include <string>

namespace dilatant {

namespace {

template <class T>
void check_size(const std::vector<T>& v, std::size_t n, const char* name) {
  if (!v.empty() && v.size() != n) {
    throw std::invalid_argument(std::string("BodyDrag::") + name + ": " + std::to_string(v.size()) +
                                " entries for " + std::to_string(n) + " bodies");
  }
}

}  // namespace

void ImplicitDrag::predict(const BodyDrag& drag, double dt, Bodies& b) {
  const std::size_t n = b.size();
  check_size(drag.translational, n, "translational");
  check_size(drag.fluid_velocity, n, "fluid_velocity");
  check_size(drag.rotational, n, "rotational");
  check_size(drag.fluid_spin, n, "fluid_spin");
  inv_mass_ = b.inv_mass;
  inv_inertia_ = b.inv_inertia;
  velocity_ = b.velocity;
  angular_velocity_ = b.angular_velocity;
  active_ = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (b.is_fixed(i)) continue;
    if (!drag.translational.empty()) {
      // (m + dt zeta) v_free = m v_pred + dt zeta U   (fluid_forces.hpp)
      const double m = 1.0 / b.inv_mass[i], damping = dt * drag.translational[i];
      const Vec3 u = drag.fluid_velocity.empty() ? Vec3::Zero() : drag.fluid_velocity[i];
      b.velocity[i] = (m * b.velocity[i] + damping * u) / (m + damping);
      inv_mass_[i] = 1.0 / (m + damping);
    }
    if (!drag.rotational.empty()) {
      const double inertia = 1.0 / b.inv_inertia[i], damping = dt * drag.rotational[i];
      const Vec3 omega = drag.fluid_spin.empty() ? Vec3::Zero() : drag.fluid_spin[i];
      b.angular_velocity[i] =
          (inertia * b.angular_velocity[i] + damping * omega) / (inertia + damping);
      inv_inertia_[i] = 1.0 / (inertia + damping);
    }
  }
}

double ImplicitDrag::work(const BodyDrag& drag, double dt, const Bodies& b) const {
  if (velocity_.size() != b.size()) return 0.0;  // predict() has not run
  double w = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (b.is_fixed(i)) continue;
    if (!drag.translational.empty()) {
      const Vec3 u = drag.fluid_velocity.empty() ? Vec3::Zero() : drag.fluid_velocity[i];
      const Vec3 impulse = -dt * drag.translational[i] * (b.velocity[i] - u);
      w += 0.5 * impulse.dot(velocity_[i] + b.velocity[i]);
    }
    if (!drag.rotational.empty()) {
      const Vec3 omega = drag.fluid_spin.empty() ? Vec3::Zero() : drag.fluid_spin[i];
      const Vec3 impulse = -dt * drag.rotational[i] * (b.angular_velocity[i] - omega);
      w += 0.5 * impulse.dot(angular_velocity_[i] + b.angular_velocity[i]);
    }
  }
  return w;
}

void ImplicitDrag::use_effective_masses(Bodies& b) {
  if (!active_ || swapped_) return;
  b.inv_mass.swap(inv_mass_);
  b.inv_inertia.swap(inv_inertia_);
  swapped_ = true;
}

void ImplicitDrag::restore_masses(Bodies& b) {
  if (swapped_) {
    b.inv_mass.swap(inv_mass_);
    b.inv_inertia.swap(inv_inertia_);
    swapped_ = false;
  }
  active_ = false;
}

}  // namespace dilatant
