#pragma once
// What `comminute pbm` and `comminute calibrate` do with a case file, shared with `comminute
// couple` (its population-balance stage): the same reading, the same files, the same plots.
#include <filesystem>

#include "comminute/core/case_table.hpp"

namespace comminute::app {

// `comminute pbm <file>`: solves the population balance, writes its outputs; returns the exit code.
int solve_pbm_case(const std::filesystem::path& file, bool no_plots);
// `comminute calibrate <file>`: fits its free parameters, writes the fit and the best solution.
int calibrate_pbm_case(const std::filesystem::path& file, bool no_plots);
// The same for a case file already loaded (`comminute calibrate` loads it to choose the mode).
int calibrate_pbm_case(const CaseFile& cf, bool no_plots);

}  // namespace comminute::app
