#pragma once
// Steady-state detection from a mill's power and kinetic-energy series. The series are averaged
// over blocks of fixed length; the mill is at steady state at the end of the first block where
// the means of the last `blocks` blocks each lie within `tolerance` (a fraction) of their common
// mean, for the kinetic energy and, when the walls do work, for the power too (|mean power| <=
// 1e-12 W: walls at rest, the power is not tested). Rule documented in docs/case-file.md
// ([collisions]).
#include <optional>
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"

namespace comminute::analysis {

struct SteadyStateRule {
  double block = 0.1;      // s, length of a block
  int blocks = 4;          // consecutive blocks compared (>= 2)
  double tolerance = 0.1;  // fraction of the mean each block mean may differ by
};

class SteadyStateDetector {
 public:
  explicit SteadyStateDetector(SteadyStateRule rule = {}) : rule_(rule) {}
  // One sample at time t (s): the walls' cumulative work on the particles (J) and the kinetic
  // energy now (J). Returns the start of the steady state once it is detected (then always).
  std::optional<double> add(double t, double wall_work, double kinetic);
  std::optional<double> detected() const;
  const std::vector<double>& block_power() const { return power_; }      // W
  const std::vector<double>& block_kinetic() const { return kinetic_; }  // J

  void save(Archive& a, const std::string& prefix) const;
  void load(const Archive& a, const std::string& prefix);

 private:
  bool settled(const std::vector<double>& means, bool skip_when_zero) const;

  SteadyStateRule rule_;
  bool started_ = false;
  double block_start_ = 0, work_start_ = 0, kinetic_sum_ = 0, samples_ = 0;
  double detected_ = -1;  // s; < 0 while not detected
  std::vector<double> power_, kinetic_;
};

}  // namespace comminute::analysis
