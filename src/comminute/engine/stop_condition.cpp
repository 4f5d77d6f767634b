#include "comminute/engine/stop_condition.hpp"

#include <fmt/format.h>

#include <cmath>

#include "comminute/core/error.hpp"
#include "comminute/engine/simulation.hpp"

namespace comminute {

StopConditionModule::StopConditionModule(std::vector<StopConditionSpec> conditions)
    : conditions_(std::move(conditions)) {}

double StopConditionModule::quantity(const Simulation& sim, std::size_t k) const {
  const StopConditionSpec& c = conditions_[k];
  const Vec3& force = sim.walls.at(c.wall)->force;
  const double f = norm2(c.direction) > 0 ? -dot(force, c.direction) : norm(force);
  return c.area > 0 ? f / c.area : f;
}

void StopConditionModule::end_of_step(Simulation& sim) {
  if (reached_) return;
  for (std::size_t k = 0; k < conditions_.size(); ++k) {
    const StopConditionSpec& c = conditions_[k];
    if (sim.time < c.after) continue;
    const double q = quantity(sim, k);
    if (c.above ? q >= c.value : q <= c.value) {
      reached_ = StopReached{static_cast<std::uint32_t>(k), 0, sim.step_count, sim.time, q};
      return;
    }
  }
}

std::string StopConditionModule::describe(const Simulation& sim) const {
  if (!reached_) return {};
  const StopConditionSpec& c = conditions_.at(reached_->condition);
  const char* unit = c.area > 0 ? "Pa" : "N";
  const Vec3& n = c.direction;
  const std::string along =
      norm2(n) > 0 ? fmt::format(" along [{:.6g}, {:.6g}, {:.6g}]", n.x, n.y, n.z) : "";
  return fmt::format("{}: wall '{}' {}{} = {:.6g} {} {} {:.6g} {} at t = {:.9g} s (step {})",
                     c.label, sim.walls.at(c.wall)->name, c.area > 0 ? "stress" : "force", along,
                     reached_->quantity, unit, c.above ? ">=" : "<=", c.value, unit, reached_->time,
                     reached_->step);
}

std::vector<Table> StopConditionModule::tables(const Simulation& sim) const {
  Table t("stop", {{"time", "s"},
                   {"step", "-"},
                   {"condition", "-"},
                   {"wall", "-"},
                   {"quantity", "N or Pa"},
                   {"value", "N or Pa"}});
  if (reached_) {
    const StopConditionSpec& c = conditions_.at(reached_->condition);
    t.add_row({reached_->time, reached_->step, c.label, sim.walls.at(c.wall)->name,
               reached_->quantity, c.value});
  }
  return {t};
}

void StopConditionModule::save(Archive& a) const {
  std::vector<StopReached> r;
  if (reached_) r.push_back(*reached_);
  a.put("stop/reached", r);
}

void StopConditionModule::load(const Archive& a) {
  const auto r = a.get<StopReached>("stop/reached");
  if (r.size() > 1 || (r.size() == 1 && r[0].condition >= conditions_.size()))
    throw Error("checkpoint entry 'stop/reached' does not name one of the case's conditions");
  reached_.reset();
  if (!r.empty()) reached_ = r[0];
}

const StopConditionModule* find_stop_conditions(const Simulation& sim) {
  for (const auto& m : sim.modules)
    if (const auto* s = dynamic_cast<const StopConditionModule*>(m.get())) return s;
  return nullptr;
}

}  // namespace comminute
