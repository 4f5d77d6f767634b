#pragma once
// The split of a step's pair list between the threads of the pair force loop.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace comminute {

// Splits the pairs [0, n) into nt ranges of about equal cost, a touching pair (active[k] = 1)
// costing 7 distance checks and another pair 1 (the contact law costs several times a distance
// check). The range of thread t is [at[t], at[t + 1]): at[t] is one past the first pair where the
// running cost reaches t / nt of the total. `at` is reused from step to step.
void balanced_pair_split(const std::uint8_t* active, std::size_t n, int nt,
                         std::vector<std::size_t>& at);

}  // namespace comminute
