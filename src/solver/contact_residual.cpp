#include "solver/contact_residual.hpp"

#include <algorithm>
#include <cmath>

#include "solver/local_problem.hpp"

namespace dilatant {

namespace {

template <class Law>
void add_range(std::span<const Contact> contacts, std::size_t first, const Bodies& b,
               const Law& law, double dt, double max_push_out, ResidualSums& s) {
  const double inv_dt = 1.0 / dt;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& c = contacts[k];
    const LocalAnswer a =
        solve_local(c, b, law, dt, inv_dt, 1.0, imposed_branch(c, true), max_push_out);
    const double noise = round_off_impulse(c, b);
    const double dn = std::max(0.0, std::abs(a.p_n + a.p_lub - c.p_n - c.p_lub) - noise);
    const double dp_t = std::max(0.0, (a.p_t - c.p_t).norm() - noise);
    s.normal_max = std::max(s.normal_max, dn);
    s.tangential_max = std::max(s.tangential_max, dp_t);
    if (std::max(dn, dp_t) > s.worst) {
      s.worst = std::max(dn, dp_t);
      s.worst_index = static_cast<std::int32_t>(first + k);
    }
    s.normal_squared += dn * dn;
    s.tangential_squared += dp_t * dp_t;
    if (c.p_n > 0.0 || c.p_lub != 0.0) {
      const double normal = c.p_n + c.p_lub;
      s.impulse_squared += normal * normal + c.p_t.squaredNorm();
      s.loaded += 1.0;
    }
  }
}

}  // namespace

ResidualSums slab_residual(const ContactProblem& problem, int slab) {
  const std::vector<Contact>& contacts = problem.contacts;
  const SlabPartition& slabs = problem.slabs;
  const double dt = problem.dt, max_push_out = problem.settings.max_push_out;
  const auto ks = static_cast<std::size_t>(slab);
  const std::span<const Contact> particles(contacts.data() + slabs.begin[ks],
                                           slabs.boundary_begin[ks] - slabs.begin[ks]);
  const std::span<const Contact> boundary(contacts.data() + slabs.boundary_begin[ks],
                                          slabs.begin[ks + 1] - slabs.boundary_begin[ks]);
  ResidualSums sums;
  std::visit(
      [&](const auto& l) {
        add_range(particles, slabs.begin[ks], problem.bodies, l, dt, max_push_out, sums);
      },
      problem.law);
  std::visit(
      [&](const auto& l) {
        add_range(boundary, slabs.boundary_begin[ks], problem.bodies, l, dt, max_push_out, sums);
      },
      problem.boundary_law());
  return sums;
}

ContactResidual combine_residual(const ContactProblem& problem,
                                 std::span<const ResidualSums> per_slab) {
  ResidualSums s;
  for (const ResidualSums& slab : per_slab) {
    s.normal_max = std::max(s.normal_max, slab.normal_max);
    s.tangential_max = std::max(s.tangential_max, slab.tangential_max);
    s.normal_squared += slab.normal_squared;
    s.tangential_squared += slab.tangential_squared;
    s.impulse_squared += slab.impulse_squared;
    s.loaded += slab.loaded;
    if (slab.worst > s.worst) {  // the first slab's on ties: the same for any thread count
      s.worst = slab.worst;
      s.worst_index = slab.worst_index;
    }
  }
  ContactResidual r;
  if (problem.contacts.empty()) return r;
  r.worst_contact = s.worst_index;
  // The unit: the reference impulse the driver set, else the typical impulse
  // of the loaded contacts; no loaded contact: any change is measured against
  // the changes themselves.
  const double unit = problem.settings.reference_impulse > 0.0
                          ? problem.settings.reference_impulse
                          : (s.loaded > 0.0 ? std::sqrt(s.impulse_squared / s.loaded) : 0.0);
  if (unit <= 0.0) {
    const bool moved = s.normal_max > 0.0 || s.tangential_max > 0.0;
    r.normal_max = r.tangential_max = r.normal_rms = r.tangential_rms = moved ? 1.0 : 0.0;
    return r;
  }
  const double n = static_cast<double>(problem.contacts.size());
  r.typical_impulse = s.loaded > 0.0 ? std::sqrt(s.impulse_squared / s.loaded) / unit : 0.0;
  r.normal_max = s.normal_max / unit;
  r.tangential_max = s.tangential_max / unit;
  r.normal_rms = std::sqrt(s.normal_squared / n) / unit;
  r.tangential_rms = std::sqrt(s.tangential_squared / n) / unit;
  return r;
}

ContactResidual contact_residual(const ContactProblem& problem) {
  // Read-only, so the slabs are independent: summed per slab, then added in
  // slab order, which gives the same bits for any number of threads.
  const int n_slabs = problem.slabs.count();
  std::vector<ResidualSums> per_slab(static_cast<std::size_t>(n_slabs));
  const int threads = problem.settings.threads;
#pragma omp parallel for schedule(static) num_threads(std::max(1, threads)) if (threads > 1)
  for (int k = 0; k < n_slabs; ++k)
    per_slab[static_cast<std::size_t>(k)] = slab_residual(problem, k);
  return combine_residual(problem, per_slab);
}

}  // namespace dilatant
