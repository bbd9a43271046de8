#pragma once
// contacts.csv (README "Using it"): the contacts that carry load at the end of a run,
//   i,j,normal_force,tangential_force,sliding_speed,sommerfeld,regime
// i and j are the particles' ids; j = -(k+1) for a contact with plane k.
// Forces are impulses over the last step divided by dt.
#include <string>
#include <vector>

#include "detection/contact.hpp"
#include "world/bodies.hpp"

namespace dilatant {

std::string contacts_csv(const Bodies& bodies, const std::vector<Contact>& contacts, double dt);

}  // namespace dilatant
