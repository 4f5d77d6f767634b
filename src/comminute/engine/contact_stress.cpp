#include "comminute/engine/contact_stress.hpp"

#include <fmt/format.h>

#include "comminute/core/error.hpp"

namespace comminute {

void ContactStress::set_threshold(double fn) {
  if (threshold_set_ && fn != threshold_)
    throw Error(
        fmt::format("two modules ask for different load-bearing force thresholds ({} N and {} N)",
                    threshold_, fn));
  threshold_ = fn;
  threshold_set_ = true;
}

void ContactStress::begin(std::size_t n) {
  starts.clear();
  if (!armed_) return;
  moment.assign(n, SymTensor{});
  load_bearing.assign(n, 0);
  contacts.clear();
}

}  // namespace comminute
