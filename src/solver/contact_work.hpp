#pragma once
// The work of the contact impulses in one step, split by kind. For any impulses,
// with u_c^free the relative velocity before any contact acts (after the
// prediction) and u_c^end after the solve, the kinetic energy changes by exactly
//
//     KE(end) - KE(free) = sum_c P_c . (u_c^free + u_c^end) / 2
//
// (the bilinear identity m (v+^2 - v-^2)/2 = m (v+ - v-) . (v+ + v-)/2, summed
// over bodies and regrouped by contacts). Its normal part is the loss of the
// perfectly inelastic impacts, its tangential part the friction loss, which we
// split by the contact's final regime (stick/BL or HD), and the squeeze film's
// impulse its viscous loss. All terms are <= 0 for a dissipative solve.
// With implicit drag the same identity holds with u^free the velocities before
// the drag acts (time_stepper.cpp), the drag's own work being counted apart.
#include <vector>

#include "detection/contact.hpp"

namespace dilatant {

struct ContactWork {
  double normal = 0.0;
  double tangential_bl = 0.0;  // stick and boundary-lubricated contacts
  double tangential_hd = 0.0;
  double lubrication = 0.0;  // squeeze films
  double total() const { return normal + tangential_bl + tangential_hd + lubrication; }
};

// `free_velocity[k]` is u^free of contacts[k]; `end_velocity[k]` its u^end.
ContactWork contact_work(const std::vector<Contact>& contacts,
                         const std::vector<Vec3>& free_velocity,
                         const std::vector<Vec3>& end_velocity);

}  // namespace dilatant
