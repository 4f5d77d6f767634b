#pragma once
// The progress line of a run, on stderr:
//   t = 0.1234 s of 0.5 s (24.7 %)  ETA 0:01:23  2.13e+06 particle-steps/s  5000 particles  12000
//   contacts
// On a terminal the line is refreshed in place (\r) about twice a second; otherwise (a log file,
// a pipe) a plain line is printed at most every `plain_period` seconds.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

namespace comminute {
class Simulation;
}

namespace comminute::run {

struct ProgressSample {
  double time = 0;  // s, simulated
  std::uint64_t step = 0;
  std::size_t particles = 0;
  std::size_t contacts = 0;  // particle–particle plus particle–wall contacts touching now
};

class ProgressReporter {
 public:
  using Clock = std::function<double()>;  // wall-clock seconds, monotonic

  // Reports the run from start_time to end_time (s) on `out` (a terminal or not, detected).
  ProgressReporter(double start_time, double end_time, std::FILE* out = stderr);
  // Full control (tests): terminal mode or not, the clock, and the two refresh periods (s).
  ProgressReporter(double start_time, double end_time, std::FILE* out, bool terminal, Clock clock,
                   double terminal_period = 0.5, double plain_period = 5.0);

  // Call after every step: cheap unless a line is due (then it counts the contacts).
  void update(const Simulation& sim);
  // Same with the numbers given; `contacts` is called only when a line is printed.
  void update(const ProgressSample& s);
  void update(double time, std::uint64_t step, std::size_t particles,
              const std::function<std::size_t()>& contacts);
  // Prints the last line (and ends the terminal line).
  void finish(const Simulation& sim);
  void finish(const ProgressSample& s);

  // Particle-steps since construction (for the run's summary line).
  double total_particle_steps() const { return total_particle_steps_; }
  // Wall-clock seconds since construction.
  double elapsed() const { return clock_() - wall_start_; }

  // The text of one line (no line ending), for a rate in particle-steps per second.
  std::string line(const ProgressSample& s, double rate, double eta_seconds) const;

 private:
  void count_steps(std::uint64_t step, std::size_t particles);
  void print(const ProgressSample& s, double now, bool last);

  double start_time_, end_time_;
  std::FILE* out_;
  bool terminal_;
  Clock clock_;
  double terminal_period_, plain_period_;
  double wall_start_;
  double last_print_wall_;
  double window_particle_steps_ = 0;  // since the last printed line
  double total_particle_steps_ = 0;
  std::uint64_t last_step_ = 0;
  bool have_step_ = false;
};

}  // namespace comminute::run
