// The collision log (issue 13, point 1): spectra from known collisions against their analytic
// cumulative distribution, events neither lost nor double-counted across thread counts,
// neighbour-list rebuilds and checkpoint restarts, the spectrum read back by `comminute pbm`'s
// reader, and determinism.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "comminute/analysis/collision_log.hpp"
#include "comminute/engine/parallel_threshold.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/pbm/capece_rate.hpp"
#include "comminute/pbm/collision_spectrum.hpp"
#include "dem_fixture.hpp"

using namespace comminute;
using namespace comminute::testing;
using analysis::CollisionLogModule;
using analysis::CollisionLogSettings;

namespace {

constexpr double kRadius = 0.005, kDensity = 2500;
const double kMass = kDensity * 4.0 / 3.0 * M_PI * std::pow(kRadius, 3);

CollisionLogSettings log_settings(std::vector<std::string> walls) {
  CollisionLogSettings s;
  s.materials = {"m"};
  s.walls = std::move(walls);
  s.energy_min = 1e-9;
  s.energy_max = 10;  // J, and J/kg for the specific impact energies (up to 1.5 J/kg here)
  s.bins = 100;       // 10 per decade
  return s;
}

CollisionLogModule& add_log(Simulation& sim, const CollisionLogSettings& s) {
  sim.modules.push_back(std::make_unique<CollisionLogModule>(s));
  return static_cast<CollisionLogModule&>(*sim.modules.back());
}

// Head-on pairs along x, one pair per (y, z) site of a square grid 4 radii apart (no pair meets
// another), closing at speed[k], centres at x = -+`half` radii; no gravity. The linear law,
// frictionless.
std::unique_ptr<Simulation> head_on_pairs(const std::vector<double>& speed, double restitution,
                                          double half = 1.5) {
  DemSetup s;
  s.law = "linear_spring_dashpot";
  s.linear_stiffness = 500;
  s.restitution = restitution;
  s.density = kDensity;
  auto sim = make_simulation(s);
  const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(double(speed.size()))));
  for (std::size_t k = 0; k < speed.size(); ++k) {
    const double y = 4 * kRadius * double(k % side), z = 4 * kRadius * double(k / side);
    add_sphere(*sim, {-half * kRadius, y, z}, kRadius, {0.5 * speed[k], 0, 0});
    add_sphere(*sim, {half * kRadius, y, z}, kRadius, {-0.5 * speed[k], 0, 0});
  }
  // contact time pi sqrt(m*/k_n) / sqrt(1 - beta^2) = 3.7 ms (e = 0.5): 184 steps
  sim->dt = 2e-5;
  return sim;
}

}  // namespace

TEST(CollisionLog, SpectrumOfKnownImpactsEqualsItsAnalyticCumulativeDistribution) {
  // N pairs whose impact energies 1/2 m* v^2 are the mid-quantiles of a log-uniform distribution
  // on [E_lo, E_hi]: F(E) = ln(E/E_lo) / ln(E_hi/E_lo).
  const int n = 200;
  const double e_lo = 1e-6, e_hi = 1e-3, mstar = 0.5 * kMass;
  std::vector<double> speed, energy;
  for (int k = 0; k < n; ++k) {
    energy.push_back(e_lo * std::pow(e_hi / e_lo, (k + 0.5) / n));
    speed.push_back(std::sqrt(2 * energy.back() / mstar));
  }
  auto sim = head_on_pairs(speed, 0.5);
  auto& log = add_log(*sim, log_settings({}));
  // the slowest pair (0.056 m/s) closes its gap of one radius in 0.09 s, then 3.7 ms in contact
  sim->run(13000);
  const std::size_t all = log.types() - 1;
  ASSERT_EQ(log.type_name(all), "all");
  EXPECT_EQ(log.sums(all).events, n);  // every pair once, none twice
  EXPECT_EQ(log.sums(0).events, n);    // material pair m-m
  const auto& h = log.histogram(all, 0);
  for (int b = 0; b <= h.bins(); ++b) {
    const double edge = h.edge(b);
    const double analytic = std::clamp(std::log(edge / e_lo) / std::log(e_hi / e_lo), 0.0, 1.0);
    // N mid-quantiles: the empirical distribution differs from the analytic one by at most
    // 1/(2N) at any energy
    EXPECT_NEAR(h.cumulative(b), analytic, 0.5 / n + 1e-12) << "edge " << edge;
    // exact count: the impact speed is the closing speed (no force acts before the touch), kept
    // in single precision (relative 6e-8, no energy lies that close to an edge)
    int below = 0;
    for (double e : energy) below += e <= edge;
    EXPECT_EQ(h.cumulative(b), double(below) / n) << "edge " << edge;
  }
  // the mean impact energy; the average-mass variant equals it times 2 for equal masses
  double mean = 0;
  for (double e : energy) mean += e / n;
  EXPECT_NEAR(log.sums(all).impact_reduced / n, mean, 1e-6 * mean);  // single-precision speed
  EXPECT_NEAR(log.sums(all).impact_average / n, 2 * mean, 2e-6 * mean);
  // every joule the dashpots dissipated is in the log: the same per-step numbers, summed per
  // contact here and per step in the ledger (rounding of 1e4 terms: 1e-9 relative is generous)
  const double logged = log.sums(all).dissipated_normal + log.sums(all).dissipated_tangential;
  EXPECT_NEAR(logged, sim->ledger.damping + sim->ledger.friction, 1e-9 * logged);
  // head-on and frictionless: all dissipation is normal, (1 - e^2) of the impact energy for the
  // linear spring-dashpot (the restitution is exact for this law); 184 steps per contact: the
  // Verlet error on the rebound speed is well below 0.5 %, 1 % on the energy
  EXPECT_NEAR(log.sums(all).dissipated_normal, (1 - 0.25) * mean * n, 0.01 * (0.75 * mean * n));
  EXPECT_NEAR(log.sums(all).dissipated_tangential, 0.0, 1e-12 * logged);

  // the spectrum file, read back by the reader of `comminute pbm`
  const double window = log.window_length(sim->time);
  EXPECT_DOUBLE_EQ(window, sim->time);
  const auto dir = std::filesystem::temp_directory_path() / "comminute_collision_spectrum";
  std::filesystem::create_directories(dir);
  int written = 0;
  for (const Table& t : log.tables(*sim))
    if (t.name() == "collision_spectrum_all" || t.name() == "collision_specific_energy_all") {
      t.write(dir);
      ++written;
    }
  ASSERT_EQ(written, 2);
  const CaseFile pbm = CaseFile::parse("spectrum_file = \"" +
                                       (dir / "collision_spectrum_all.csv").string() + "\"\n");
  const pbm::CollisionSpectrum spec = pbm::read_collision_spectrum(pbm.root(), "spectrum_file");
  ASSERT_EQ(spec.energy.size(), std::size_t(h.bins()));
  double rate = 0, power = 0;
  for (std::size_t k = 0; k < spec.energy.size(); ++k) {
    rate += spec.frequency[k];
    power += spec.frequency[k] * spec.energy[k];
    // each bin's energy lies in the bin (the mean of its events, or its centre when empty)
    EXPECT_GE(spec.energy[k], h.edge(int(k)) * (1 - 1e-12));
    EXPECT_LE(spec.energy[k], h.edge(int(k) + 1) * (1 + 1e-12));
  }
  // sum of frequencies = events per second; sum of frequency x energy = the impact energy per
  // second (bin energies are the means of their events); up to the CSV's exact round trip
  EXPECT_NEAR(rate, n / window, 1e-12 * n / window);
  EXPECT_NEAR(power, mean * n / window, 1e-6 * mean * n / window);
  // the mass-specific impact energies 1/2 v^2 = E / m*, read back by the `capece` rate's reader
  // (which checks that the probabilities sum to 1); their mean is the mean impact energy over m*
  const CaseFile capece = CaseFile::parse(
      "specific_energy_file = \"" + (dir / "collision_specific_energy_all.csv").string() + "\"\n");
  const auto em = pbm::read_specific_energy_distribution(capece.root(), "specific_energy_file");
  double mean_em = 0;
  for (std::size_t k = 0; k < em.energy.size(); ++k) mean_em += em.probability[k] * em.energy[k];
  EXPECT_NEAR(mean_em, mean / mstar, 1e-6 * mean / mstar);  // single-precision speed
  std::filesystem::remove_all(dir);
}

namespace {

struct Counts {
  double pair = 0, wall = 0, dissipated = 0;
  bool operator==(const Counts&) const = default;
};

Counts counts(const CollisionLogModule& log) {
  Counts c;
  c.pair = log.sums(0).events_total;
  for (std::size_t k = 1; k + 1 < log.types(); ++k) c.wall += log.sums(k).events_total;
  const auto& all = log.sums(log.types() - 1);
  c.dissipated = all.dissipated_normal + all.dissipated_tangential;
  return c;
}

// 2304 pairs closing at 0.5 m/s with a gap of 0.2 radii, between two walls at x = +-0.011 m
// (0.5 mm from the particles); a skin of 15 mm lists each particle's lateral neighbours too, so
// the pair list and the wall candidates (every particle) are long enough to run on several
// threads. Each pair touches over steps 101-285 and separates at 0.25 m/s; each particle meets
// its wall 1 mm further over steps ~690-950 (5.2 ms) and comes back (the second pair collision
// is after step 1700).
std::unique_ptr<Simulation> pairs_between_walls() {
  std::vector<double> speed(2304, 0.5);
  auto sim = head_on_pairs(speed, 0.5, 1.1);
  sim->options.skin = 0.015;
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{-0.011, 0, 0}, Vec3{1, 0, 0}));
  sim->walls.push_back(std::make_unique<PlaneWall>(Vec3{0.011, 0, 0}, Vec3{-1, 0, 0}));
  return sim;
}

}  // namespace

TEST(CollisionLog, EventsAreNeitherLostNorDoubleCountedAcrossThreadsRebuildsAndRestarts) {
  const int threads = omp_get_max_threads();
  const std::uint64_t steps = 1100;  // every pair and wall collision, no second one
  auto run = [&](int nt, bool rebuild_every_step, std::uint64_t restart_at) {
    omp_set_num_threads(nt);
    auto sim = pairs_between_walls();
    auto* log = &add_log(*sim, log_settings({"left", "right"}));
    for (std::uint64_t s = 0; s < steps; ++s) {
      if (rebuild_every_step) sim->particles_changed();
      sim->step();
      if (s + 1 == restart_at) {  // a fresh simulation continues from the checkpoint
        const Observables o = sim->observe();
        EXPECT_GT(o.contacts + o.wall_contacts, 1000u)  // events open at the checkpoint
            << "step " << restart_at;
        Archive a;
        sim->save(a);
        sim = pairs_between_walls();
        log = &add_log(*sim, log_settings({"left", "right"}));
        sim->load(a);
      }
    }
    omp_set_num_threads(threads);
    // the lists are long enough for the force loops to split them between threads
    EXPECT_GE(sim->pairs().size(), 2 * kParallelMin);
    EXPECT_GE(sim->wall_state().size(), kParallelMin / 2);
    return counts(*log);
  };
  const Counts serial = run(1, false, 0);
  // every pair once, every particle on its wall once
  EXPECT_EQ(serial.pair, 2304);
  EXPECT_EQ(serial.wall, 2 * 2304);
  // two threads: the pair and wall loops split the lists; a neighbour-list rebuild at every step
  // (contacts carried through every build while open); a restart in the middle of the pair
  // collisions (step 200) and one in the middle of the wall collisions (step 800). Counts are
  // exact; the dissipation sums too, up to the summation order of the force loops (1e-12)
  for (const Counts& c :
       {run(2, false, 0), run(1, true, 0), run(1, false, 200), run(2, false, 800)}) {
    EXPECT_EQ(c.pair, serial.pair);
    EXPECT_EQ(c.wall, serial.wall);
    EXPECT_NEAR(c.dissipated, serial.dissipated, 1e-12 * serial.dissipated);
  }
}

TEST(CollisionLog, SameCaseSameOutputs) {
  // two runs of the same set-up write the same tables, cell for cell
  auto tables = [] {
    std::vector<double> speed;
    for (int k = 0; k < 50; ++k) speed.push_back(0.1 + 0.01 * k);
    auto sim = head_on_pairs(speed, 0.3);
    auto& log = add_log(*sim, log_settings({}));
    sim->run(3000);
    std::string text;
    const auto dir = std::filesystem::temp_directory_path() / "comminute_collision_determinism";
    std::filesystem::create_directories(dir);
    for (const Table& t : log.tables(*sim)) {
      t.write(dir);
      std::ifstream in(dir / (t.name() + ".csv"));
      text += std::string(std::istreambuf_iterator<char>(in), {});
    }
    std::filesystem::remove_all(dir);
    return text;
  };
  const std::string a = tables();
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, tables());
}
