#include "comminute/analysis/steady_state.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "comminute/core/error.hpp"

namespace comminute::analysis {

std::optional<double> SteadyStateDetector::add(double t, double wall_work, double kinetic) {
  if (detected_ >= 0) return detected_;
  if (!started_) {
    started_ = true;
    block_start_ = t;
    work_start_ = wall_work;
    kinetic_sum_ = 0;
    samples_ = 0;
  }
  kinetic_sum_ += kinetic;
  samples_ += 1;
  if (t - block_start_ < rule_.block * (1 - 1e-9)) return std::nullopt;
  power_.push_back((wall_work - work_start_) / (t - block_start_));
  kinetic_.push_back(kinetic_sum_ / samples_);
  block_start_ = t;
  work_start_ = wall_work;
  kinetic_sum_ = 0;
  samples_ = 0;
  if (settled(kinetic_, false) && settled(power_, true)) detected_ = t;
  return detected();
}

std::optional<double> SteadyStateDetector::detected() const {
  if (detected_ < 0) return std::nullopt;
  return detected_;
}

bool SteadyStateDetector::settled(const std::vector<double>& means, bool skip_when_zero) const {
  const auto n = static_cast<std::size_t>(rule_.blocks);
  if (means.size() < n) return false;
  const auto first = means.end() - static_cast<long>(n);
  const double mean = std::accumulate(first, means.end(), 0.0) / static_cast<double>(n);
  if (skip_when_zero && std::abs(mean) <= 1e-12) return true;
  for (auto it = first; it != means.end(); ++it)
    if (std::abs(*it - mean) > rule_.tolerance * std::abs(mean)) return false;
  return true;
}

void SteadyStateDetector::save(Archive& a, const std::string& prefix) const {
  a.put(prefix + "state", std::vector<double>{started_ ? 1.0 : 0.0, block_start_, work_start_,
                                              kinetic_sum_, samples_, detected_});
  a.put(prefix + "block_power", power_);
  a.put(prefix + "block_kinetic", kinetic_);
}

void SteadyStateDetector::load(const Archive& a, const std::string& prefix) {
  const auto s = a.get<double>(prefix + "state");
  auto power = a.get<double>(prefix + "block_power");
  auto kinetic = a.get<double>(prefix + "block_kinetic");
  bool ok = s.size() == 6 && power.size() == kinetic.size();
  for (double v : s) ok = ok && std::isfinite(v);
  if (!ok)
    throw Error(
        fmt::format("checkpoint entries '{}state', '{}block_power', '{}block_kinetic' do "
                    "not hold a steady-state detector",
                    prefix, prefix, prefix));
  started_ = s[0] != 0;
  block_start_ = s[1];
  work_start_ = s[2];
  kinetic_sum_ = s[3];
  samples_ = s[4];
  detected_ = s[5];
  power_ = std::move(power);
  kinetic_ = std::move(kinetic);
}

}  // namespace comminute::analysis
