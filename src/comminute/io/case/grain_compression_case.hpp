#pragma once
// Single-grain compression and the calibration of bond parameters against it (issue 11 point 6).
// A DEM case holds one bonded grain resting on a floor and a platen moving into it at a constant
// velocity; the platen's force–displacement record runs from its first contact with the grain.
// `comminute calibrate` with a [calibration.compression] table fits free numeric keys of the
// case (bond strengths, stiffness per area, G_c, ...) to a measured curve (CSV
// `displacement [m]`, `force [N]`) by multi-start Nelder–Mead; each evaluation runs the small
// DEM compression with the trial values. Objective (dimensionless, P the measured peak force):
//   J = (1/n) Σ_i ((F_sim(δ_i) − F_i) / P)² + w_peak ((P_sim − P) / P)²,
// F_sim interpolated linearly between steps, P_sim the largest simulated force up to the last
// measured displacement. Every key: docs/case-file.md ([calibration.compression]) and
// docs/pbm.md ([calibration]).
#include <functional>
#include <string>
#include <vector>

#include "comminute/calibrate/multistart.hpp"
#include "comminute/calibrate/parameter_space.hpp"
#include "comminute/core/case_table.hpp"

namespace comminute::io {

struct ForceDisplacement {
  std::vector<double> displacement;  // m, of the platen since its first contact
  std::vector<double> force;         // N, compressive, on the platen
};

struct CompressionSpec {
  std::string platen;        // the [[walls]] name of the moving platen
  double contact_force = 0;  // N: contact begins at the first step with a force above it
  double peak_weight = 1;    // w_peak of the objective
};

// Builds the DEM case (its DEM tables and [bonds]) and steps it until the platen has moved
// `displacement` past its first contact, or to the case's end time. Throws InputError for a
// platen that is not a wall moving at a constant velocity.
ForceDisplacement compress_grain(const CaseFile& file, const CompressionSpec& spec,
                                 double displacement);

// Force at displacement x, linear between records; NaN outside the record.
double force_at(const ForceDisplacement& c, double x);

struct GrainCalibrationCase {
  calibrate::ParameterSpace space;
  calibrate::MultiStartOptions options;
  CompressionSpec spec;
  ForceDisplacement measured;
  std::vector<double> case_values;  // the free keys' values as the case gives them
  // Thread-safe: J at the parameter values, +inf when the run fails or stops short.
  std::function<double(const std::vector<double>&)> objective;
  // The simulated record at the parameter values (to the last measured displacement).
  std::function<ForceDisplacement(const std::vector<double>&)> simulate;
  // The case with the given parameter values set.
  std::function<CaseFile(const std::vector<double>&)> case_with;
};

// Whether `comminute calibrate` should fit a grain compression: the case has
// [calibration.compression].
bool is_grain_calibration(const CaseTable& root);
// Reads [calibration] of a loaded single-grain case, reads its DEM and [bonds] tables and runs it
// once at the case's own values (a run that does not reach the last measured displacement, or
// fails, is an InputError). Call file.reject_unknown() afterwards.
GrainCalibrationCase read_grain_calibration(const CaseFile& file);

}  // namespace comminute::io
