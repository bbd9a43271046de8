#pragma once
// The records a shear cell's time series yields besides its rheology
// (measure/rheology.hpp): each a typed set of named quantities, computed once
// from the rows and written into summary.json by itself (docs/shear-cell.md
// "summary.json"). Steady averages are over the rows past the transient
// (measure/flow_series.hpp); the solver's record covers the whole run.
#include <nlohmann/json.hpp>
#include <vector>

#include "measure/flow_series.hpp"

namespace dilatant {

// The particle stress tensor's steady averages (measure/particle_stress.hpp),
// code units; written in the paper's (stress `unit`). Two friction
// coefficients, each a ratio of means:
//   mu_pressure = sigma_zx / p, p = -tr(sigma)/3 the measured pressure, its
//                 error propagated from both as if independent;
//   mu_eff      = sigma_zx / P with P the normal stress imposed (code units,
//                 > 0: the pressure-imposed cell), the definition of Boyer,
//                 Guazzelli & Pouliquen (PRL 107, 188301 (2011): mu = tau / P
//                 with P the particle pressure the plate imposes), its error
//                 sigma_zx's alone; without an imposed one (imposed_normal 0)
//                 it is mu_pressure. mu_eff_definition says which.
struct StressRecord {
  SteadyAverage shear, pressure, n1, n2;
  Tensor3 tensor{};  // sigma_ab, the mean of each component
  static StressRecord of(const std::vector<FlowRow>& rows, double from);
  void write(nlohmann::json& summary, double unit, double imposed_normal = 0.0) const;
};

// Contact fractions: boundary lubrication (BL) among closed particle contacts,
// beyond s_lim, impulsive (closed within the step), BL among persistent ones.
struct ContactRecord {
  SteadyAverage bl, over_s_lim, impulsive, bl_persistent;
  static ContactRecord of(const std::vector<FlowRow>& rows, double from);
  void write(nlohmann::json& summary) const;
};

// The steady state's energy budget, code units (force x velocity): the
// drive's power equals the dissipation in impacts, friction and the fluid
// plus d(KE)/dt. Dissipations are positive.
struct EnergyRecord {
  SteadyAverage injected, impacts, friction_bl, friction_hd, lubrication, drag, kinetic;
  SteadyAverage sliding_bl, sliding_hd;  // |F_t| v_s at particle-particle contacts
  static EnergyRecord of(const std::vector<FlowRow>& rows, double from);
  void write(nlohmann::json& summary) const;
};

// Forces of the particles on the rough walls (null without walls).
struct WallForceRecord {
  SteadyAverage bottom_x, top_z, bottom_z;
  bool walls = true;
  static WallForceRecord of(const std::vector<FlowRow>& rows, double from, bool walls);
  void write(nlohmann::json& summary) const;
};

// How well the contact problem was solved over the whole run: steps, mean
// iterations, unconverged steps, the contact residual (solver/contact_residual.hpp)
// and the largest overlap, each worst with its step and bodies (ids; a plane
// k as -(k+1), as contacts.csv).
struct SolverRecord {
  double steps = 0.0, iterations = 0.0, unconverged = 0.0;
  double residual_max = 0.0, residual_rms_sum = 0.0;  // largest; sum over steps of the RMS
  const FlowRow* worst_residual = nullptr;            // the row that holds residual_max
  const FlowRow* deepest = nullptr;                   // the row that holds the largest overlap
  static SolverRecord of(const std::vector<FlowRow>& rows);
  double max_overlap() const { return deepest != nullptr ? deepest->max_overlap : 0.0; }
  // Also overlap_tolerance and overlap_exceeded, against `overlap_tolerance`.
  void write(nlohmann::json& summary, double overlap_tolerance) const;
};

}  // namespace dilatant
