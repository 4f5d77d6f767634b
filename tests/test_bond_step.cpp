// The batch bond step (bonds/bond_step.hpp) against one update() call per bond: the same bond
// states, the same force on j and the torques (x_c − x) × F + M, bit for bit, for both bond laws;
// a gone bond is skipped, a failing one is flagged and carries nothing, the sums add up.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "comminute/bonds/bond_law.hpp"
#include "comminute/bonds/bond_step.hpp"

using namespace comminute;
using namespace comminute::bonds;

namespace {

std::unique_ptr<BondLaw> make_law(const std::string& name, const std::string& text) {
  const CaseFile f = CaseFile::parse(text);
  auto law = BondLawRegistry::create(name, f.root());
  f.reject_unknown();
  return law;
}

// Four particles, bonds 0–1, 1–2, 2–3 (the last one flagged gone), all moving and spinning.
struct Scene {
  std::vector<Vec3> x{{0, 0, 0}, {2.01e-3, 1e-5, 0}, {4.0e-3, 2e-5, -1e-5}, {6e-3, 0, 0}};
  std::vector<Vec3> v{{1e-3, 0, 0}, {-2e-3, 1e-3, 5e-4}, {0, -1e-3, 2e-3}, {0, 0, 0}};
  std::vector<Vec3> w{{0.1, -0.2, 0.3}, {-0.3, 0.1, 0.2}, {0.2, 0.2, -0.1}, {0, 0, 0}};
  std::vector<double> radius{1e-3, 1e-3, 1.1e-3, 1e-3};
  std::vector<std::uint32_t> si{0, 1, 2}, sj{1, 2, 3};
  std::vector<std::uint8_t> flag{0, 0, 1};
};

// A chain of n particles with scattered positions, velocities and spins, bonds k–(k+1), every
// seventh one gone: more bonds than one batch of the vectorised step, with a remainder.
Scene chain(std::size_t n) {
  Scene sc;
  Rng rng(5, 3);
  sc.x.clear(), sc.v.clear(), sc.w.clear(), sc.radius.clear(), sc.si.clear(), sc.sj.clear();
  sc.flag.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const double r = 1e-3 * (1 + 0.1 * rng.uniform());
    const double at = sc.x.empty() ? 0.0 : sc.x.back().x + sc.radius.back() + r;
    sc.x.push_back({at, 2e-5 * rng.uniform(), 2e-5 * rng.uniform()});
    sc.v.push_back({1e-3 * rng.uniform(), -1e-3 * rng.uniform(), 1e-3 * rng.uniform()});
    sc.w.push_back({0.3 * rng.uniform(), -0.2 * rng.uniform(), 0.1 * rng.uniform()});
    sc.radius.push_back(r);
    if (k == 0) continue;
    sc.si.push_back(static_cast<std::uint32_t>(k - 1));
    sc.sj.push_back(static_cast<std::uint32_t>(k));
    sc.flag.push_back(k % 7 == 3 ? 1 : 0);
  }
  return sc;
}

// Returns how many of the loaded bonds failed.
std::size_t check_batch_equals_single(const BondLaw& law, double strain, const Scene& sc = {}) {
  Rng rng(1, 7);
  std::vector<BondState> state;
  for (std::size_t b = 0; b < sc.si.size(); ++b) {
    // made at a slightly different length, so that the bonds carry load
    const Vec3 d = sc.x[sc.sj[b]] - sc.x[sc.si[b]];
    state.push_back(law.create(sc.radius[sc.si[b]], sc.radius[sc.sj[b]], norm(d) * (1 - strain),
                               d / norm(d), rng));
  }
  std::vector<BondState> single = state;
  BondStates split;  // as a bond list keeps them: hot and cold records apart
  split.assign(state);
  const std::size_t nb = sc.si.size();
  std::vector<std::uint8_t> flag = sc.flag;
  std::vector<Vec3> force(nb), ti(nb), tj(nb);
  const BondStep st{.x = sc.x.data(),
                    .v = sc.v.data(),
                    .w = sc.w.data(),
                    .radius = sc.radius.data(),
                    .slot_i = sc.si.data(),
                    .slot_j = sc.sj.data(),
                    .state = &split,
                    .flag = flag.data(),
                    .dt = 1e-6,
                    .force = force.data(),
                    .torque_i = ti.data(),
                    .torque_j = tj.data()};
  const BondStepSums sums = law.update_range(st, 0, nb);
  state = split.records();
  double released = 0, elastic = 0;
  std::size_t failed = 0;
  for (std::size_t b = 0; b < nb; ++b) {
    if (sc.flag[b]) {  // a gone bond is left as it was and carries nothing
      EXPECT_EQ(state[b].normal, single[b].normal);
      EXPECT_EQ(state[b].strain_energy, 0.0);
      EXPECT_EQ(flag[b], 1);
      EXPECT_EQ(force[b], Vec3{});
      continue;
    }
    // the motion as the bond sees it (one virtual call per bond): the contact point's levers
    // from the relative position, its velocity from the relative velocity and the spins
    const std::uint32_t i = sc.si[b], j = sc.sj[b];
    const Vec3 d = sc.x[j] - sc.x[i];
    BondMotion m;
    m.length = norm(d);
    m.normal = d * (1.0 / m.length);
    const Vec3 lever_i = (sc.radius[i] + 0.5 * (m.length - sc.radius[i] - sc.radius[j])) * m.normal;
    const Vec3 lever_j = lever_i - d;
    const Vec3 vc = (sc.v[j] - sc.v[i]) + cross(sc.w[j], lever_j) - cross(sc.w[i], lever_i);
    m.slip_increment = (vc - dot(vc, m.normal) * m.normal) * st.dt;
    m.rotation_increment = (sc.w[j] - sc.w[i]) * st.dt;
    const double before = single[b].dissipated;
    const BondLoad load = law.update(single[b], m);
    released += single[b].dissipated - before;
    // bit for bit: the batch runs the same arithmetic, only without the virtual call
    EXPECT_EQ(state[b].normal, single[b].normal);
    EXPECT_EQ(state[b].shear_force, single[b].shear_force);
    EXPECT_EQ(state[b].moment, single[b].moment);
    EXPECT_EQ(state[b].slip, single[b].slip);
    EXPECT_EQ(state[b].damage, single[b].damage);
    EXPECT_EQ(state[b].strain_energy, single[b].strain_energy);
    EXPECT_EQ(state[b].failed, single[b].failed);
    if (single[b].failed != FailureMode::none) {
      ++failed;
      EXPECT_EQ(flag[b], 2);
      EXPECT_EQ(force[b], Vec3{});
      EXPECT_EQ(ti[b], Vec3{});
      EXPECT_EQ(tj[b], Vec3{});
      continue;
    }
    elastic += single[b].strain_energy;
    EXPECT_EQ(flag[b], 0);
    EXPECT_EQ(force[b], load.force);
    EXPECT_EQ(tj[b], cross(lever_j, load.force) + load.moment);
    EXPECT_EQ(ti[b], cross(lever_i, load.force) + load.moment);
    EXPECT_GT(norm(load.force), 0.0);  // the bond is loaded: the comparison is not of zeros
  }
  EXPECT_EQ(sums.failed, failed);
  EXPECT_EQ(sums.released, released);  // summed in the same (bond) order
  EXPECT_EQ(sums.elastic, elastic);
  return failed;
}

}  // namespace

TEST(BondStep, ParallelBondBatchEqualsOneUpdatePerBond) {
  const std::string keys =
      "normal_stiffness = 1e10\nshear_stiffness = 4e9\ntensile_strength = 1e7\n"
      "shear_strength = 1e7\n";
  EXPECT_EQ(check_batch_equals_single(*make_law("parallel_bond", keys), 1e-4), 0u);
}

TEST(BondStep, ParallelBondBatchFlagsAFailure) {
  // 1 % strain at k̄n = 1e10 Pa/m on 2 mm: σ ≈ 2e5 Pa > 1e5 Pa, both loaded bonds fail
  const std::string keys =
      "normal_stiffness = 1e10\nshear_stiffness = 4e9\ntensile_strength = 1e5\n"
      "shear_strength = 1e7\n";
  EXPECT_EQ(check_batch_equals_single(*make_law("parallel_bond", keys), 1e-2), 2u);
}

TEST(BondStep, CohesiveBondBatchEqualsOneUpdatePerBond) {
  const std::string keys =
      "penalty_stiffness = 1e12\nnormal_strength = 1e7\nshear_strength = 1e7\n"
      "mode_I_toughness = 1000\nmode_II_toughness = 2000\nbk_exponent = 2\n";
  // δ = 2e-3 × 2 mm = 4 µm below δ0 = N/K = 10 µm: elastic, loaded, intact
  EXPECT_EQ(check_batch_equals_single(*make_law("bilinear_cohesive", keys), 2e-3), 0u);
}

TEST(BondStep, ParallelBondBatchEqualsOneUpdatePerBondOverSeveralBatches) {
  // 99 bonds: three full batches of the vectorised step and a remainder, gone bonds among them
  const std::string keys =
      "normal_stiffness = 1e10\nshear_stiffness = 4e9\ntensile_strength = 1e7\n"
      "shear_strength = 1e7\n";
  EXPECT_EQ(check_batch_equals_single(*make_law("parallel_bond", keys), 1e-4, chain(100)), 0u);
}

TEST(BondStep, ParallelBondBatchFlagsFailuresOverSeveralBatches) {
  // strain scattered by the chain's gaps: 1 % nominal at σ̄c = 1e5 Pa, every loaded bond fails
  const std::string keys =
      "normal_stiffness = 1e10\nshear_stiffness = 4e9\ntensile_strength = 1e5\n"
      "shear_strength = 1e7\n";
  const Scene sc = chain(100);
  EXPECT_EQ(check_batch_equals_single(*make_law("parallel_bond", keys), 1e-2, sc),
            static_cast<std::size_t>(std::count(sc.flag.begin(), sc.flag.end(), 0)));
}
