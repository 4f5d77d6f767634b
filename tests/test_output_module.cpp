// The output module on a real run: series written on their cadence, a stop by SIGINT that
// leaves a checkpoint, and a restart from it that reproduces the uninterrupted run bit for bit
// (same thread count): final state, time-series CSV, collections and snapshot files.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <sstream>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/core/rng.hpp"
#include "comminute/engine/series_source.hpp"
#include "comminute/geometry/box_wall.hpp"
#include "comminute/geometry/plane_wall.hpp"
#include "comminute/io/output/checkpoint.hpp"
#include "comminute/io/output/output_module.hpp"
#include "comminute/run/run_loop.hpp"
#include "comminute/run/stop_request.hpp"
#include "dem_fixture.hpp"
#include "temp_dir.hpp"

using namespace comminute;
using namespace comminute::testing;

namespace {

constexpr double end_time = 0.03;  // s: 1500 steps of 2e-5 s

// Sends SIGINT to the process at the end of a given step (a user pressing Ctrl-C).
class InterruptAt : public Module {
 public:
  explicit InterruptAt(std::uint64_t step) : step_(step) {}
  std::string name() const override { return "interrupt_at"; }
  void end_of_step(Simulation& sim) override {
    if (sim.step_count == step_) std::raise(SIGINT);
  }

 private:
  std::uint64_t step_;
};

// A module that offers a table: one row (time, step) per sample, every 400 steps. Rows are
// checkpointed, so a continued run has them all.
class CountingSource : public Module, public SeriesSource {
 public:
  std::string name() const override { return "counting"; }
  SeriesSource* series_source() override { return this; }
  Cadence output_cadence() const override { return {0, 400}; }
  void sample(const Simulation& sim) override {
    times_.push_back(sim.time);
    steps_.push_back(sim.step_count);
  }
  std::vector<Table> tables(const Simulation&) const override {
    Table t("counting", {{"time", "s"}, {"step", "-"}});
    for (std::size_t k = 0; k < times_.size(); ++k) t.add_row({times_[k], steps_[k]});
    return {t};
  }
  void save(Archive& a) const override {
    a.put("counting/times", times_);
    a.put("counting/steps", steps_);
  }
  void load(const Archive& a) override {
    times_ = a.get<double>("counting/times");
    steps_ = a.get<std::uint64_t>("counting/steps");
  }

 private:
  std::vector<double> times_;
  std::vector<std::uint64_t> steps_;
};

struct DemRun {
  std::unique_ptr<Simulation> sim;
  io::OutputModule* output = nullptr;
};

// 48 spheres with random velocities dropping into an open box, a lid plane coming down:
// contacts with walls and each other, sliding friction, a moving wall and a particle field.
DemRun make_run(const std::filesystem::path& dir, std::uint64_t interrupt_step = 0) {
  DemSetup s;
  s.gravity = {0, 0, -9.81};
  s.friction = 0.4;
  s.restitution = 0.6;
  DemRun run;
  run.sim = make_simulation(s);
  Simulation& sim = *run.sim;
  std::array<bool, 6> open{};
  open[5] = true;  // no top face
  sim.walls.push_back(std::make_unique<BoxWall>(Vec3{0, 0, 0}, Vec3{0.04, 0.04, 0.1}, open));
  sim.walls.back()->name = "box";
  sim.walls.push_back(std::make_unique<PlaneWall>(Vec3{0, 0, 0.027}, Vec3{0, 0, -1}));
  sim.walls.back()->name = "lid";
  sim.walls.back()->kinematics.velocity = {0, 0, -0.2};
  Rng rng(77);
  const double r = 0.004;
  for (int k = 0; k < 48; ++k) {
    const Vec3 x{0.006 + 0.009 * (k % 4), 0.006 + 0.009 * ((k / 4) % 4),
                 r + 1e-4 + 0.0085 * (k / 16)};
    add_sphere(sim, x, r * rng.uniform(0.9, 1.0), {rng.normal(0, 0.3), rng.normal(0, 0.3), 0});
  }
  auto& damage = sim.particles.field(sim.particles.add_field("damage", 0.0));
  for (auto& d : damage) d = rng.uniform();
  sim.dt = 2e-5;
  io::OutputOptions o;
  o.directory = dir;
  o.particles_cadence.interval = 0.005;
  o.timeseries_cadence.steps = 25;
  o.checkpoint_cadence.interval = 0.01;
  sim.modules.push_back(std::make_unique<CountingSource>());
  auto out = std::make_unique<io::OutputModule>(o, end_time);
  run.output = out.get();
  sim.modules.push_back(std::move(out));
  if (interrupt_step) sim.modules.push_back(std::make_unique<InterruptAt>(interrupt_step));
  return run;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::size_t count_lines(const std::string& s) {
  return std::count(s.begin(), s.end(), '\n');
}

}  // namespace

TEST(OutputModule, WritesEachSeriesOnItsCadence) {
  const TestDir dir;
  DemRun run = make_run(dir.path());
  run.sim->setup();
  ASSERT_EQ(run::run_until(*run.sim, end_time, run.output, nullptr, nullptr), 0);
  EXPECT_EQ(run.sim->step_count, 1500u);
  // Rows at step 0 and every 25 steps: 1 + 1500/25 = 61, plus the header.
  EXPECT_EQ(count_lines(slurp(dir / "timeseries.csv")), 62u);
  // A module's table: a row at the start, every 400 steps and a final one at the end time.
  {
    std::istringstream t(slurp(dir / "counting.csv"));
    std::string line;
    std::getline(t, line);
    EXPECT_EQ(line, "time [s],step [-]");
    std::vector<std::string> steps;
    std::string last_time;
    while (std::getline(t, line)) {
      last_time = line.substr(0, line.find(','));
      steps.push_back(line.substr(line.find(',') + 1));
    }
    EXPECT_EQ(steps, (std::vector<std::string>{"0", "400", "800", "1200", "1500"}));
    EXPECT_EQ(last_time, fmt::format("{}", run.sim->time));
  }
  // Snapshots at t = 0, 0.005, ..., 0.03: 7 entries in each collection.
  const std::string pvd = slurp(dir / "particles.pvd");
  EXPECT_EQ(count_lines(pvd), 7u + 5u) << pvd;  // 5 lines of XML around the entries
  EXPECT_NE(pvd.find("file=\"particles/particles_0000000250.vtp\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("file=\"particles/particles_0000001500.vtp\""), std::string::npos) << pvd;
  EXPECT_EQ(count_lines(slurp(dir / "walls.pvd")), 12u);
  // The last checkpoint is the final state.
  const auto info = io::read_checkpoint_info(dir / "checkpoint.h5");
  EXPECT_EQ(info.step, 1500u);
  EXPECT_EQ(info.time, run.sim->time);
  // Something happened: the lid came down onto the spheres (a force in some row).
  std::istringstream csv(slurp(dir / "timeseries.csv"));
  std::string line;
  std::getline(csv, line);
  const auto col = [&] {
    std::istringstream h(line);
    std::size_t k = 0;
    for (std::string c; std::getline(h, c, ','); ++k)
      if (c == "lid_Fz [N]") return k;
    return std::size_t(-1);
  }();
  ASSERT_NE(col, std::size_t(-1)) << line;
  double max_lid = 0;
  while (std::getline(csv, line)) {
    std::istringstream r(line);
    std::string c;
    for (std::size_t k = 0; k <= col; ++k) std::getline(r, c, ',');
    max_lid = std::max(max_lid, std::abs(std::stod(c)));
  }
  EXPECT_GT(max_lid, 0.0);
}

TEST(OutputModule, InterruptAndRestartReproduceTheUninterruptedRun) {
  const TestDir dir;
  // A: straight through.
  DemRun a = make_run(dir / "a");
  a.sim->setup();
  ASSERT_EQ(run::run_until(*a.sim, end_time, a.output, nullptr, nullptr), 0);
  Archive final_a;
  a.sim->save(final_a);

  // B: Ctrl-C at step 1037 (between all output times): checkpoint and exit code 130.
  {
    DemRun b = make_run(dir / "b", 1037);
    b.sim->setup();
    run::StopRequest stop;
    std::FILE* log = std::tmpfile();
    EXPECT_EQ(run::run_until(*b.sim, end_time, b.output, nullptr, &stop, log), 130);
    std::rewind(log);
    char msg[256] = {};
    ASSERT_NE(std::fgets(msg, sizeof msg, log), nullptr);
    std::fclose(log);
    EXPECT_NE(std::string(msg).find("stopped by SIGINT"), std::string::npos) << msg;
    EXPECT_EQ(b.sim->step_count, 1037u);
  }
  EXPECT_EQ(io::read_checkpoint_info(dir / "b" / "checkpoint.h5").step, 1037u);
  // The killed run's CSV ends at the last row before the stop (step 1025).
  const std::string partial = slurp(dir / "b" / "timeseries.csv");
  EXPECT_EQ(count_lines(partial), 1u + 1u + 1025u / 25u);

  // B continued: same set-up, state from the checkpoint.
  DemRun c = make_run(dir / "b");
  io::CheckpointInfo info;
  c.sim->load(io::read_checkpoint(dir / "b" / "checkpoint.h5", &info));
  EXPECT_EQ(info.threads, max_threads());
  ASSERT_EQ(run::run_until(*c.sim, end_time, c.output, nullptr, nullptr), 0);
  Archive final_c;
  c.sim->save(final_c);

  EXPECT_EQ(c.sim->step_count, 1500u);
  ASSERT_EQ(final_a.entries().size(), final_c.entries().size());
  for (const auto& [name, bytes] : final_a.entries())
    EXPECT_TRUE(final_c.entries().at(name) == bytes) << "state entry '" << name << "' differs";
  for (const char* f : {"timeseries.csv", "counting.csv", "particles.pvd", "walls.pvd",
                        "particles/particles_0000001500.vtp", "walls/walls_0000001500.vtp",
                        "particles/particles_0000001250.vtp"})
    EXPECT_TRUE(slurp(dir / "a" / f) == slurp(dir / "b" / f)) << f << " differs";
}

TEST(OutputModule, UnknownFieldIsAnInputErrorAtStart) {
  const TestDir dir;
  DemRun run = make_run(dir.path());
  io::OutputOptions o;
  o.directory = dir.path();
  o.fields = std::vector<std::string>{"damgae"};
  o.case_file = "case.toml";
  o.fields_line = 12;
  io::OutputModule out(o, end_time);
  run.sim->setup();
  try {
    out.start(*run.sim);
    FAIL() << "unknown field accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "output.fields");
    EXPECT_EQ(e.line(), 12);
    EXPECT_NE(std::string(e.what()).find("'damgae'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("known: damage"), std::string::npos) << e.what();
  }
}
