// The pair force loop gathers the touching pairs of the neighbour list into runs (without a branch
// per pair) and hands each run to the contact law in one call; Hertz–Mindlin takes its tangential
// dashpot's root from the normal one's. These tests hold the loop and the law to the analytic
// contact: a chain of bead pairs, touching pairs interleaved with listed pairs that do not touch,
// more touching pairs than one run holds.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "comminute/contact/contact_law.hpp"
#include "comminute/core/case_table.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "comminute/engine/pair_force_loop.hpp"
#include "comminute/neighbor/neighbor_list.hpp"
#include "comminute/particles/material.hpp"

using namespace comminute;

namespace {

constexpr double r = 1e-3;      // m, bead radius
constexpr double rho = 2500.0;  // kg/m3
constexpr int n_pairs = 150;    // touching pairs: more than two runs of the loop

// Overlap of touching pair m (m): all different, so a force landing on the wrong pair shows.
double overlap_of(int m) {
  return 1e-6 * (1.0 + 0.5 * m);
}

// Beads 2m and 2m+1 overlap by overlap_of(m) (or sit 0.1 mm apart when `apart(m)`); pair m and
// pair m+1 are 0.2 mm apart: listed (skin 0.5 mm), not touching.
struct Chain {
  ParticleStore p;
  MaterialTable materials;
  std::unique_ptr<ContactLaw> law;
  ContactPipeline pipeline;
  ContactStateStore state;
  NeighborList pairs;
  PairForceLoop loop;
  EnergyLedger ledger;

  Chain() {
    materials.add({"glass", rho, 5e6, 0.3});
    PairInput in;
    in.restitution = 0.5;
    in.friction = 0.5;
    materials.set_pair(0, 0, in);
    const CaseFile c = CaseFile::parse("tangential = \"mindlin\"\n");
    law = ContactLawRegistry::create("hertz_mindlin", c.root());
    std::vector<std::unique_ptr<Module>> none;
    state = pipeline.assemble(*law, nullptr, nullptr, none).same_layout();
    double x = 0;
    for (int m = 0; m < n_pairs; ++m) {
      p.add({{x, 0, 0}, {}, {}, r, rho, 0, 0});
      x += 2 * r - overlap_of(m);
      // the second bead of a pair slides along y: its tangential spring loads
      p.add({{x, 0, 0}, {0, 1e-3, 0}, {}, r, rho, 0, 0});
      x += 2 * r + 2e-4;
    }
    pairs.build(p, 5e-4);
    state.carry({}, {}, {}, pairs.size());
  }
  void forces() {
    for (std::size_t i = 0; i < p.size(); ++i) p.f[i] = p.t[i] = Vec3{};
    double elastic = 0;
    std::vector<EndedContact> ended;
    loop.run(p, materials, pairs, nullptr, pipeline, state, 1e-6, ledger, elastic, ended);
  }
};

}  // namespace

TEST(PairForceRuns, EveryTouchingPairGetsItsHertzForceAndOnlyThose) {
  Chain c;
  ASSERT_EQ(c.pairs.size(), 2u * n_pairs - 1);  // the touching pairs and the gaps between them
  c.forces();
  const double estar = c.materials.pair(0, 0).effective_modulus;
  for (int m = 0; m < n_pairs; ++m) {
    const double d = overlap_of(m);
    // Hertz (J. reine angew. Math. 1882): F = (4/3) E* sqrt(R*) d^1.5, R* = r/2; the beads
    // approach at no speed, so the dashpot adds nothing along x. Tolerance 1e-9 relative: the
    // overlap is a difference of ~2 mm lengths, ~1e-16 * 2e-3 / 1e-6 = 2e-13 of itself.
    const double hertz = 4.0 / 3.0 * estar * std::sqrt(0.5 * r) * std::pow(d, 1.5);
    EXPECT_NEAR(c.p.f[2 * m].x, -hertz, 1e-9 * hertz) << "pair " << m;
    EXPECT_NEAR(c.p.f[2 * m + 1].x, hertz, 1e-9 * hertz) << "pair " << m;
  }
  // a gap pair is listed but untouched: its flag stays 0
  std::size_t touching = 0;
  for (auto a : c.state.active) touching += a;
  EXPECT_EQ(touching, static_cast<std::size_t>(n_pairs));
}

TEST(PairForceRuns, TangentialDashpotIsTsujisWithMindlinsStiffness) {
  Chain c;
  c.forces();
  const PairParameters& pp = c.materials.pair(0, 0);
  const double mass = rho * 4.0 / 3.0 * M_PI * r * r * r;
  const double dt = 1e-6, vt = 1e-3;  // bead 2m+1 slides along +y: v_t of 2m relative to it -vt
  for (int m = 0; m < n_pairs; m += 7) {
    const double d = overlap_of(m);
    const double a = std::sqrt(0.5 * r * d);
    const double st = 8.0 * pp.effective_shear_modulus * a;  // Mindlin (J. Appl. Mech. 1949)
    // Tsuji, Tanaka & Ishida (Powder Technol. 1992): c_t = -2 sqrt(5/6) beta sqrt(S_t m*)
    const double ct = -2.0 * std::sqrt(5.0 / 6.0) * pp.damping_beta * std::sqrt(st * 0.5 * mass);
    // a new contact: spring st * vt dt, dashpot ct vt, both pushing bead 2m along +y
    const double ft = st * vt * dt + ct * vt;
    const double fn = 4.0 / 3.0 * pp.effective_modulus * std::sqrt(0.5 * r) * std::pow(d, 1.5);
    ASSERT_LT(ft, pp.friction * fn);  // sticking: the dashpot is not capped
    // 1e-9 relative: the law takes the dashpot's root from S_n m* times sqrt(4 G*/E*), a few
    // ulp from sqrt(S_t m*); the overlap carries ~2e-13 (above)
    EXPECT_NEAR(c.p.f[2 * m].y, ft, 1e-9 * ft) << "pair " << m;
    EXPECT_NEAR(c.p.f[2 * m + 1].y, -ft, 1e-9 * ft) << "pair " << m;
  }
}

TEST(PairForceRuns, ASeparatedPairLosesItsSpringAndTheOthersKeepTheirs) {
  Chain c;
  c.forces();
  const SlotId spring = c.state.vec3_slot("tangential_spring");
  // every third pair separates: its second bead (and every bead after it) moves 10 um along +x
  Vec3 shift{};
  for (int m = 0; m < n_pairs; ++m) {
    if (m % 3 == 0) shift.x += overlap_of(m) + 1e-5;
    c.p.x[2 * m + 1] += shift;
    if (m + 1 < n_pairs) c.p.x[2 * m + 2] += shift;
  }
  c.forces();
  for (int m = 0; m < n_pairs; ++m) {
    const std::size_t k = 2 * static_cast<std::size_t>(m);  // pair m's index in the list
    ASSERT_EQ(c.pairs.first[k], 2u * m);
    ASSERT_EQ(c.pairs.second[k], 2u * m + 1);
    const double s = c.state.at(k).vec3(spring).y;
    if (m % 3 == 0) {
      EXPECT_EQ(c.state.active[k], 0) << "pair " << m;
      EXPECT_EQ(s, 0.0) << "pair " << m;  // its state is gone
      EXPECT_EQ(c.p.f[2 * m].x, 0.0) << "pair " << m;
    } else {
      EXPECT_EQ(c.state.active[k], 1) << "pair " << m;
      // two steps of -vt dt (the spring of i relative to j): exact up to round-off
      EXPECT_NEAR(s, -2e-9, 1e-22) << "pair " << m;
    }
  }
}
