#include "comminute/io/output/output_module.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "comminute/core/error.hpp"
#include "comminute/core/parallel.hpp"
#include "comminute/engine/simulation.hpp"
#include "comminute/io/output/checkpoint.hpp"

namespace comminute::io {

// A time-based output is due at the step nearest to k * interval (within half a step).
bool OutputModule::Schedule::due(double time, std::uint64_t step, double dt) const {
  if (step == last_step) return false;
  if (cadence.steps > 0) return step % cadence.steps == 0;
  if (cadence.interval > 0)
    return time >= static_cast<double>(next_index) * cadence.interval - 0.5 * dt;
  return false;
}

void OutputModule::Schedule::done(double time, std::uint64_t step, double dt) {
  last_step = step;
  if (cadence.interval > 0)  // skip outputs missed when the interval is shorter than a step
    next_index = static_cast<std::uint64_t>(std::floor((time + 0.5 * dt) / cadence.interval)) + 1;
}

OutputModule::OutputModule(OutputOptions options, double end_time) : options_(std::move(options)) {
  particles_.cadence = options_.particles_cadence;
  if (!particles_.cadence.is_set()) particles_.cadence.interval = end_time / 100;
  timeseries_.cadence = options_.timeseries_cadence;
  if (!timeseries_.cadence.is_set()) timeseries_.cadence.interval = end_time / 1000;
  checkpoint_.cadence = options_.checkpoint_cadence;
  // A checkpoint at the start would only repeat the case file: the first one is one period in.
  checkpoint_.next_index = 1;
  if (!options_.particles) particles_.cadence = {};
}

// Field names can only be checked once the modules have registered their fields (setup).
void OutputModule::check_fields(const ParticleStore& p) const {
  if (!options_.fields) return;
  for (const auto& name : *options_.fields)
    if (!p.has_field(name))
      throw InputError(
          options_.case_file.string(), "output.fields", options_.fields_line,
          fmt::format("'{}' is not a per-particle field of this case (known: {})", name,
                      p.field_names().empty()
                          ? std::string("none")
                          : fmt::format("{}", fmt::join(p.field_names(), ", "))));
}

void OutputModule::start(Simulation& sim) {
  if (started_) return;
  check_fields(sim.particles);
  started_ = true;
  std::vector<std::string> names;
  for (const auto& w : sim.walls) names.push_back(w->name);
  csv_ = std::make_unique<TimeSeriesWriter>(timeseries_path(), names);
  vtk_ = std::make_unique<VtkWriter>(options_.directory, options_.fields);
  if (resume_time_) {
    csv_->resume(*resume_time_);
    vtk_->resume(*resume_time_);
    return;
  }
  std::filesystem::create_directories(options_.directory);
  csv_->start_fresh();
  vtk_->start_fresh();
  // The initial state, before the first step.
  if (options_.particles) {
    write_snapshot(sim);
    particles_.done(sim.time, sim.step_count, sim.dt);
  }
  write_row(sim);
  timeseries_.done(sim.time, sim.step_count, sim.dt);
}

void OutputModule::end_of_step(Simulation& sim) {
  if (!started_) start(sim);
  const double t = sim.time, dt = sim.dt;
  const std::uint64_t s = sim.step_count;
  if (particles_.due(t, s, dt)) {
    write_snapshot(sim);
    particles_.done(t, s, dt);
  }
  if (timeseries_.due(t, s, dt)) {
    write_row(sim);
    timeseries_.done(t, s, dt);
  }
  if (checkpoint_.due(t, s, dt)) write_checkpoint(sim);
}

void OutputModule::finish(Simulation& sim) {
  if (!started_) start(sim);
  const double t = sim.time, dt = sim.dt;
  const std::uint64_t s = sim.step_count;
  if (options_.particles && particles_.last_step != s) {
    write_snapshot(sim);
    particles_.done(t, s, dt);
  }
  if (timeseries_.last_step != s) {
    write_row(sim);
    timeseries_.done(t, s, dt);
  }
  if (checkpoint_.last_step != s) write_checkpoint(sim);
}

void OutputModule::write_checkpoint(Simulation& sim) {
  // The schedule is advanced first: the saved state says "checkpoint written at this step".
  checkpoint_.done(sim.time, sim.step_count, sim.dt);
  Archive a;
  sim.save(a);
  CheckpointInfo info;
  info.time = sim.time;
  info.step = sim.step_count;
  info.threads = max_threads();
  io::write_checkpoint(checkpoint_path(), a, info);
}

void OutputModule::write_snapshot(Simulation& sim) {
  vtk_->write_particles(sim.particles, sim.time, sim.step_count);
  if (options_.walls && !sim.walls.empty()) {
    if (extent_ == 0) extent_ = wall_extent(sim);
    vtk_->write_walls(sim.walls, sim.time, sim.step_count, extent_);
  }
}

void OutputModule::write_row(Simulation& sim) {
  csv_->append(sim.observe(), sim.walls);
}

// Half-size of drawn infinite planes: the largest edge of the box around the particles and the
// finite walls, so a plane spans the scene; 1 m when there is nothing yet to measure.
double OutputModule::wall_extent(const Simulation& sim) const {
  if (options_.wall_extent > 0) return options_.wall_extent;
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo{inf, inf, inf}, hi{-inf, -inf, -inf};
  auto grow = [&](const Vec3& p, double r) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k] - r);
      hi[k] = std::max(hi[k], p[k] + r);
    }
  };
  const auto& p = sim.particles;
  for (std::size_t i = 0; i < p.size(); ++i) grow(p.x[i], p.radius[i]);
  for (const auto& w : sim.walls)
    for (const auto& v : w->surface(0).vertices) grow(v, 0);
  const double edge = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  return std::isfinite(edge) && edge > 0 ? edge : 1.0;
}

void OutputModule::save(Archive& a) const {
  const std::vector<std::uint64_t> state = {particles_.next_index,  particles_.last_step,
                                            timeseries_.next_index, timeseries_.last_step,
                                            checkpoint_.next_index, checkpoint_.last_step};
  a.put("output/schedule", state);
  a.put("output/wall_extent", std::vector<double>{extent_});
}

void OutputModule::load(const Archive& a) {
  const auto s = a.get<std::uint64_t>("output/schedule");
  if (s.size() != 6) throw Error("checkpoint entry 'output/schedule' has a wrong size");
  particles_.next_index = s[0];
  particles_.last_step = s[1];
  timeseries_.next_index = s[2];
  timeseries_.last_step = s[3];
  checkpoint_.next_index = s[4];
  checkpoint_.last_step = s[5];
  extent_ = a.get<double>("output/wall_extent").at(0);
  resume_time_ = a.get<double>("sim/time").at(0);
  started_ = false;
}

}  // namespace comminute::io
