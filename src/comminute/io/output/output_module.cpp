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
#include "comminute/io/output/dataset_writer.hpp"

namespace comminute::io {

OutputModule::OutputModule(OutputOptions options, double end_time) : options_(std::move(options)) {
  Cadence particles = options_.particles_cadence;
  if (!particles.is_set()) particles.interval = end_time / 100;
  if (!options_.particles) particles = {};
  particles_ = OutputSchedule(particles);
  Cadence timeseries = options_.timeseries_cadence;
  if (!timeseries.is_set()) timeseries.interval = end_time / 1000;
  timeseries_ = OutputSchedule(timeseries);
  // A checkpoint at the start would only repeat the case file: the first one is one period in.
  checkpoint_ = OutputSchedule(options_.checkpoint_cadence, 1);
  timeseries_cadence_ = timeseries;
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
  for (const auto& m : sim.modules)
    if (SeriesSource* s = m->series_source()) {
      const Cadence c = s->output_cadence();
      Source src{m->name(), s, OutputSchedule(c.is_set() ? c : timeseries_cadence_)};
      if (const auto it = loaded_sources_.find(src.name); it != loaded_sources_.end())
        src.schedule.set_state(it->second.at(0), it->second.at(1));
      sources_.push_back(std::move(src));
    }
  if (resume_time_) {
    csv_->resume(*resume_time_);
    vtk_->resume(*resume_time_);
    // The tables as of the checkpoint: drops rows a killed run wrote after it.
    for (const auto& s : sources_) write_tables(s, sim);
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
  for (auto& s : sources_) sample(s, sim);
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
  for (auto& src : sources_)
    if (src.schedule.due(t, s, dt)) sample(src, sim);
  if (checkpoint_.due(t, s, dt)) write_checkpoint(sim);
}

void OutputModule::finish(Simulation& sim) {
  if (!started_) start(sim);
  const double t = sim.time, dt = sim.dt;
  const std::uint64_t s = sim.step_count;
  if (options_.particles && !particles_.written_at(s)) {
    write_snapshot(sim);
    particles_.done(t, s, dt);
  }
  if (!timeseries_.written_at(s)) {
    write_row(sim);
    timeseries_.done(t, s, dt);
  }
  for (auto& src : sources_)
    if (!src.schedule.written_at(s)) sample(src, sim);
  if (!checkpoint_.written_at(s)) write_checkpoint(sim);
}

void OutputModule::write_checkpoint(Simulation& sim) {
  // The schedule is advanced first: the saved state says "checkpoint written at this step".
  checkpoint_.done(sim.time, sim.step_count, sim.dt);
  Archive a;
  sim.save(a);
  put_case_fingerprint(a, options_.case_fingerprint);
  CheckpointInfo info;
  info.time = sim.time;
  info.step = sim.step_count;
  info.threads = max_threads();
  io::write_checkpoint(checkpoint_path(), a, info);
}

void OutputModule::write_snapshot(Simulation& sim) {
  vtk_->write_particles(sim.particles, sim.time, sim.step_count, options_.coarse_scale);
  if (options_.walls && !sim.walls.empty()) {
    if (extent_ == 0) extent_ = wall_extent(sim);
    vtk_->write_walls(sim.walls, sim.time, sim.step_count, extent_);
  }
}

void OutputModule::write_row(Simulation& sim) {
  csv_->append(sim.observe(), sim.walls);
}

void OutputModule::sample(Source& s, const Simulation& sim) {
  s.source->sample(sim);
  write_tables(s, sim);
  s.schedule.done(sim.time, sim.step_count, sim.dt);
}

void OutputModule::write_tables(const Source& s, const Simulation& sim) const {
  for (const Table& t : s.source->tables(sim)) t.write(options_.directory);
  for (const Dataset& d : s.source->datasets(sim)) write_dataset(options_.directory, d, sim.time);
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
  std::vector<std::uint64_t> state;
  for (const auto* sc : {&particles_, &timeseries_, &checkpoint_})
    for (std::uint64_t v : sc->state()) state.push_back(v);
  a.put("output/schedule", state);
  a.put("output/wall_extent", std::vector<double>{extent_});
  for (const auto& s : sources_) a.put("output/series/" + s.name, s.schedule.state());
}

void OutputModule::load(const Archive& a) {
  const auto s = a.get<std::uint64_t>("output/schedule");
  if (s.size() != 6) throw Error("checkpoint entry 'output/schedule' has a wrong size");
  particles_.set_state(s[0], s[1]);
  timeseries_.set_state(s[2], s[3]);
  checkpoint_.set_state(s[4], s[5]);
  extent_ = a.get_value<double>("output/wall_extent");
  const std::string prefix = "output/series/";
  loaded_sources_.clear();
  for (const auto& [name, bytes] : a.entries())
    if (name.starts_with(prefix)) {
      auto v = a.get<std::uint64_t>(name);
      if (v.size() != 2) throw Error("checkpoint entry '" + name + "' has a wrong size");
      loaded_sources_[name.substr(prefix.size())] = std::move(v);
    }
  resume_time_ = a.get_value<double>("sim/time");
  sources_.clear();
  started_ = false;
}

}  // namespace comminute::io
