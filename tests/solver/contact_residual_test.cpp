// The residual of the contact problem (solver/contact_residual.hpp): zero at
// the solution, and exactly the distance to each contact's local answer when
// the impulses are moved off it.
#include "solver/contact_residual.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "detection/contact_detector.hpp"
#include "friction/coulomb_law.hpp"
#include "solver/contact_solver.hpp"
#include "solver/local_problem.hpp"

namespace dilatant::contact_residual_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kDt = 1e-3;

// The residual of `contacts` in `slabs`, every one under `law`.
ContactResidual residual_of(std::vector<Contact>& contacts, const SlabPartition& slabs,
                            Bodies& bodies, const FrictionLaw& law, int threads = 1) {
  const SolverSettings settings{.threads = threads};
  return contact_residual({.contacts = contacts,
                           .slabs = slabs,
                           .bodies = bodies,
                           .law = law,
                           .dt = kDt,
                           .settings = settings});
}

// A sphere resting on a plane under gravity g = 1, sliding at 0.5 along x
// with mu0 0.2 (so it keeps sliding through the step).
struct Resting {
  World world;
  std::vector<Contact> contacts;
  CoulombLaw law{.mu0 = 0.2, .eta_f = 0.0};
  double m = 0.0;

  Resting() {
    world.planes.push_back(Plane{});
    world.bodies.add_sphere(0, Vec3(0.0, 0.0, 1.0), 1.0, 1.0, false, Vec3(0.5, 0.0, -kDt));
    m = world.bodies.mass(0);
    ContactDetector().detect(world, 0.1, contacts);
    solve_contacts(contacts, world.bodies, law, kDt, SolverSettings{.tolerance = 1e-14});
  }
  ContactResidual residual() {
    const SlabPartition one = SlabPartition::single(contacts.size(), contacts.size());
    return residual_of(contacts, one, world.bodies, law);
  }
};

TEST(ContactResidual, VanishesAtTheSolution) {
  Resting r;
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_NEAR(r.contacts[0].p_n, r.m * kDt, 8 * kEps * r.m * kDt);  // N = m g
  EXPECT_EQ(r.contacts[0].regime, Regime::BoundaryLubricated);
  const ContactResidual res = r.residual();
  EXPECT_LE(res.max(), 16 * kEps);
}

// Push the normal impulse up by d (and the body with it, as the sweep would):
// the local answer is still m g dt, so the normal residual is exactly d less
// the round-off of recomputing it (round_off_impulse), relative to the
// contact's impulse |P|; the tangential answer moves with the cone, mu0 d.
TEST(ContactResidual, MeasuresTheDistanceToTheLocalAnswer) {
  Resting r;
  Contact& c = r.contacts[0];
  const double d = 0.25 * c.p_n;
  c.p_n += d;
  r.world.bodies.velocity[0] += d / r.m * c.normal;
  const double typical = std::sqrt(c.p_n * c.p_n + c.p_t.squaredNorm());
  const ContactResidual res = r.residual();
  const double normal = d - round_off_impulse(c, r.world.bodies);
  EXPECT_NEAR(res.normal_max, normal / typical, 1e-12);
  EXPECT_NEAR(res.normal_rms, normal / typical, 1e-12);
  // The cone was mu0 (p_n - d); the local answer slides on mu0 (p_n - d) too:
  // the tangential impulse is already that, so no tangential residual.
  EXPECT_LE(res.tangential_max, 1e-12);

  // A tangential impulse off the law by e (body moved with it).
  Resting s;
  Contact& t = s.contacts[0];
  const Vec3 e(0.1 * t.p_t.norm(), 0.0, 0.0);
  t.p_t += e;
  s.world.bodies.velocity[0] += e / s.m;
  s.world.bodies.angular_velocity[0] -= (t.arm_i / (0.4 * s.m)) * t.normal.cross(e);
  const double typical_t = std::sqrt(t.p_n * t.p_n + t.p_t.squaredNorm());
  const ContactResidual rt = s.residual();
  EXPECT_NEAR(rt.tangential_max, (e.norm() - round_off_impulse(t, s.world.bodies)) / typical_t,
              1e-12);
  EXPECT_LE(rt.normal_max, 1e-12);
}

// The contact that holds the largest residual is named (its index), also when
// it lies in a later slab and the slabs are shared by threads: four spheres
// resting apart on a plane, two of them pushed off their answers by 10% and 30%.
TEST(ContactResidual, NamesTheContactThatHoldsTheLargest) {
  World world;
  world.planes.push_back(Plane{});
  for (int k = 0; k < 4; ++k)
    world.bodies.add_sphere(k, Vec3(3.0 * k, 0.0, 1.0), 1.0, 1.0, false, Vec3(0.5, 0.0, -kDt));
  std::vector<Contact> contacts;
  ContactDetector().detect(world, 0.1, contacts);
  ASSERT_EQ(contacts.size(), 4u);
  const CoulombLaw law{.mu0 = 0.2, .eta_f = 0.0};
  solve_contacts(contacts, world.bodies, law, kDt, SolverSettings{.tolerance = 1e-14});
  const auto push = [&](std::size_t k, double fraction) {
    const double d = fraction * contacts[k].p_n;
    contacts[k].p_n += d;
    world.bodies.velocity[static_cast<std::size_t>(contacts[k].i)] +=
        d * world.bodies.inv_mass[static_cast<std::size_t>(contacts[k].i)] * contacts[k].normal;
  };
  push(1, 0.1);
  push(2, 0.3);
  SlabPartition two;  // slab 0: contacts 0, 1; slab 1: contacts 2, 3
  two.begin = {0, 2, 4};
  two.boundary_begin = {2, 4};
  for (const int threads : {1, 2}) {
    const ContactResidual one_slab =
        residual_of(contacts, SlabPartition::single(4, 4), world.bodies, law);
    const ContactResidual slabs = residual_of(contacts, two, world.bodies, law, threads);
    EXPECT_EQ(one_slab.worst_contact, 2);
    EXPECT_EQ(slabs.worst_contact, 2) << threads << " threads";
    EXPECT_EQ(slabs.max(), one_slab.max());
  }
  push(0, 0.5);  // now the first slab's
  EXPECT_EQ(residual_of(contacts, two, world.bodies, law, 2).worst_contact, 0);
}

TEST(ContactResidual, NoContactsNoResidual) {
  std::vector<Contact> none;
  Bodies b;
  const ContactResidual r = residual_of(none, SlabPartition::single(0, 0), b, CoulombLaw{});
  EXPECT_EQ(r.max(), 0.0);
  EXPECT_EQ(r.worst_contact, -1);
}

}  // namespace
}  // namespace dilatant::contact_residual_test
