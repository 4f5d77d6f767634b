#include "comminute/run/progress_reporter.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "comminute/engine/simulation.hpp"

namespace comminute::run {

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string hms(double s) {
  if (!std::isfinite(s)) return "--:--:--";
  const auto t = static_cast<long long>(std::llround(std::max(0.0, s)));
  return fmt::format("{}:{:02d}:{:02d}", t / 3600, (t / 60) % 60, t % 60);
}

std::size_t touching_contacts(const Simulation& sim) {
  std::size_t n = sim.wall_contacts().size();
  for (auto t : sim.pair_state().active) n += t;
  return n;
}

ProgressSample sample_of(const Simulation& sim) {
  return {sim.time, sim.step_count, sim.particles.size(), touching_contacts(sim)};
}

}  // namespace

ProgressReporter::ProgressReporter(double start_time, double end_time, std::FILE* out)
    : ProgressReporter(start_time, end_time, out, ::isatty(::fileno(out)) == 1, steady_seconds) {}

ProgressReporter::ProgressReporter(double start_time, double end_time, std::FILE* out,
                                   bool terminal, Clock clock, double terminal_period,
                                   double plain_period)
    : start_time_(start_time),
      end_time_(end_time),
      out_(out),
      terminal_(terminal),
      clock_(std::move(clock)),
      terminal_period_(terminal_period),
      plain_period_(plain_period),
      wall_start_(clock_()),
      last_print_wall_(wall_start_) {}

void ProgressReporter::update(const Simulation& sim) {
  update(sim.time, sim.step_count, sim.particles.size(), [&] { return touching_contacts(sim); });
}

void ProgressReporter::update(const ProgressSample& s) {
  update(s.time, s.step, s.particles, [&] { return s.contacts; });
}

void ProgressReporter::update(double time, std::uint64_t step, std::size_t particles,
                              const std::function<std::size_t()>& contacts) {
  count_steps(step, particles);
  const double now = clock_();
  if (now - last_print_wall_ < (terminal_ ? terminal_period_ : plain_period_)) return;
  print({time, step, particles, contacts()}, now, false);
}

void ProgressReporter::finish(const Simulation& sim) {
  finish(sample_of(sim));
}

void ProgressReporter::finish(const ProgressSample& s) {
  count_steps(s.step, s.particles);
  print(s, clock_(), true);
}

// Steps since the last call times the current particle count.
void ProgressReporter::count_steps(std::uint64_t step, std::size_t particles) {
  if (have_step_ && step > last_step_) {
    const double n = static_cast<double>(step - last_step_) * static_cast<double>(particles);
    window_particle_steps_ += n;
    total_particle_steps_ += n;
  }
  last_step_ = step;
  have_step_ = true;
}

std::string ProgressReporter::line(const ProgressSample& s, double rate, double eta) const {
  const double span = end_time_ - start_time_;
  const double percent = span > 0 ? 100.0 * (s.time - start_time_) / span : 100.0;
  return fmt::format(
      "t = {:.6g} s of {:.6g} s ({:.1f} %)  ETA {}  {:.3g} particle-steps/s  {} particles  {} "
      "contacts",
      s.time, end_time_, percent, hms(eta), rate, s.particles, s.contacts);
}

void ProgressReporter::print(const ProgressSample& s, double now, bool last) {
  const double window = now - last_print_wall_;
  const double rate = window > 0 ? window_particle_steps_ / window : 0.0;
  // ETA from the average pace of the whole run so far (simulated seconds per wall second).
  const double done = s.time - start_time_, elapsed = now - wall_start_;
  const double eta =
      done > 0 ? elapsed * (end_time_ - s.time) / done : std::numeric_limits<double>::infinity();
  const std::string text = line(s, rate, eta);
  if (terminal_)
    fmt::print(out_, "\r{}\x1b[K{}", text, last ? "\n" : "");
  else
    fmt::print(out_, "{}\n", text);
  std::fflush(out_);
  last_print_wall_ = now;
  window_particle_steps_ = 0;
}

}  // namespace comminute::run
