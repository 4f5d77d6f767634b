#pragma once
// Builds a calibration problem from a case file: a pbm case plus
//   [calibration]              starts, seed, threads, tolerances
//   [[calibration.parameter]]  key (any numeric key of the case, e.g. "breakage.q"), min, max,
//                              scale = "auto" | "log" | "linear"
//   [[calibration.data]]       file (CSV: size_m, cumulative_passing), time (s), basis, weight,
//                              case (optional: another pbm case sharing the free parameters)
// The objective is Σ weight · Σ_sizes (simulated − measured cumulative passing)². Each
// evaluation sets the free keys in a copy of the parsed case and rebuilds the model through the
// same validating reader as `comminute pbm`, so a trial value the model rejects (ν < 2, …) is an
// infinite error rather than a wrong model. Every key: docs/pbm.md.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "comminute/calibrate/multistart.hpp"
#include "comminute/calibrate/parameter_space.hpp"
#include "comminute/core/case_table.hpp"

namespace comminute::io {

struct FitPoint {
  std::size_t dataset;  // index of the [[calibration.data]] entry
  double time, size, measured, simulated;
};

struct CalibrationCase {
  calibrate::ParameterSpace space;
  calibrate::MultiStartOptions options;
  // Thread-safe: returns the weighted squared error, +inf when the model cannot be built.
  std::function<double(const std::vector<double>&)> objective;
  // Measured against simulated at the given parameter values.
  std::function<std::vector<FitPoint>(const std::vector<double>&)> fit;
  // The main case's text with the given parameter values set (to rerun the best fit).
  std::function<CaseFile(const std::vector<double>&)> case_with;
};

// Reads [calibration] of an already loaded case; call file.reject_unknown() afterwards.
CalibrationCase read_calibration(const CaseFile& file);

}  // namespace comminute::io
