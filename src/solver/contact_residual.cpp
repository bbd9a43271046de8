#include "solver/contact_residual.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "solver/local_problem.hpp"

namespace dilatant {

namespace {

struct Sums {
  double normal_max = 0.0, normal_squared = 0.0;
  double tangential_max = 0.0, tangential_squared = 0.0;
  double impulse_squared = 0.0;
  double loaded = 0.0;
  double worst = 0.0;             // max(normal_max, tangential_max) ...
  std::int32_t worst_index = -1;  // ... at this contact
};

template <class Law>
void add_range(std::span<const Contact> contacts, std::size_t first, const Bodies& b,
               const Law& law, double dt, double max_push_out, Sums& s) {
  const double inv_dt = 1.0 / dt;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& c = contacts[k];
    const LocalAnswer a =
        solve_local(c, b, law, dt, inv_dt, 1.0, imposed_branch(c, true), max_push_out);
    const double dn = std::abs(a.p_n + a.p_lub - c.p_n - c.p_lub);
    const double dp_t = (a.p_t - c.p_t).norm();
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

ContactResidual contact_residual(const ContactProblem& problem) {
  const std::vector<Contact>& contacts = problem.contacts;
  const SlabPartition& slabs = problem.slabs;
  const Bodies& bodies = problem.bodies;
  const FrictionLaw& law = problem.law;
  const FrictionLaw& boundary_law = problem.boundary_law();
  const double dt = problem.dt, max_push_out = problem.settings.max_push_out;
  const int threads = problem.settings.threads;
  // Read-only, so the slabs are independent: summed per slab, then added in
  // slab order, which gives the same bits for any number of threads.
  std::vector<Sums> per_slab(static_cast<std::size_t>(slabs.count()));
  const int n_slabs = slabs.count();
#pragma omp parallel for schedule(static) num_threads(std::max(1, threads)) if (threads > 1)
  for (int k = 0; k < n_slabs; ++k) {
    const auto ks = static_cast<std::size_t>(k);
    const std::span<const Contact> particles(contacts.data() + slabs.begin[ks],
                                             slabs.boundary_begin[ks] - slabs.begin[ks]);
    const std::span<const Contact> boundary(contacts.data() + slabs.boundary_begin[ks],
                                            slabs.begin[ks + 1] - slabs.boundary_begin[ks]);
    Sums& slab = per_slab[ks];
    std::visit(
        [&](const auto& l) {
          add_range(particles, slabs.begin[ks], bodies, l, dt, max_push_out, slab);
        },
        law);
    std::visit(
        [&](const auto& l) {
          add_range(boundary, slabs.boundary_begin[ks], bodies, l, dt, max_push_out, slab);
        },
        boundary_law);
  }
  Sums s;
  for (const Sums& slab : per_slab) {
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
  if (contacts.empty()) return r;
  r.worst_contact = s.worst_index;
  // No loaded contact: any change is measured against the changes themselves.
  const double typical = s.loaded > 0.0 ? std::sqrt(s.impulse_squared / s.loaded) : 0.0;
  if (typical <= 0.0) {
    const bool moved = s.normal_max > 0.0 || s.tangential_max > 0.0;
    r.normal_max = r.tangential_max = r.normal_rms = r.tangential_rms = moved ? 1.0 : 0.0;
    return r;
  }
  const double n = static_cast<double>(contacts.size());
  r.normal_max = s.normal_max / typical;
  r.tangential_max = s.tangential_max / typical;
  r.normal_rms = std::sqrt(s.normal_squared / n) / typical;
  r.tangential_rms = std::sqrt(s.tangential_squared / n) / typical;
  return r;
}

}  // namespace dilatant
