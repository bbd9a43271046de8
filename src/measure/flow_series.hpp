#pragma once
// The shear cell's time series: per-step quantities are accumulated over each
// output interval (time-weighted) into one row of timeseries.csv; steady-state
// averages are block averages over the rows past the transient.
//
// Error bars: the steady rows are cut into kBlocks consecutive blocks of equal
// duration; the error is the standard error of the block means. Blocks longer
// than the correlation time make this honest; with 10 blocks over >= 5 strain
// units each block spans >= 0.5 strain.
#include <array>
#include <string>
#include <vector>

#include "measure/particle_stress.hpp"

namespace dilatant {

struct FlowRow {
  double t = 0.0, strain = 0.0, duration = 0.0;
  double wall_velocity = 0.0;  // time average over the interval
  double kinetic_energy = 0.0, contacts = 0.0, frac_bl = 0.0, frac_over_slim = 0.0;
  // Impulsive contacts (closed within the step) among the closed ones, and the
  // BL fraction of the persistent ones alone, whose s does not depend on dt.
  double frac_impulsive = 0.0, frac_bl_persistent = 0.0;
  double normal_stress = 0.0;   // mean of the walls' z forces / (Lx Ly), compressive > 0
  double bottom_force_x = 0.0;  // x force on the fixed wall
  double top_force_z = 0.0, bottom_force_z = 0.0;
  double sliding_bl = 0.0, sliding_hd = 0.0;  // sum |F_t| v_s at particle contacts
  double mean_iterations = 0.0, max_residual = 0.0, mean_dt = 0.0, steps = 0.0;
  double unconverged_steps = 0.0;
  // Residual of the contact problem at the end of the steps (solver/contact_residual.hpp),
  // in units of the load's impulse tau (2R)^2 dt: the largest of any contact in any
  // step of the interval, and the step-mean of the RMS over contacts.
  double contact_residual_max = 0.0, contact_residual_rms = 0.0;
  // Where the largest was: step and the contact's bodies (ids, as max_overlap's).
  double contact_residual_step = -1.0, contact_residual_body_i = -1.0;
  double contact_residual_body_j = -1.0;
  double phi_bulk = 0.0;     // central half of the gap, at the end of the interval
  double max_overlap = 0.0;  // largest overlap at the end of any step of the interval,
  // in this step, between these bodies (ids; a plane k as -(k+1), as contacts.csv)
  double max_overlap_step = -1.0, max_overlap_body_i = -1.0, max_overlap_body_j = -1.0;
  // Powers: drive, contact work by kind (< 0: dissipation; solver/contact_work.hpp),
  // and the rate of change of the total kinetic energy (particles and wall).
  double power_drive = 0.0, power_normal = 0.0, power_bl = 0.0, power_hd = 0.0;
  double power_lubrication = 0.0, power_drag = 0.0;  // fluid forces (fluid/)
  double power_kinetic = 0.0;
  // Particle stress tensor (measure/particle_stress.hpp), time average, code units.
  Tensor3 stress{};
};

std::string flow_csv_header();
std::string flow_csv_row(const FlowRow& row, double lz);

// Sums of one output interval.
struct IntervalSums {
  double time = 0.0, velocity = 0.0, kinetic_energy = 0.0, contacts = 0.0;
  double closed = 0.0, boundary = 0.0, over_s_lim = 0.0;  // time-weighted counts
  double impulsive = 0.0, impulsive_boundary = 0.0;
  double normal_stress = 0.0, bottom_force_x = 0.0, top_force_z = 0.0, bottom_force_z = 0.0;
  double sliding_bl = 0.0, sliding_hd = 0.0;
  double iterations = 0.0, max_residual = 0.0, steps = 0.0, unconverged = 0.0;
  double contact_residual_max = 0.0, contact_residual_rms = 0.0;  // max; sum over steps
  double contact_residual_step = -1.0, contact_residual_body_i = -1.0;
  double contact_residual_body_j = -1.0;
  double max_overlap = 0.0;
  double max_overlap_step = -1.0, max_overlap_body_i = -1.0, max_overlap_body_j = -1.0;
  double work_drive = 0.0, work_normal = 0.0, work_bl = 0.0, work_hd = 0.0;
  double work_lubrication = 0.0, work_drag = 0.0;
  double kinetic_start = 0.0, kinetic_end = 0.0;  // total, particles and wall
  Tensor3 stress_dt{};                            // sum over steps of sigma dt

  FlowRow close(double t, double strain) const;
};

struct SteadyAverage {
  double mean = 0.0;
  double error = 0.0;
  int samples = 0;
};

inline constexpr int kBlocks = 10;

// Duration-weighted block average of field(row) over rows with strain > from.
template <class Field>
SteadyAverage steady_average(const std::vector<FlowRow>& rows, double from, Field field);

}  // namespace dilatant

#include "measure/flow_series_impl.hpp"
