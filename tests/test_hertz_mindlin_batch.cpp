// Hertz–Mindlin evaluates a batch of contacts in stages (the square roots of many contacts in
// loops of their own); a contact's result must not depend on that: the batch gives the same bits as
// compute() contact by contact (forces, energies, stored spring, sliding flag, stiffness), for
// every variant of the law, over contacts that stick, slide, start with no spring, have their
// spring along the normal, and turn their normal between steps. Exact equality: the same
// operations in the same order on the same numbers leave no room for a difference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "comminute/contact/contact_law.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/particles/material.hpp"

using namespace comminute;

namespace {

constexpr std::size_t n_contacts = 150;  // more than two batches of kBatchSize (64)

// One variant of the law with two stores of the same layout: one driven by compute_batch, the
// other by compute() contact by contact.
struct Twin {
  MaterialTable materials;
  std::unique_ptr<ContactLaw> law;
  ContactStateStore batch, single;

  Twin(const std::string& keys, bool dynamic_friction) {
    materials.add({"glass", 2500, 5e6, 0.3});
    materials.add({"steel", 7800, 2e8, 0.28});
    for (std::uint16_t a = 0; a < 2; ++a)
      for (std::uint16_t b = a; b < 2; ++b) {
        PairInput in;
        in.restitution = a == b ? 0.5 : 0.8;
        in.friction = a == b ? 0.5 : 0.3;
        if (dynamic_friction) in.dynamic_friction = a == b ? 0.35 : 0.2;
        materials.set_pair(a, b, in);
      }
    const CaseFile c = CaseFile::parse(keys);
    law = ContactLawRegistry::create("hertz_mindlin", c.root());
    if (dynamic_friction) law->use_dynamic_friction();
    ContactStateStore layout;
    law->declare(layout);
    batch = layout.same_layout();
    single = layout.same_layout();
    batch.carry({}, {}, {}, n_contacts);
    single.carry({}, {}, {}, n_contacts);
  }
};

// Random contacts of a step; contact 3 keeps no spring, contact 5 starts with its spring along the
// normal (projected to zero), a fifth of them slide fast.
std::vector<ContactKinematics> contacts(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.1, 1.0);
  std::vector<ContactKinematics> k(n_contacts);
  for (std::size_t c = 0; c < n_contacts; ++c) {
    Vec3 n{u(rng), u(rng), u(rng)};
    n /= norm(n);
    k[c].normal = n;
    k[c].overlap = 1e-6 * pos(rng);
    k[c].overlap_rate = 1e-2 * u(rng);
    const Vec3 v{u(rng), u(rng), u(rng)};
    const double speed = c % 5 == 0 ? 1.0 : 1e-3;
    k[c].tangential_velocity = speed * (v - dot(v, n) * n);
    if (c == 3) k[c].tangential_velocity = {};
    k[c].effective_radius = 1e-3 * pos(rng);
    k[c].effective_mass = 1e-5 * pos(rng);
    k[c].dt = 1e-5;
  }
  return k;
}

}  // namespace

TEST(HertzMindlinBatch, StagedBatchEqualsContactByContact) {
  const std::vector<std::pair<std::string, bool>> variants{
      {"tangential = \"mindlin\"\n", false},
      {"tangential = \"mindlin\"\n", true},
      {"tangential = \"mindlin_rescale_force\"\n", false},
      {"tangential = \"mindlin_rescale_force\"\ntangential_damping = false\n", true},
  };
  // mixed material pairs, and one pair for all (the batch then spreads its parameters)
  for (const bool one_pair : {false, true})
    for (const auto& [keys, dynamic] : variants) {
      Twin t(keys, dynamic);
      const std::string label = keys + (one_pair ? "(one material pair) " : "");
      std::mt19937_64 rng(20261201);
      std::vector<const PairParameters*> params(n_contacts);
      std::vector<std::size_t> index(n_contacts);
      for (std::size_t c = 0; c < n_contacts; ++c) {
        params[c] = one_pair ? &t.materials.pair(1, 1)
                             : &t.materials.pair(c % 3 == 0 ? 0 : 1, c % 2 == 0 ? 0 : 1);
        index[c] = n_contacts - 1 - c;  // the batch's contacts in another order than the store's
      }
      const SlotId spring = t.batch.vec3_slot("tangential_spring");
      for (int step = 0; step < 4; ++step) {
        std::vector<ContactKinematics> k = contacts(rng);
        if (step == 1) {  // contact 5: its spring along the new normal
          const Vec3 along = 1e-7 * k[5].normal;
          t.batch.at(index[5]).vec3(spring) = along;
          t.single.at(index[5]).vec3(spring) = along;
        }
        std::vector<ContactForces> fb(n_contacts), fs(n_contacts);
        for (std::size_t c0 = 0; c0 < n_contacts; c0 += kBatchSize) {   // batches of the most
          const std::size_t n = std::min(kBatchSize, n_contacts - c0);  // contacts, and a rest
          KinematicsColumns columns;
          columns.dt = k[c0].dt;
          for (std::size_t c = 0; c < n; ++c) columns.set(c, k[c0 + c]);
          ForceColumns forces;
          t.law->compute_batch(ContactBatch{n, &columns, params.data() + c0, index.data() + c0,
                                            &t.batch.slots(), &forces});
          for (std::size_t c = 0; c < n; ++c) fb[c0 + c] = forces.at(c);
        }
        for (std::size_t c = 0; c < n_contacts; ++c)
          t.law->compute(k[c], *params[c], t.single.at(index[c]), fs[c]);
        std::size_t limited = 0;
        for (std::size_t c = 0; c < n_contacts; ++c) {
          const std::string where =
              label + " step " + std::to_string(step) + " contact " + std::to_string(c);
          EXPECT_EQ(fb[c].normal_force, fs[c].normal_force) << where;
          EXPECT_EQ(fb[c].elastic_normal_force, fs[c].elastic_normal_force) << where;
          EXPECT_EQ(fb[c].tangential_force, fs[c].tangential_force) << where;
          EXPECT_EQ(fb[c].stored_energy, fs[c].stored_energy) << where;
          EXPECT_EQ(fb[c].normal_elastic_energy, fs[c].normal_elastic_energy) << where;
          // the law's energy alone (breakage's bookkeeping) gives compute()'s bits
          EXPECT_EQ(t.law->normal_elastic_energy(*params[c], k[c].effective_radius, k[c].overlap),
                    fs[c].normal_elastic_energy)
              << where;
          EXPECT_EQ(fb[c].damping_dissipation, fs[c].damping_dissipation) << where;
          EXPECT_EQ(fb[c].friction_dissipation, fs[c].friction_dissipation) << where;
          const double mu_d = params[c]->dynamic_friction;
          limited += norm(fb[c].tangential_force) > 0.999 * mu_d * std::abs(fb[c].normal_force);
        }
        // the stores, every declared slot (spring, and the flag and stiffness where declared)
        const Slots &sb = t.batch.slots(), &ss = t.single.slots();
        for (std::size_t s = 0; s < Slots::max_slots; ++s)
          for (std::size_t k2 = 0; k2 < n_contacts; ++k2) {
            if (sb.vec3[s]) {
              EXPECT_EQ(sb.vec3[s][k2], ss.vec3[s][k2]) << label << " vec3 " << s;
            }
            if (sb.f32[s]) {
              EXPECT_EQ(sb.f32[s][k2], ss.f32[s][k2]) << label << " f32 " << s;
            }
            if (sb.f64[s]) {
              EXPECT_EQ(sb.f64[s][k2], ss.f64[s][k2]) << label << " f64 " << s;
            }
          }
        // the set covers both branches of the friction law: at the Coulomb limit and below it
        EXPECT_GT(limited, 0u) << label << " step " << step;
        EXPECT_LT(limited, n_contacts) << label << " step " << step;
      }
    }
}
