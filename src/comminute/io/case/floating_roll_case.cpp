#include "comminute/io/case/floating_roll_case.hpp"

#include <string>

namespace comminute::io {

std::optional<WallControlSpec> floating_roll_control(const CaseTable& t, std::size_t index,
                                                     const Wall& w) {
  const auto f = t.optional_table("floating");
  if (!f || t.string("type") != "hpgr" || w.name.size() < 6 ||
      w.name.compare(w.name.size() - 6, 6, "_roll2") != 0)
    return std::nullopt;
  WallControlSpec s;
  s.mode = WallControlSpec::Mode::floating;
  s.wall = index;
  s.name = w.name;
  s.direction = {-1, 0, 0};  // roll 2 (at +x) towards roll 1, along the line of centres
  const double gap = t.number("gap", Limits::positive());
  const bool has_force = f->has("force"), has_specific = f->has("specific_force");
  if (has_force == has_specific)
    f->fail({}, "a floating roll needs exactly one of 'force' (N) or 'specific_force' (N/m²)");
  // specific pressing force as quoted for roll presses: F / (D W), N/m² (N/mm² × 1e6)
  s.push = has_force ? f->number("force", Limits::non_negative())
                     : f->number("specific_force", Limits::non_negative()) *
                           t.number("diameter", Limits::positive()) *
                           t.number("width", Limits::positive());
  s.mass = f->number("mass", Limits::positive());
  s.damping = f->number("damping", Limits::non_negative(), 0.0);
  const double min_gap = f->number("min_gap", Limits::between(0.0, gap), gap);
  s.max_travel = gap - min_gap;
  s.gap = gap;
  return s;
}

}  // namespace comminute::io
