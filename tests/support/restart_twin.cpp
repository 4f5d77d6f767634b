#include "restart_twin.hpp"

#include "comminute/core/archive.hpp"

namespace comminute::testing {

void run_restart_twin(Simulation& full, Simulation& resumed, std::uint64_t before,
                      std::uint64_t after, const std::function<void()>& at_save) {
  full.run(before);
  Archive checkpoint;
  full.save(checkpoint);
  if (at_save) at_save();
  full.run(after);
  resumed.load(checkpoint);
  resumed.run(after);
}

}  // namespace comminute::testing
