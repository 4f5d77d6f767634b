// Bonds in the engine: a bonded chain as a cantilever (Euler–Bernoulli deflection, failure at the
// criterion's load), the energy ledger with bonds breaking, checkpoint restart bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <utility>

#include "comminute/bonds/bonds_module.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

bonds::BondsModule* add_bonds(Simulation& sim, const std::string& law, const std::string& keys,
                              double gap_tolerance) {
  const CaseFile f = CaseFile::parse(keys);
  bonds::BondOptions opt;
  opt.gap_tolerance = gap_tolerance;
  auto m = std::make_unique<bonds::BondsModule>(bonds::BondLawRegistry::create(law, f.root()), opt);
  f.reject_unknown();
  bonds::BondsModule* out = m.get();
  sim.modules.push_back(std::move(m));
  return out;
}

// A load on one particle (scaled by scale(t); none: constant) and viscous damping of every
// particle's velocity and spin, so that the chain comes to rest in its static shape.
class TipLoad final : public Module {
 public:
  TipLoad(std::uint64_t id, Vec3 load, std::function<double(double)> scale, double c, double c_spin)
      : id_(id), load_(load), scale_(std::move(scale)), c_(c), c_spin_(c_spin) {}
  std::string name() const override { return "tip_load"; }
  void post_force(Simulation& sim) override {
    auto& p = sim.particles;
    const double scale = scale_ ? scale_(sim.time) : 1.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.id[i] == id_) p.f[i] += scale * load_;
      p.f[i] -= c_ * p.v[i];
      p.t[i] -= c_spin_ * p.w[i];
    }
  }

 private:
  std::uint64_t id_;
  Vec3 load_;
  std::function<double(double)> scale_;
  double c_, c_spin_;
};

struct Cantilever {
  static constexpr int bonds = 10;
  static constexpr double r = 1e-3, gap = 1e-7, spacing = 2 * r + gap;
  static constexpr double kn = 1e9, ks = 4e8;  // Pa/m
  std::unique_ptr<Simulation> sim;
  bonds::BondsModule* module = nullptr;
  std::uint64_t tip = 0;

  Cantilever(double tensile_strength, Vec3 load, std::function<double(double)> scale = {}) {
    DemSetup s;
    sim = make_simulation(s);
    for (int k = 0; k <= bonds; ++k) {
      const std::uint64_t id = add_sphere(*sim, {k * spacing, 0, 0}, r);
      if (k == 0) sim->particles.flags[0] |= pflag::fixed;  // clamped: neither moves nor turns
      tip = id;
    }
    module = add_bonds(*sim, "parallel_bond",
                       "normal_stiffness = 1e9\nshear_stiffness = 4e8\ntensile_strength = " +
                           std::to_string(tensile_strength) + "\nshear_strength = 1e12\n",
                       1e-6);
    // damping near critical for the first bending mode, ω1 = 1.875² √(EI / (ρ_l L⁴))
    const double m = sim->particles.mass[0];
    const double E = kn * spacing, I = std::numbers::pi * std::pow(r, 4) / 4;
    const double L = bonds * spacing,
                 w1 = 3.516 * std::sqrt(E * I / (m / spacing * std::pow(L, 4)));
    sim->modules.push_back(
        std::make_unique<TipLoad>(tip, load, scale, 2 * m * w1, 2 * m * w1 * r * r));
    sim->dt = 5e-6;
    sim->options.skin = 2e-4;
  }
  double euler_bernoulli(double P) const {
    const double E = kn * spacing, I = std::numbers::pi * std::pow(r, 4) / 4;
    const double L = bonds * spacing;
    return P * L * L * L / (3 * E * I);
  }
};

}  // namespace

TEST(BondsEngine, BondedCantileverDeflectsAsEulerBernoulli) {
  const double P = 1e-5;  // N: deflection ~1.7e-5 m, 1e-3 of the length (small deflection)
  Cantilever c(1e12, {0, 0, -P});
  c.sim->run(40000);  // 0.2 s: ~30 damping times of the first mode
  ASSERT_EQ(c.module->bonds().size(), 10u);
  const double tip_z = c.sim->particles.x[slot_of(*c.sim, c.tip)].z;
  const double expected = c.euler_bernoulli(P);
  // 5 % as the issue asks; the chain differs from the beam by its discreteness (1/(4N²) =
  // 0.25 %) and its shear compliance (3 k̄n R̄² / (4 k̄s N² L_b²) = 0.5 %)
  EXPECT_NEAR(-tip_z, expected, 0.05 * expected) << "EB " << expected << " m";
  // at rest: the tip's speed has decayed to nothing
  EXPECT_LT(norm(c.sim->particles.v[slot_of(*c.sim, c.tip)]), 1e-6 * expected / 5e-6);
  // the chain's own closed form: rotational springs k̄n I at each bond, lever (m + ½) L_b, gives
  // EB (1 - 1/(4N²)), plus the shear of N bonds, N P / (k̄s A); 1e-4: what is left is the decay
  // of the motion and the geometric nonlinearity of a 1e-3 rotation (~1e-6)
  const double area = std::numbers::pi * Cantilever::r * Cantilever::r;
  const double chain = expected * (1 - 1.0 / (4 * Cantilever::bonds * Cantilever::bonds)) +
                       Cantilever::bonds * P / (Cantilever::ks * area);
  EXPECT_NEAR(-tip_z, chain, 1e-4 * chain);
  RecordProperty("deflection_over_euler_bernoulli", std::to_string(-tip_z / expected));
  RecordProperty("deflection_over_chain", std::to_string(-tip_z / chain));
}

TEST(BondsEngine, CantileverRootBondFailsAtTheCriterionLoad) {
  // root bond: |M_s| = P (N - ½) L_b at its contact point, σ = |M_s| R̄ / I reaches σ̄c at
  // P_c = σ̄c I / (R̄ (N - ½) L_b)
  const double sigma_c = 2e3;
  const double I = std::numbers::pi * std::pow(Cantilever::r, 4) / 4;
  const double Pc = sigma_c * I / (Cantilever::r * (Cantilever::bonds - 0.5) * Cantilever::spacing);
  // load: up to 0.9 P_c in 0.3 s, then 0.1 P_c per second (slow against the first mode, period
  // 0.04 s, and its damping time 1/ω1 = 6.5 ms)
  auto scale = [](double t) { return t < 0.3 ? 0.9 * t / 0.3 : 0.9 + 0.1 * (t - 0.3); };
  Cantilever c(sigma_c, {0, 0, -Pc}, scale);
  c.sim->dt = 1e-5;
  for (int k = 0; k < 300000 && c.module->failures().empty(); ++k) c.sim->step();
  ASSERT_FALSE(c.module->failures().empty());
  const auto& f = c.module->failures().front();
  EXPECT_EQ(f.cause, bonds::FailureCause::tensile);
  EXPECT_EQ(std::min(f.id_i, f.id_j), 1u);  // the bond at the clamp
  EXPECT_EQ(std::max(f.id_i, f.id_j), 2u);
  const double P_fail = Pc * scale(f.time);
  RecordProperty("failure_load_over_criterion", std::to_string(P_fail / Pc));
  // 1 %: the damped chain lags the slow ramp by about two damping times (2 × 6.5 ms × 0.1 P_c/s
  // = 0.13 % of P_c) and the failing step adds 1e-6 P_c
  EXPECT_NEAR(P_fail, Pc, 0.01 * Pc);
}

namespace {

// Two spheres with a gap of 1e-9 m flying apart at ±v along x: the bond stretches and breaks.
std::unique_ptr<Simulation> pulled_pair(const std::string& law, const std::string& keys, double v,
                                        bonds::BondsModule** module) {
  DemSetup s;
  auto sim = make_simulation(s);
  const double r = 1e-3;
  add_sphere(*sim, {0, 0, 0}, r, {-v, 0, 0});
  add_sphere(*sim, {2 * r + 1e-9, 0, 0}, r, {v, 0, 0});
  *module = add_bonds(*sim, law, keys, 1e-6);
  sim->options.skin = 1e-4;
  return sim;
}

double balance(const Simulation& sim) {
  const Observables o = sim.observe();
  const EnergyLedger& l = o.ledger;
  return o.kinetic_translational + o.kinetic_rotational + o.elastic + l.bond_elastic + l.damping +
         l.friction + l.removed + l.bond_dissipated - l.wall_work;
}

// The pair pulled apart for 2000 steps: the largest departure of the balance from its start
// and the most strain energy the bonds held.
struct Pulled {
  std::unique_ptr<Simulation> sim;
  bonds::BondsModule* module = nullptr;
  double e0 = 0, worst = 0, max_elastic = 0;
};

Pulled pull_apart(const std::string& law, const std::string& keys, double v, double dt) {
  Pulled r;
  r.sim = pulled_pair(law, keys, v, &r.module);
  r.sim->dt = dt;
  r.sim->setup();
  r.e0 = balance(*r.sim);
  for (int k = 0; k < 2000; ++k) {
    r.sim->step();
    r.worst = std::max(r.worst, std::abs(balance(*r.sim) - r.e0));
    r.max_elastic = std::max(r.max_elastic, r.sim->ledger.bond_elastic);
  }
  return r;
}

}  // namespace

TEST(BondsEngine, EnergyLedgerClosesWhenCohesiveBondBreaks) {
  // K A = 1e12 π 1e-6 = 3.1e6 N/m; G_Ic A = 10 π 1e-6 = 3.1e-5 J < the kinetic energy 9.4e-5 J
  const Pulled r =
      pull_apart("bilinear_cohesive",
                 "penalty_stiffness = 1e12\nnormal_strength = 1e6\nshear_strength = 1e6\n"
                 "mode_I_toughness = 10\nmode_II_toughness = 20\nbk_exponent = 2\n",
                 3.0, 1e-8);
  const auto& module = r.module;
  const auto& sim = r.sim;
  const double e0 = r.e0, worst = r.worst, max_elastic = r.max_elastic;
  ASSERT_EQ(module->failures().size(), 1u);
  EXPECT_EQ(module->failures()[0].cause, bonds::FailureCause::tensile);
  const double GA = 10 * std::numbers::pi * 1e-6;
  // pure mode I: the bond dissipates G_Ic A (1 %: the tolerance; the booking is exact
  // along a fixed mode ratio)
  EXPECT_NEAR(sim->ledger.bond_dissipated, GA, 0.01 * GA);
  EXPECT_NEAR(module->failures()[0].energy, sim->ledger.bond_dissipated, 1e-15);
  EXPECT_GT(max_elastic, 0.0);
  EXPECT_EQ(sim->ledger.bond_elastic, 0.0);
  // the balance holds to the integration error of velocity Verlet over the ~330 steps of the
  // bond's life (second order: below 1e-4 of the energy moved through the bond)
  EXPECT_LT(worst, 1e-4 * e0) << "worst drift " << worst << " J of " << e0 << " J";
  RecordProperty("worst_balance_drift_over_energy", std::to_string(worst / e0));
  RecordProperty("dissipated_over_GA", std::to_string(sim->ledger.bond_dissipated / GA));
}

TEST(BondsEngine, EnergyLedgerClosesWhenParallelBondBreaks) {
  // k̄n A = 3.1e6 N/m; fails at δ = σ̄c / k̄n = 1e-5 m, releasing ½ k̄n A δ² = 1.6e-4 J of the
  // kinetic energy m v² = 1.05e-3 J
  const Pulled r = pull_apart("parallel_bond",
                              "normal_stiffness = 1e12\nshear_stiffness = 4e11\n"
                              "tensile_strength = 1e7\nshear_strength = 1e7\n",
                              10.0, 2e-9);
  const auto& module = r.module;
  const auto& sim = r.sim;
  const double e0 = r.e0, worst = r.worst;
  ASSERT_EQ(module->failures().size(), 1u);
  const double released = 0.5 * 1e12 * std::numbers::pi * 1e-6 * 1e-5 * 1e-5;
  // the strain energy at failure, ∝ δ²: the failing step opens at most 2 v dt = 4e-8 m past
  // 1e-5 m, so it is up to 0.8 % above ½ k̄n A δ_c² and never below
  EXPECT_GE(sim->ledger.bond_dissipated, released);
  EXPECT_LT(sim->ledger.bond_dissipated, 1.008 * released);
  // A bond that fails under load drops its force within a step: velocity Verlet then books the
  // step's work with the force on for half of it, an error of at most F_c v_rel dt =
  // (σ̄c A)(2 v)(dt) = 31.4 N · 20 m/s · 2e-9 s = 1.26e-6 J (first order in dt, once per failure);
  // before the failure the balance holds to second order
  const double bound = 1e7 * std::numbers::pi * 1e-6 * 20.0 * 2e-9;
  EXPECT_LT(worst, bound) << "worst drift " << worst << " J of " << e0 << " J";
}

TEST(BondsEngine, CheckpointRestartIsBitForBit) {
  auto build = [](bonds::BondsModule** m) {
    Cantilever c(3e3, {0, 0, -2e-4});
    *m = c.module;
    return std::move(c.sim);
  };
  bonds::BondsModule* m1 = nullptr;
  auto straight = build(&m1);
  straight->run(3000);
  Archive a;
  straight->save(a);
  straight->run(3000);

  bonds::BondsModule* m2 = nullptr;
  auto resumed = build(&m2);
  resumed->load(a);
  resumed->run(3000);
  const auto& p = straight->particles;
  const auto& q = resumed->particles;
  ASSERT_EQ(p.size(), q.size());
  EXPECT_EQ(0, std::memcmp(p.x.data(), q.x.data(), p.size() * sizeof(Vec3)));
  EXPECT_EQ(0, std::memcmp(p.w.data(), q.w.data(), p.size() * sizeof(Vec3)));
  ASSERT_EQ(m1->bonds().size(), m2->bonds().size());
  EXPECT_EQ(m1->failures().size(), m2->failures().size());
  EXPECT_EQ(straight->ledger.bond_dissipated, resumed->ledger.bond_dissipated);
  for (std::size_t b = 0; b < m1->bonds().size(); ++b) {
    EXPECT_EQ(m1->bonds().state.moment(b), m2->bonds().state.moment(b));
    EXPECT_EQ(m1->bonds().state.rest[b].damage, m2->bonds().state.rest[b].damage);
  }
}
