// The normal elastic energy a law reports without evaluating a contact
// (ContactLaw::normal_elastic_energy, used by breakage's energy bookkeeping) is the integral of
// the law's elastic normal force from 0 to the overlap: Hertz (4/3) E* sqrt(R*) d^1.5 gives
// (8/15) E* sqrt(R*) d^2.5, a linear spring k_n d gives k_n d^2 / 2. Tolerance 1e-14 relative:
// a handful of roundings of double arithmetic. It is also the same bits as compute()'s
// out.normal_elastic_energy for a contact at rest (the Hertz–Mindlin batch test covers moving
// contacts).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "comminute/contact/contact_law.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/particles/material.hpp"

using namespace comminute;

namespace {

struct Law {
  MaterialTable materials;
  std::unique_ptr<ContactLaw> law;
  ContactStateStore store;
  Law(const std::string& name, const std::string& keys) {
    materials.add({"glass", 2500, 5e6, 0.3});
    materials.set_pair(0, 0, PairInput{});
    const CaseFile c = CaseFile::parse(keys);
    law = ContactLawRegistry::create(name, c.root());
    ContactStateStore layout;
    law->declare(layout);
    store = layout.same_layout();
    store.carry({}, {}, {}, 1);
  }
  // compute()'s normal elastic energy for a contact at rest with a fresh state
  double computed(double radius, double delta) {
    ContactKinematics k;
    k.normal = {0, 0, 1};
    k.overlap = delta;
    k.effective_radius = radius;
    k.effective_mass = 1e-3;
    ContactForces out;
    law->compute(k, materials.pair(0, 0), store.at(0), out);
    return out.normal_elastic_energy;
  }
};

}  // namespace

TEST(NormalElasticEnergy, HertzIsTheIntegralOfItsForce) {
  Law h("hertz_mindlin", "");
  const PairParameters& p = h.materials.pair(0, 0);
  for (double radius : {1e-4, 1e-3, 2e-2})
    for (double delta : {1e-9, 3e-6, 1e-4}) {
      const double e = h.law->normal_elastic_energy(p, radius, delta);
      const double exact =
          8.0 / 15.0 * p.effective_modulus * std::sqrt(radius) * std::pow(delta, 2.5);
      EXPECT_NEAR(e, exact, 1e-14 * exact) << radius << " " << delta;
      EXPECT_EQ(e, h.computed(radius, delta)) << radius << " " << delta;
    }
}

TEST(NormalElasticEnergy, LinearSpringIsHalfKDeltaSquared) {
  Law l("linear_spring_dashpot", "normal_stiffness = 2.5e5\n");
  const PairParameters& p = l.materials.pair(0, 0);
  for (double delta : {1e-9, 3e-6, 1e-4}) {
    const double e = l.law->normal_elastic_energy(p, 1e-3, delta);
    const double exact = 0.5 * 2.5e5 * delta * delta;
    EXPECT_NEAR(e, exact, 1e-14 * exact) << delta;
    EXPECT_EQ(e, l.computed(1e-3, delta)) << delta;
  }
}
