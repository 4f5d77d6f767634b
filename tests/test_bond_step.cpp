// The batch bond step (bonds/bond_step.hpp) against one update() call per bond: the same bond
// states, the same force on j and the torques (x_c − x) × F + M, bit for bit, for both bond laws;
// a gone bond is skipped, a failing one is flagged and carries nothing, the sums add up.
#include <gtest/gtest.h>

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
};

// Returns how many of the two loaded bonds failed.
std::size_t check_batch_equals_single(const BondLaw& law, double strain) {
  Scene sc;
  Rng rng(1, 7);
  std::vector<BondState> state;
  for (std::size_t b = 0; b < sc.si.size(); ++b) {
    // made at a slightly different length, so that the bonds carry load
    const Vec3 d = sc.x[sc.sj[b]] - sc.x[sc.si[b]];
    state.push_back(law.create(sc.radius[sc.si[b]], sc.radius[sc.sj[b]], norm(d) * (1 - strain),
                               d / norm(d), rng));
  }
  std::vector<BondState> single = state;
  std::vector<std::uint8_t> flag{0, 0, 1};
  std::vector<Vec3> force(3), ti(3), tj(3);
  const BondStep st{.x = sc.x.data(),
                    .v = sc.v.data(),
                    .w = sc.w.data(),
                    .radius = sc.radius.data(),
                    .slot_i = sc.si.data(),
                    .slot_j = sc.sj.data(),
                    .state = state.data(),
                    .flag = flag.data(),
                    .dt = 1e-6,
                    .force = force.data(),
                    .torque_i = ti.data(),
                    .torque_j = tj.data()};
  const BondStepSums sums = law.update_range(st, 0, 3);
  double released = 0, elastic = 0;
  std::size_t failed = 0;
  for (std::size_t b = 0; b < 2; ++b) {
    // the motion as the bonds module computed it before the batch step (one virtual call per bond)
    const std::uint32_t i = sc.si[b], j = sc.sj[b];
    const Vec3 d = sc.x[j] - sc.x[i];
    BondMotion m;
    m.length = norm(d);
    m.normal = d * (1.0 / m.length);
    const Vec3 xc = bond_point(sc.x[i], sc.radius[i], sc.radius[j], m.normal, m.length);
    const Vec3 vc = sc.v[j] + cross(sc.w[j], xc - sc.x[j]) - sc.v[i] - cross(sc.w[i], xc - sc.x[i]);
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
    EXPECT_EQ(tj[b], cross(xc - sc.x[j], load.force) + load.moment);
    EXPECT_EQ(ti[b], cross(xc - sc.x[i], load.force) + load.moment);
    EXPECT_GT(norm(load.force), 0.0);  // the bond is loaded: the comparison is not of zeros
  }
  // the gone bond is left as it was and carries nothing
  EXPECT_EQ(state[2].normal, single[2].normal);
  EXPECT_EQ(state[2].strain_energy, 0.0);
  EXPECT_EQ(flag[2], 1);
  EXPECT_EQ(force[2], Vec3{});
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
