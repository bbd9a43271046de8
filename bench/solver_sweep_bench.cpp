// Cost of ONE nonlinear Gauss–Seidel sweep (gauss_seidel_pass, solver/contact_solver.hpp)
// over the contacts of a dense, sheared, random packing of polydisperse spheres.
//
// The packing, built once per process by the engine itself (build_packing):
//   * the paper's shear cell: box 25 x 10 x 27, periodic in x and y, floor plane
//     z = 0 (normal +z) and ceiling plane z = 27 (normal -z); no gravity (a
//     density-matched suspension);
//   * 1300 spheres, radii uniform in [0.8, 1.0], density 1: phi = 0.593 over the
//     cell (about 0.60 in the bulk, away from the walls);
//   * random sequential addition (no overlap) at phi = 0.3 in a cell twice as
//     tall, then the ceiling is lowered to z = 27 in 100 geometric increments:
//     each increment is one frictionless Contact Dynamics step whose predicted
//     velocities are the affine compression v_z = rate * z (the solver stops every
//     closing contact), after which velocities are zeroed (quasi-static). A few
//     frictionless steps at rest then remove the last overlaps (checked with a
//     margin-0 detection). Uniaxial compression by the lid is how a shear cell is
//     filled, it avoids the slow load propagation (and the resulting bouncing of
//     under-converged steps) of a gravity sediment 27 diameters deep, and it hits
//     the paper's cell volume exactly;
//   * then the affine simple shear v_x = gamma_dot (z - 13.5), w_y = gamma_dot / 2
//     is imposed and ONE step (tolerance 1e-6) is taken from that same state with
//     each friction law. Its contacts, impulses and end-of-step velocities are the
//     input of the benchmarks: about 4300 contacts (margin included), 2900 loaded.
//     Sliding gives a mix of regimes; for Stribeck, eta_f is chosen so that the
//     median Sommerfeld number of the loaded, sliding contacts of the Coulomb step
//     equals s_c (about 0.2 stick, 0.2 bl, 0.2 hd; the rest are open).
//
// The timed loop sweeps a private copy of those contacts and bodies repeatedly,
// WITHOUT resetting them: the end of a solved step is (to the solver tolerance) a
// fixed point of the sweep, so each timed sweep does the work of the last sweeps
// of a real solve and sees the same regime mix (stick/bl/hd/open are counted
// after the loop to show it). Early sweeps cost the same as late ones (same loads,
// stores and flops), so resetting would only add copying to the timing. (The
// Stribeck step does not converge -- mu jumps from mu0 to mu_HD(s_c) ~ 0.003 at
// s_c -- and is stopped after 500 sweeps; its regime mix still stays put.)
//
// BM_ReferenceSweep is the leanest plain Gauss–Seidel sweep we could write over
// the Coulomb step's contacts (with Coulomb friction, and frictionless): plain
// arrays, 64-byte body records, planes as one fixed ghost body (no branch), no
// residual and no regime, sliding speed or Sommerfeld bookkeeping. The ratios
// printed at the end are engine / reference.
//
// Counters: ns_per_contact = CPU time of the timed loop (this thread's, like the
// CPU column; wall time suffers when the machine is shared) / (sweeps x contacts),
// where every listed contact is visited once per sweep, loaded or not; contacts
// (all in the list), loaded (p_n > 0), bodies.
#include <benchmark/benchmark.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "detection/contact_detector.hpp"
#include "solver/contact_solver.hpp"
#include "solver/time_stepper.hpp"
#include "sweep_packing.hpp"
#include "world/world.hpp"

namespace {

using namespace dilatant;
using namespace dilatant::bench;
using Clock = std::chrono::steady_clock;

void set_counters(benchmark::State& state, double cpu_ns, std::size_t contacts,
                  std::size_t loaded_contacts) {
  state.counters["ns_per_contact"] =
      cpu_ns / (static_cast<double>(state.iterations()) * static_cast<double>(contacts));
  state.counters["contacts"] = static_cast<double>(contacts);
  state.counters["loaded"] = static_cast<double>(loaded_contacts);
  state.counters["bodies"] = packing().bodies;
}

// ---------------------------------------------------------------- the engine's sweep

void BM_GaussSeidelSweep(benchmark::State& state, bool stribeck) {
  const Case& c = stribeck ? packing().stribeck : packing().coulomb;
  std::vector<Contact> contacts = c.contacts;
  Bodies bodies = c.bodies;
  const double start = thread_cpu_ns();
  for (auto _ : state) {
    PassChange change = gauss_seidel_pass(contacts, bodies, c.law, kDt);
    benchmark::DoNotOptimize(change);
  }
  set_counters(state, thread_cpu_ns() - start, contacts.size(), loaded(contacts));
  const RegimeMix mix = regime_mix(contacts);
  state.counters["open"] = mix.open;
  state.counters["stick"] = mix.stick;
  state.counters["bl"] = mix.bl;
  state.counters["hd"] = mix.hd;
}
BENCHMARK_CAPTURE(BM_GaussSeidelSweep, coulomb, false);
BENCHMARK_CAPTURE(BM_GaussSeidelSweep, stribeck, true);

// ---------------------------------------------------------------- the reference loop

struct RefBody {  // one cache line
  double v[3], w[3];
  double inv_mass, inv_inertia;
};

struct RefContact {
  std::int32_t i, j;  // j = the ghost body for a plane
  double n[3];
  double bias;  // gap / dt
  double arm_i, arm_j;
  double w_n_inv, w_t, w_t_inv;
  double p_n, p_t[3];
};

struct Reference {
  std::vector<RefBody> bodies;
  std::vector<RefContact> contacts;
};

Reference make_reference(const Case& c) {
  Reference r;
  const Bodies& b = c.bodies;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec3 &v = b.velocity[i], &w = b.angular_velocity[i];
    r.bodies.push_back(
        {{v.x(), v.y(), v.z()}, {w.x(), w.y(), w.z()}, b.inv_mass[i], b.inv_inertia[i]});
  }
  r.bodies.push_back(RefBody{});  // the ghost: fixed, at rest, stands for every plane
  const auto ghost = static_cast<std::int32_t>(b.size());
  for (const Contact& k : c.contacts) {
    r.contacts.push_back({k.i,
                          k.with_plane() ? ghost : k.other,
                          {k.normal.x(), k.normal.y(), k.normal.z()},
                          k.gap / kDt,
                          k.arm_i,
                          k.arm_j,
                          1.0 / k.w_n,
                          k.w_t,
                          1.0 / k.w_t,
                          k.p_n,
                          {k.p_t.x(), k.p_t.y(), k.p_t.z()}});
  }
  return r;
}

// Same local problem as the engine (Signorini + Coulomb, closed form).
template <bool kFriction>
void reference_sweep(Reference& r, double mu) {
  RefBody* const bodies = r.bodies.data();
  for (RefContact& c : r.contacts) {
    RefBody& a = bodies[c.i];
    RefBody& o = bodies[c.j];
    const double* n = c.n;
    // u = v_i - v_j - (r_i w_i + r_j w_j) x n
    const double wx = c.arm_i * a.w[0] + c.arm_j * o.w[0];
    const double wy = c.arm_i * a.w[1] + c.arm_j * o.w[1];
    const double wz = c.arm_i * a.w[2] + c.arm_j * o.w[2];
    const double u[3] = {a.v[0] - o.v[0] - (wy * n[2] - wz * n[1]),
                         a.v[1] - o.v[1] - (wz * n[0] - wx * n[2]),
                         a.v[2] - o.v[2] - (wx * n[1] - wy * n[0])};
    const double u_n = u[0] * n[0] + u[1] * n[1] + u[2] * n[2];
    const double p_n = std::max(0.0, c.p_n - (u_n + c.bias) * c.w_n_inv);
    double dp[3];
    for (int k = 0; k < 3; ++k) dp[k] = (p_n - c.p_n) * n[k];
    c.p_n = p_n;
    if constexpr (kFriction) {
      double ut[3], slip2 = 0.0;  // free slip: without this contact's tangential impulse
      for (int k = 0; k < 3; ++k) {
        ut[k] = u[k] - u_n * n[k] - c.w_t * c.p_t[k];
        slip2 += ut[k] * ut[k];
      }
      const double cone = mu * p_n;
      const double scale =
          slip2 <= c.w_t * c.w_t * cone * cone ? -c.w_t_inv : -cone / std::sqrt(slip2);
      for (int k = 0; k < 3; ++k) {
        const double p_t = scale * ut[k];
        dp[k] += p_t - c.p_t[k];
        c.p_t[k] = p_t;
      }
    }
    const double n_x_dp[3] = {n[1] * dp[2] - n[2] * dp[1], n[2] * dp[0] - n[0] * dp[2],
                              n[0] * dp[1] - n[1] * dp[0]};
    const double spin_a = a.inv_inertia * c.arm_i, spin_o = o.inv_inertia * c.arm_j;
    for (int k = 0; k < 3; ++k) {
      a.v[k] += a.inv_mass * dp[k];
      a.w[k] -= spin_a * n_x_dp[k];
      o.v[k] -= o.inv_mass * dp[k];
      o.w[k] -= spin_o * n_x_dp[k];
    }
  }
}

void BM_ReferenceSweep(benchmark::State& state, bool friction) {
  const Case& c = packing().coulomb;
  Reference r = make_reference(c);
  const double start = thread_cpu_ns();
  for (auto _ : state) {
    if (friction) {
      reference_sweep<true>(r, kMu0);
    } else {
      reference_sweep<false>(r, 0.0);
    }
    benchmark::DoNotOptimize(r.bodies.data());
    benchmark::ClobberMemory();
  }
  set_counters(state, thread_cpu_ns() - start, r.contacts.size(), loaded(c.contacts));
}
BENCHMARK_CAPTURE(BM_ReferenceSweep, coulomb, true);
BENCHMARK_CAPTURE(BM_ReferenceSweep, frictionless, false);

// ---------------------------------------------------------------- reporting

// The console reporter, remembering ns_per_contact of each benchmark for the ratios.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  using ConsoleReporter::ConsoleReporter;

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      const auto it = run.counters.find("ns_per_contact");
      if (run.error_occurred || it == run.counters.end()) continue;
      // Single runs, or the mean when --benchmark_repetitions aggregates them.
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "mean") continue;
      // BENCHMARK_CAPTURE names are "function/case", without further arguments.
      ns_[run.run_name.function_name] = it->second.value;
    }
  }

  void print_ratios() const {
    for (const char* law : {"BM_GaussSeidelSweep/coulomb", "BM_GaussSeidelSweep/stribeck"}) {
      for (const char* ref : {"BM_ReferenceSweep/coulomb", "BM_ReferenceSweep/frictionless"}) {
        const auto e = ns_.find(law), r = ns_.find(ref);
        if (e == ns_.end() || r == ns_.end()) continue;
        std::printf("ratio %s / %s = %.2f  (%.1f / %.1f ns per contact)\n", law, ref,
                    e->second / r->second, e->second, r->second);
      }
    }
  }

 private:
  std::map<std::string, double> ns_;
};

void print_packing(std::FILE* out) {
  const Packing& p = packing();
  std::fprintf(out,
               "packing: %d spheres, r in [%.1f, %.1f], cell %.0f x %.0f x %.0f (periodic x, y; "
               "floor and ceiling planes)\n"
               "  phi = %.3f (cell), %.3f (bulk, 3 < z < 24); largest overlap %.1e\n"
               "  setup %.2f s: compression %.2f s (%d steps), then one sheared step per law "
               "(dt = %g, gamma_dot = %g)\n",
               p.bodies, kRadiusMin, kRadiusMax, kLx, kLy, kLz, p.phi_cell, p.phi_bulk,
               p.max_overlap, p.setup_seconds, p.compression_seconds, p.compression_steps, kDt,
               kShearRate);
  for (const Case* c : {&p.coulomb, &p.stribeck}) {
    const RegimeMix m = regime_mix(c->contacts);
    const auto* s = std::get_if<StribeckLaw>(&c->law);
    std::fprintf(out,
                 "  %-8s mu0 = %g%s: %zu contacts, %zu loaded = %.2f per sphere; solve %d sweeps "
                 "(residual %.1e); open %.2f stick %.2f bl %.2f hd %.2f\n",
                 s ? "stribeck" : "coulomb", kMu0,
                 s ? (", eta_f = " + std::to_string(s->eta_f)).c_str() : "", c->contacts.size(),
                 loaded(c->contacts), contacts_per_sphere(c->contacts, p.bodies),
                 c->solve.iterations, c->solve.residual, m.open, m.stick, m.bl, m.hd);
  }
  std::fflush(out);
}

}  // namespace

int main(int argc, char** argv) {
  // Our console reporter adds the ratios; with another --benchmark_format the
  // library's own reporter runs and the packing summary goes to stderr.
  bool console = true;
  for (int k = 1; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (arg.starts_with("--benchmark_format=") && arg != "--benchmark_format=console") {
      console = false;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  print_packing(console ? stdout : stderr);
  if (console) {
    RatioReporter reporter(isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_ColorTabular
                                                  : benchmark::ConsoleReporter::OO_Tabular);
    benchmark::RunSpecifiedBenchmarks(&reporter);
    reporter.print_ratios();
  } else {
    benchmark::RunSpecifiedBenchmarks();
  }
  benchmark::Shutdown();
  return 0;
}
