#pragma once
// The two runs of a restart test: one run checkpointed part-way and continued, and a fresh
// simulation that loads that checkpoint and takes the same steps. A test then compares the two
// (bit for bit: restarts must reproduce the uninterrupted run at the same thread count).
#include <cstdint>
#include <functional>

#include "comminute/engine/simulation.hpp"

namespace comminute::testing {

// `full` (set up, or set up by its first run) runs `before` steps, is saved into a checkpoint and
// runs `after` more; `resumed`, made like `full`, loads the checkpoint and runs the same `after`
// steps. `at_save`, when given, is called right after the save (to record what the test compares
// later, e.g. the rebuilds or breakages up to the checkpoint).
void run_restart_twin(Simulation& full, Simulation& resumed, std::uint64_t before,
                      std::uint64_t after, const std::function<void()>& at_save = {});

}  // namespace comminute::testing
