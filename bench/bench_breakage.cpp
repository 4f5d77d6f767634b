// Cost of breakage in a bed: `bench_breakage N on|off [warmup=50] [steps=200]` builds a cubic
// lattice of ~N weak 3 mm particles (Hertz, E = 50 MPa; spacing 0.995 d, so every particle starts
// with six 0.5 % overlaps) in a box, agitated (random velocities up to 1 m/s per component) and
// squeezed by a platen at 1 m/s, so that nearly every particle breaks at its first collisions and
// the fragments break again (down to 1.5 mm); then it times `steps` steps after `warmup` and
// prints particle-steps per second, with the breakage module ("on") or without it ("off", the same
// bed and time step), and with it the seconds spent in the module's post_force (growth, contact
// loads, events) and end_of_step (replacement). Issue 3's benchmark; results in bench/RESULTS.md
// ("## Breakage"). Environment: SORT_EVERY (re-sort the particles by cell every this many list
// rebuilds, >= 0, 0 never; default 20), REPLACEMENT_INTERVAL (the breakage module's
// replacement_interval, steps >= 1; default 1); any other value is refused (exit code 2).
#include <fmt/format.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "comminute/breakage/breakage_module.hpp"
#include "comminute/breakage/criteria/tavares.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"

namespace {
// The integer >= `least` in environment variable `name`, or `fallback` when it is not set; exits
// with code 2 on anything else (a typo must not run the default set-up under another name).
int env_count(const char* name, int fallback, int least) {
  const char* text = std::getenv(name);
  if (!text) return fallback;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < least || v > std::numeric_limits<int>::max()) {
    fmt::print(stderr, "error: {}={} is not an integer >= {}\n", name, text, least);
    std::exit(2);
  }
  return static_cast<int>(v);
}

// The breakage module with a stopwatch on each of its hooks: the seconds the step spends in
// breakage (criterion, events, replacement and the neighbour-list updates it calls for).
class TimedModule : public comminute::Module {
 public:
  explicit TimedModule(std::unique_ptr<comminute::Module> inner) : inner_(std::move(inner)) {}
  std::string name() const override { return inner_->name(); }
  comminute::ModuleStage stage() const override { return inner_->stage(); }
  void declare_contact_state(comminute::ContactPipeline& c) override {
    inner_->declare_contact_state(c);
  }
  void setup(comminute::Simulation& s) override { inner_->setup(s); }
  void pre_force(comminute::Simulation& s) override { inner_->pre_force(s); }
  void post_force(comminute::Simulation& s) override {
    timed(post_, [&] { inner_->post_force(s); });
  }
  void end_of_step(comminute::Simulation& s) override {
    timed(end_, [&] { inner_->end_of_step(s); });
  }
  void announce_sizes(std::vector<comminute::ParticleSize>& sizes,
                      const comminute::Simulation& s) const override {
    inner_->announce_sizes(sizes, s);
  }
  void reset() { post_ = end_ = 0; }
  // seconds in post_force and end_of_step since the last reset() (the module does its work there)
  double post() const { return post_; }
  double end() const { return end_; }

 private:
  template <class F>
  static void timed(double& into, F f) {
    const double t0 = omp_get_wtime();
    f();
    into += omp_get_wtime() - t0;
  }
  std::unique_ptr<comminute::Module> inner_;
  double post_ = 0, end_ = 0;
};
}  // namespace

int main(int argc, char** argv) {
  using namespace comminute;
  if (argc < 3) {
    fmt::print(stderr, "usage: {} N on|off [warmup=50] [steps=200]\n", argv[0]);
    return 2;
  }
  const long n_target = std::atol(argv[1]);
  const bool on = std::string(argv[2]) == "on";
  const long warm = argc > 3 ? std::atol(argv[3]) : 50;
  const long steps = argc > 4 ? std::atol(argv[4]) : 200;
  Simulation sim;
  sim.materials.add({"ore", 2500, 5e7, 0.3});
  PairInput pi;
  pi.restitution = 0.5;
  pi.friction = 0.3;
  sim.materials.set_pair(0, 0, pi);
  sim.law = ContactLawRegistry::create("hertz_mindlin", CaseFile::parse("").root());
  sim.gravity = {0, 0, 0};
  sim.seed = 5;
  sim.options.sort_every = env_count("SORT_EVERY", sim.options.sort_every, 0);
  const double d = 0.003, a = 0.995 * d;  // 0.5 % overlaps: a pre-stressed, contact-rich bed
  const int side = static_cast<int>(std::lround(std::cbrt(static_cast<double>(n_target))));
  const double L = side * a;
  Rng rng(11);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) {
        ParticleInit p;
        p.x = {(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a};
        p.v = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        p.radius = d / 2;
        p.density = 2500;
        sim.particles.add(p);
      }
  sim.walls.push_back(
      std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{L, L, 2 * L},
                                std::array<bool, 6>{false, false, false, false, false, true}));
  auto platen = std::make_unique<PlaneWall>(Vec3{0, 0, L}, Vec3{0, 0, -1});
  platen->kinematics.velocity = {0, 0, -1.0};
  sim.walls.push_back(std::move(platen));
  const double min_breakable = 0.0015, ratio = 0.3;
  breakage::BreakageModule* module = nullptr;
  TimedModule* timed = nullptr;
  if (on) {
    breakage::TavaresParameters tp;
    tp.size_effect = {0.1, 0.0, 1.0, 1.0};  // J/kg absorbed: weak, breaks at first collisions
    tp.sigma = 0.5;
    tp.damage.gamma = 3.0;
    std::vector<std::optional<breakage::MaterialBreakage>> mats(1);
    mats[0].emplace();
    mats[0]->criterion = std::make_unique<breakage::Tavares>(tp);
    mats[0]->min_breakable_size = min_breakable;
    mats[0]->min_fragment_ratio = ratio;
    mats[0]->fines = breakage::FinesRule::mass;
    breakage::BreakageOptions opt;
    opt.replacement_interval = env_count("REPLACEMENT_INTERVAL", opt.replacement_interval, 1);
    auto m = std::make_unique<breakage::BreakageModule>(std::move(mats), opt);
    module = m.get();
    auto t = std::make_unique<TimedModule>(std::move(m));
    timed = t.get();
    sim.modules.push_back(std::move(t));
  }
  // Same time step both ways: resolves the smallest fragment breakage can make.
  const double r_min = 0.5 * ratio * min_breakable;
  const double g = 5e7 / (2 * 1.3);
  sim.dt = 0.2 * M_PI * r_min * std::sqrt(2500 / g) / (0.1631 * 0.3 + 0.8766);
  sim.setup();
  sim.run(static_cast<std::uint64_t>(warm));
  const std::uint64_t b0 = module ? module->breakages() : 0;
  if (timed) timed->reset();
  double particle_steps = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (long s = 0; s < steps; ++s) {
    particle_steps += static_cast<double>(sim.particles.size());
    sim.step();
  }
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print(
      "breakage={} N0={} N_end={} threads={} warmup={} steps={} seconds={:.3f} "
      "particle_steps_per_s={:.4g} breakages_total={} breakages_in_window={} pending={} "
      "rebuilds={} breakage_seconds(post_force,end_of_step)={:.3f},{:.3f}\n",
      on ? "on" : "off", side * side * side, sim.particles.size(), omp_get_max_threads(), warm,
      steps, sec, particle_steps / sec, module ? module->breakages() : 0,
      module ? module->breakages() - b0 : 0, module ? module->pending() : 0,
      sim.neighbor_rebuilds(), timed ? timed->post() : 0.0, timed ? timed->end() : 0.0);
  return 0;
}
