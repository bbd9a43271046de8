#pragma once
// The packing the sweep benchmark times (bench/solver_sweep_bench.cpp, whose
// header describes how it is built): the paper's cell filled by uniaxial
// compression, then one sheared step with each friction law.
#include <cstddef>
#include <vector>

#include "detection/contact.hpp"
#include "friction/friction_law.hpp"
#include "solver/contact_solver.hpp"
#include "world/bodies.hpp"

namespace dilatant::bench {

constexpr int kSpheres = 1300;
constexpr double kLx = 25.0, kLy = 10.0, kLz = 27.0;
constexpr double kRadiusMin = 0.8, kRadiusMax = 1.0;
constexpr double kMu0 = 0.1;
constexpr double kDt = 0.01;        // time unit: 1 / gamma_dot = 10
constexpr double kShearRate = 0.1;  // the wall-to-wall speed difference is 2.7
constexpr double kPhiLoose = 0.3;   // random sequential addition, well below its 0.38 limit
constexpr int kIncrements = 100;    // ceiling-lowering steps
constexpr int kMaxRelaxSteps = 30;  // at most, to remove the last overlaps
constexpr double kMaxOverlap = 1e-6;

struct Case {
  FrictionLaw law;
  Bodies bodies;                  // end-of-step velocities, consistent with the impulses
  std::vector<Contact> contacts;  // with the solved impulses
  SolveReport solve;
};

struct Packing {
  Case coulomb;
  Case stribeck;
  int bodies = 0;
  double phi_bulk = 0.0;      // solid fraction between z = 3 and z = 24
  double phi_cell = 0.0;      // total solid volume / (25 x 10 x 27)
  double max_overlap = 0.0;   // before the shear step
  int compression_steps = 0;  // increments + relaxation steps
  double compression_seconds = 0.0;
  double setup_seconds = 0.0;
};

// The packing and both sheared steps, built once per process.
const Packing& packing();

struct RegimeMix {
  double open = 0, stick = 0, bl = 0, hd = 0, frictionless = 0;  // fractions of all contacts
};

RegimeMix regime_mix(const std::vector<Contact>& contacts);
std::size_t loaded(const std::vector<Contact>& contacts);
// Loaded contacts per sphere (a sphere pair counts for both spheres).
double contacts_per_sphere(const std::vector<Contact>& contacts, int bodies);
// CPU time of the calling thread, ns.
double thread_cpu_ns();

}  // namespace dilatant::bench
