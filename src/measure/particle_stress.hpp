#pragma once
// The particle stress tensor of a cell from its contacts and velocities: the
// virial (Irving–Kirkwood) stress of a granular assembly, e.g. Andreotti,
// Forterre & Pouliquen, "Granular Media" (2013), section 2.3; Christoffersen,
// Mehrabadi & Nemat-Nasser, J. Appl. Mech. 48, 339 (1981):
//
//     sigma_ab = -(1/V) [ sum_c r_a F_b  +  sum_n m_n v'_a v'_b ] ,
//
// tensile positive (a compressed packing has sigma_zz < 0, pressure
// p = -tr(sigma)/3 > 0), with, for contact c between bodies i and j,
// r = x_i - x_j the branch vector and F the force on i (contact, friction and
// squeeze film), and v' the velocity relative to the mean flow. The first
// index is the branch's: sigma_zx is the x force carried across a plane of
// constant z, the shear stress a wall at constant z feels.
//
// Why the wall cell's sigma_zx is exactly the applied stress on average: for
// every body, sum_c (z_i - z_j) F_x = sum_n z_n F_n,x (each contact gives
// +F to i and -F to j). The walls' spheres sit at z = 0 and z = Lz, and the
// top wall feels -tau Lx Ly from the contacts in steady state; the mobile
// spheres' sum z_n F_n,x equals d/dt(sum z m v_x) - sum m v_z v_x. So
//
//     sum_c r_z F_x + sum_n m v_z v_x = -Lz tau Lx Ly + d/dt(...),
//
// and sigma_zx = tau with V = Lx Ly Lz once the time derivatives average out
// (tests/measure/particle_stress_test.cpp checks this to round-off, step by
// step, with the walls' and particles' momenta at the window's ends). Discrete
// form: contact impulses act on positions at the step's start and the
// positions advance with the end-of-step velocity, so the kinetic term takes
// the end-of-step velocities.
//
// The Stokes drag on each body is a force of the fluid, not of a pair: it is
// not in this tensor (the stress the fluid carries is the fluid's). With
// fluid.drag = "stokes" sigma_zx therefore falls short of tau by the drag's
// share; the squeeze film is a pair force and is in.
#include <array>
#include <vector>

#include "detection/contact.hpp"
#include "world/bodies.hpp"
#include "world/shear_flow.hpp"

namespace dilatant {

// A 3x3 tensor, row-major (k = 3 a + b): trivially copyable, so it sits in the
// time series' rows and the checkpoint's raw bytes.
using Tensor3 = std::array<double, 9>;

inline constexpr int kX = 0, kY = 1, kZ = 2;
inline constexpr int tensor_index(int a, int b) { return 3 * a + b; }

// sum_c r (x) P over the contacts of one step, P the impulse on i over the step
// (normal, friction and squeeze film): dt times the contact virial. The branch
// vector is rebuilt from the contact record, r = (r_i + r_j + gap) n (with r_j = 0
// for a plane), so periodic images need no care.
Tensor3 contact_impulse_moment(const std::vector<Contact>& contacts);

// sum_n m_n v'_n (x) v'_n over the bodies with mass (fixed bodies, e.g. the
// walls' spheres, have none), v' = v - u(z), u the mean flow (world/shear_flow.hpp).
Tensor3 velocity_fluctuation_moment(const Bodies& bodies, ShearFlow flow);

// The invariants rheologists report (x flow, y vorticity, z gradient).
struct StressInvariants {
  double shear = 0.0;     // sigma_zx
  double pressure = 0.0;  // -(sigma_xx + sigma_yy + sigma_zz) / 3
  double n1 = 0.0;        // sigma_xx - sigma_zz
  double n2 = 0.0;        // sigma_zz - sigma_yy
};
StressInvariants invariants(const Tensor3& sigma);

}  // namespace dilatant
