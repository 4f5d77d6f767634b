// OpenMP: a run with the same thread count is bit-for-bit reproducible, and a bed of spheres in a
// box runs bit for bit the same on one, two and three threads (every particle receives its contact
// loads in the order of the pair list, whatever split the pair loop takes; engine/pair_force_loop).
// Large enough
// (> 4096 particles) for every parallel loop to run threaded; scripts/test also runs this test
// in a ThreadSanitizer build (with LLVM's OpenMP and its archer tool) to check for data races.
#include <gtest/gtest.h>
#include <omp.h>

#include "breakage_engine_fixture.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/contact_pipeline.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

// A lattice of spheres in an open box, moving sideways (`stirred`: every way, off the lattice
// points in all three directions, so that contacts come from every direction).
std::unique_ptr<Simulation> lattice_bed(int threads, std::unique_ptr<Module> module = nullptr,
                                        bool stirred = false) {
  omp_set_num_threads(threads);
  auto sim = make_simulation(frictional_rolling_setup());
  const double r = 0.001, a = 2.05 * r;
  const int nx = 20;
  add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{nx * a, nx * a, 1.0});
  Rng rng(9);
  const double off = stirred ? 0.02 * r : 0.0, vz = stirred ? 0.1 : 0.0;
  for (int k = 0; k < 13; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i)
        add_sphere(*sim,
                   {(i + 0.5) * a + rng.uniform(-1e-5, 1e-5),
                    (j + 0.5) * a + rng.uniform(-off, off), (k + 0.5) * a + rng.uniform(-off, off)},
                   r * rng.uniform(0.9, 1.0),
                   {rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), rng.uniform(-vz, vz)});
  sim->dt = 1e-5;
  if (module) sim->modules.push_back(std::move(module));
  sim->setup();
  return sim;
}

// Asks for the contact stress (engine/contact_stress.hpp) and arms it every step.
class ArmContactStress final : public Module {
 public:
  std::string name() const override { return "arm"; }
  void declare_contact_state(ContactPipeline& p) override { p.require_contact_stress(); }
  void pre_force(Simulation& sim) override { sim.contacts().stress()->arm(); }
};

}  // namespace

TEST(Parallel, SameThreadCountIsBitForBitReproducible) {
  const int steps = 300;
  auto a = lattice_bed(2);
  a->run(steps);
  auto b = lattice_bed(2);
  b->run(steps);
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_GT(a->particles.size(), 4096u);
  ASSERT_GT(a->observe().contacts, 300u);  // the contact loop is exercised
  EXPECT_EQ(a->particles.x, b->particles.x);
  EXPECT_EQ(a->particles.w, b->particles.w);
}

TEST(Parallel, AnyThreadCountGivesTheSameRunBitForBit) {
  // Same initial state on one, two and three threads (three on a two-core machine: the threads
  // take turns, their speeds and so the splits vary from step to step): the same positions,
  // velocities, spins and energy books, bit for bit, over 300 steps of a stirred bed.
  const int steps = 300;
  auto a = lattice_bed(1, nullptr, true);
  a->run(steps);
  for (int threads : {2, 3}) {
    auto b = lattice_bed(threads, nullptr, true);
    b->run(steps);
    ASSERT_EQ(a->particles.size(), b->particles.size());
    ASSERT_GT(a->observe().contacts, 500u);  // the contact loop is exercised
    for (std::size_t i = 0; i < a->particles.size(); ++i) {
      const std::size_t j = slot_of(*b, a->particles.id[i]);
      ASSERT_EQ(a->particles.x[i], b->particles.x[j]) << threads << " threads, slot " << i;
      ASSERT_EQ(a->particles.v[i], b->particles.v[j]) << threads << " threads, slot " << i;
      ASSERT_EQ(a->particles.w[i], b->particles.w[j]) << threads << " threads, slot " << i;
    }
    const Observables oa = a->observe(), ob = b->observe();
    EXPECT_EQ(oa.elastic, ob.elastic) << threads << " threads";
    EXPECT_EQ(oa.ledger.damping, ob.ledger.damping) << threads << " threads";
    EXPECT_EQ(oa.ledger.friction, ob.ledger.friction) << threads << " threads";
  }
  omp_set_num_threads(omp_get_num_procs());
}

// parallel_scatter (pair loops of modules writing both particles of a pair): a minimum is exact
// for any thread count; a sum differs from the serial one only by rounding (each slot sums ~80
// terms of magnitude <= 1, so reordering moves it by at most ~80 ulp of ~10, about 2e-13: 1e-12
// absolute) and repeats bit for bit with the same thread count.
TEST(Parallel, ScatterMatchesTheSerialLoop) {
  const std::size_t pairs = 200000, slots = 5000;
  Rng rng(3);
  std::vector<std::uint32_t> a(pairs), b(pairs);
  std::vector<double> w(pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    a[k] = static_cast<std::uint32_t>(rng.below(slots));
    b[k] = static_cast<std::uint32_t>(rng.below(slots));
    w[k] = rng.uniform(-1, 1);
  }
  auto run = [&](int threads, std::vector<double>& sum, std::vector<double>& low) {
    omp_set_num_threads(threads);
    sum.assign(slots, 0.0);
    low.assign(slots, 10.0);
    parallel_scatter(
        pairs, sum, 0.0,
        [&](std::size_t k, std::vector<double>& s) {
          s[a[k]] += w[k];
          s[b[k]] -= 0.5 * w[k];
        },
        [](double x, double y) { return x + y; });
    parallel_scatter(
        pairs, low, 10.0,
        [&](std::size_t k, std::vector<double>& m) {
          m[a[k]] = std::min(m[a[k]], w[k]);
          m[b[k]] = std::min(m[b[k]], -w[k]);
        },
        [](double x, double y) { return std::min(x, y); });
  };
  const int saved = omp_get_max_threads();
  std::vector<double> s1, m1, s2, m2, s2b, m2b;
  run(1, s1, m1);
  run(2, s2, m2);
  run(2, s2b, m2b);
  omp_set_num_threads(saved);
  EXPECT_EQ(m1, m2);
  EXPECT_EQ(s2, s2b);
  for (std::size_t i = 0; i < slots; ++i) EXPECT_NEAR(s1[i], s2[i], 1e-12);
}

// owner_scatter over items grouped by owner, as a half pair list is by its first particle, with
// a tenth of them out of owner order (their sums must come out the same, only queued):
// - one thread gives exactly the serial loop's sums and minima (same order of additions);
// - two threads: minima exact (order-free); sums equal the serial ones to rounding (each slot sums
//   ~80 terms of magnitude <= 1: at most ~80 ulp of ~10, about 2e-13, so 1e-12 absolute) and
//   repeat bit for bit; stale values in `out` and in the kept queues are dropped.
TEST(Parallel, OwnerScatterMatchesTheSerialLoop) {
  const std::size_t items = 200000, slots = 5000;
  Rng rng(4);
  std::vector<std::uint32_t> a(items), b(items);
  std::vector<double> w(items);
  for (std::size_t k = 0; k < items; ++k) {
    a[k] = static_cast<std::uint32_t>(k * slots / items);  // the owner, ascending
    if (rng.uniform(0, 1) < 0.1) a[k] = static_cast<std::uint32_t>(rng.below(slots));
    b[k] = static_cast<std::uint32_t>(rng.below(slots));
    w[k] = rng.uniform(-1, 1);
  }
  std::vector<double> serial_sum(slots, 0.0), serial_low(slots, 10.0);
  for (std::size_t k = 0; k < items; ++k) {
    serial_sum[a[k]] += w[k];
    serial_sum[b[k]] += -0.5 * w[k];
    serial_low[a[k]] = std::min(serial_low[a[k]], w[k]);
    serial_low[b[k]] = std::min(serial_low[b[k]], -w[k]);
  }
  OwnerScatterQueues<double> sum_queues, low_queues;  // kept from call to call
  auto run = [&](int threads, std::vector<double>& sum, std::vector<double>& low) {
    omp_set_num_threads(threads);
    sum.assign(slots, 7.0);  // stale: the scatter resets every slot
    low.assign(slots, -7.0);
    owner_scatter(
        items, [&](std::size_t k) { return a[k]; }, sum, 0.0,
        [&](std::size_t k, auto& add) {
          add(a[k], w[k]);
          add(b[k], -0.5 * w[k]);
        },
        [](double x, double y) { return x + y; }, sum_queues);
    owner_scatter(
        items, [&](std::size_t k) { return a[k]; }, low, 10.0,
        [&](std::size_t k, auto& add) {
          add(a[k], w[k]);
          add(b[k], -w[k]);
        },
        [](double x, double y) { return std::min(x, y); }, low_queues);
  };
  const int saved = omp_get_max_threads();
  std::vector<double> s1, m1, s2, m2, s2b, m2b;
  run(1, s1, m1);
  run(2, s2, m2);
  run(2, s2b, m2b);
  omp_set_num_threads(saved);
  EXPECT_EQ(s1, serial_sum);
  EXPECT_EQ(m1, serial_low);
  EXPECT_EQ(m2, serial_low);
  EXPECT_EQ(s2, s2b);
  EXPECT_EQ(sum_queues.size(), 2u);  // the two-thread calls queued into two queues
  for (std::size_t i = 0; i < slots; ++i) EXPECT_NEAR(s2[i], serial_sum[i], 1e-12);
}

// ParticleStore::extend and put (breakage writes many parents' fragments at once into slots laid
// out beforehand) against add_with_mass one by one: a store of 20000 (past the size where extend
// resizes its arrays on all threads) with two fields, 3000 particles appended either way, the
// slots of the second store written by two threads in interleaved order; every array, field and
// the next id must be exactly the same, and the blank slots must hold the fields' defaults.
TEST(Parallel, StoreExtendedAndPutOnTwoThreadsEqualsAppendingOneByOne) {
  auto base = [] {
    ParticleStore p;
    p.add_field("damage", 0.25);
    p.add_field("target", -1.0);
    Rng rng(5);
    for (int k = 0; k < 20000; ++k) {
      ParticleInit init;
      init.x = {rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)};
      init.radius = 0.001;
      init.density = 2500;
      p.add(init);
    }
    return p;
  };
  auto fresh = [](std::size_t k) {
    ParticleInit init;
    init.x = {0.1 * static_cast<double>(k), 0, 1};
    init.v = {0, static_cast<double>(k), 0};
    init.radius = 0.0002 + 1e-7 * static_cast<double>(k);
    init.material = static_cast<std::uint16_t>(k % 3);
    init.flags = k % 2 == 0 ? pflag::growing : 0;
    return init;
  };
  constexpr std::size_t added = 3000;
  ParticleStore one = base();
  for (std::size_t k = 0; k < added; ++k)
    one.add_with_mass(fresh(k), 1e-6 * static_cast<double>(k));
  ParticleStore two = base();
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);
  const std::size_t first_slot = two.size();
  two.extend(added);
  for (std::size_t s = first_slot; s < two.size(); ++s) {  // blank until put
    EXPECT_EQ(two.field(0)[s], 0.25);
    EXPECT_EQ(two.field(1)[s], -1.0);
    EXPECT_EQ(two.id[s], 0u);
  }
  const std::uint64_t first_id = two.take_ids(added);
#pragma omp parallel for schedule(static, 1)
  for (std::size_t k = 0; k < added; ++k)
    two.put(first_slot + k, fresh(k), 1e-6 * static_cast<double>(k), first_id + k);
  omp_set_num_threads(saved);
  EXPECT_EQ(two.next_id(), one.next_id());
  EXPECT_EQ(two.x, one.x);
  EXPECT_EQ(two.v, one.v);
  EXPECT_EQ(two.w, one.w);
  EXPECT_EQ(two.f, one.f);
  EXPECT_EQ(two.t, one.t);
  EXPECT_EQ(two.radius, one.radius);
  EXPECT_EQ(two.mass, one.mass);
  EXPECT_EQ(two.inertia, one.inertia);
  EXPECT_EQ(two.id, one.id);
  EXPECT_EQ(two.material, one.material);
  EXPECT_EQ(two.flags, one.flags);
  EXPECT_EQ(two.field(0), one.field(0));
  EXPECT_EQ(two.field(1), one.field(1));
  two.add_ghost(0, {}, {}, {});
  EXPECT_THROW(two.extend(1), Error);  // ghosts are the force stage's, never extended over
}

// Breakage on two threads: a pre-stressed lattice of 9261 weak particles squeezed by a platen
// (the benchmark's bed, small), so that the module's threaded loops (contact loads, growth) and
// in-place fragment insertion all run; the same thread count must repeat bit for bit. Also run
// under ThreadSanitizer by scripts/test.
TEST(Parallel, BreakageRepeatsBitForBitOnTwoThreads) {
  auto run = [] {
    omp_set_num_threads(2);
    DemSetup s;
    s.youngs = 5e7;
    auto sim = make_simulation(s);
    Rng rng(11);
    const double d = 0.003, a = 0.995 * d, L = 21 * a;
    lattice(*sim, d, a, L, 1.0, rng);
    add_open_top_box(*sim, Vec3{0, 0, 0}, Vec3{L, L, 2 * L});
    auto platen = std::make_unique<PlaneWall>(Vec3{0, 0, L}, Vec3{0, 0, -1});
    platen->kinematics.velocity = {0, 0, -1.0};
    sim->walls.push_back(std::move(platen));
    std::vector<std::optional<breakage::MaterialBreakage>> mats;
    mats.emplace_back(weak_material(0.1, 0.5, 0.0015, 0.3, breakage::FinesRule::mass, 0.0));
    auto mod =
        std::make_unique<breakage::BreakageModule>(std::move(mats), breakage::BreakageOptions{});
    breakage::BreakageModule* m = mod.get();
    sim->modules.push_back(std::move(mod));
    sim->dt = 0.2 * M_PI * 0.00045 * std::sqrt(2500 / (5e7 / 2.6)) / (0.1631 * 0.3 + 0.8766);
    sim->setup();
    sim->run(40);
    return std::make_pair(m->breakages(), sim->particles.x);
  };
  const int saved = omp_get_max_threads();
  const auto first = run();
  const auto second = run();
  omp_set_num_threads(saved);
  EXPECT_GT(first.first, 100u);
  EXPECT_EQ(first.first, second.first);
  EXPECT_EQ(first.second, second.second);
}

// The per-particle Love–Weber moments and load-bearing counts of the contact stress on two
// threads (a particle that pairs of both threads touch has its shares queued and added in pair
// order, as the forces) against one thread, one step from the same checkpointed state of a
// stirred bed (so from the same positions): the same, bit for bit.
TEST(Parallel, ContactStressOnTwoThreadsAgreesWithOne) {
  auto settled = lattice_bed(1, std::make_unique<ArmContactStress>(), true);
  settled->run(300);
  Archive ar;
  settled->save(ar);
  auto a = lattice_bed(1, std::make_unique<ArmContactStress>(), true);
  a->load(ar);
  a->step();
  auto b = lattice_bed(2, std::make_unique<ArmContactStress>(), true);
  b->load(ar);
  b->step();
  omp_set_num_threads(omp_get_num_procs());
  const ContactStress& sa = *a->contacts().stress();
  const ContactStress& sb = *b->contacts().stress();
  const std::size_t n = a->particles.size();
  ASSERT_GT(n, 4096u);
  double largest = 0;
  std::size_t bearing = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (double m : sa.moment[i]) largest = std::max(largest, std::abs(m));
    bearing += sa.load_bearing[i];
  }
  ASSERT_GT(largest, 0.0);
  ASSERT_GT(bearing, 300u);  // the contact loop is exercised
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = slot_of(*b, a->particles.id[i]);
    ASSERT_EQ(sa.load_bearing[i], sb.load_bearing[j]) << "particle " << a->particles.id[i];
    for (std::size_t k = 0; k < 6; ++k)
      ASSERT_EQ(sa.moment[i][k], sb.moment[j][k])
          << "particle " << a->particles.id[i] << " component " << k;
  }
}
