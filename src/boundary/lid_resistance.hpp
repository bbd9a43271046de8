#pragma once
// The squeeze films' resistance to the lid of the pressure-controlled
// Lees–Edwards box (boundary/image_drive.hpp): how much the normal stress
// p = -sigma_zz a step transmits falls per unit of the lid's speed W, the
// bodies' velocities held fixed,
//
//     c = -dp/dW = (1 / (V Lz)) sum_films (k / dt) (d_z n_z)^2  >= 0.
//
// Derivation. A film's impulse on i over the step is -k u_n n, its force
// -(k/dt) u_n n (fluid/squeeze_film.hpp, k = c_film dt), with u_n the pair's
// normal relative velocity at the step's end. The box's affine dilation adds
// (W/Lz) d_z to the pair's z relative velocity (Contact::dilation_drift;
// d = x_i - x_partner = |d| n), so u_n gains (W/Lz) d_z n_z. The pair's share
// of p = (1/V) sum r_z F_z (measure/particle_stress.hpp, r = d) is
// -(1/V) (k/dt) u_n n_z d_z, whose derivative in W is the term above with a
// minus sign. Holding the bodies fixed bounds the true response from above:
// free bodies give way to the films.
//
// The lid's update uses c as the linearised response of p to W over the step
// (a linearly implicit Euler step, image_drive.hpp). A film whose pair
// touches (p_n > 0) is counted as if open: with the bodies fixed the contact
// would resist even more.
#include <vector>

#include "detection/contact.hpp"

namespace dilatant {

// c above, for the contacts of one step; volume V = Lx Ly Lz, height Lz, step dt.
double film_lid_resistance(const std::vector<Contact>& contacts, double volume, double height,
                           double dt);

}  // namespace dilatant
