#pragma once
// What every `comminute calibrate` mode shares: the [calibration] optimiser keys, the free
// parameters ([[calibration.parameter]]: a numeric case key with bounds and scale) and a case
// rebuilt with trial values of its free keys. Every key: docs/pbm.md ([calibration]) and
// docs/case-file.md ([calibration.compression]).
#include <filesystem>
#include <string>
#include <vector>

#include "comminute/calibrate/multistart.hpp"
#include "comminute/calibrate/parameter_space.hpp"
#include "comminute/core/case_table.hpp"

namespace comminute::io {

// starts, seed, threads, simplex_step, adaptive, x_tolerance, f_tolerance,
// f_relative_tolerance, max_evaluations of [calibration] (`n_parameters` for `adaptive`).
calibrate::MultiStartOptions read_calibration_options(const CaseTable& c, std::size_t n_parameters);

struct FreeKeys {
  std::vector<std::string> keys;                 // dotted case keys, e.g. "bonds.tensile_strength"
  std::vector<calibrate::FreeParameter> params;  // bounds and scale, one per key
  std::vector<CaseTable> tables;                 // the [[calibration.parameter]] tables (messages)
};
// The [[calibration.parameter]] entries (at least one, each key once).
FreeKeys read_free_parameters(const CaseTable& c);

// The TOML document of a case file (after the case-file text checks).
toml::table parse_case_toml(const std::filesystem::path& path);
// `doc` with the numbers at `keys` ("a.b", "a.b[2]", "a.list[0].c") set to `values`, as a case
// named `path` (relative file keys stay relative to its folder).
CaseFile case_with_numbers(const toml::table& doc, const std::filesystem::path& path,
                           const std::vector<std::string>& keys, const std::vector<double>& values);
// The values of `keys` in `doc` (0 where a key is not a number).
std::vector<double> numbers_at(const toml::table& doc, const std::vector<std::string>& keys);

}  // namespace comminute::io
