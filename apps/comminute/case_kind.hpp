#pragma once
// Which command runs a case, read from the tables it has: `comminute check` reads each kind with
// that command's reader, and each command refuses a case of another kind by naming the command
// that runs it (instead of the first table its own reader misses).
#include <filesystem>
#include <initializer_list>

namespace comminute::app {

enum class CaseKind {
  dem,                     // [simulation] (or no table that marks another kind): `run`
  grain_fit,               // [simulation] and [calibration.compression]: `calibrate`
  population_balance,      // [grid] and no [simulation]: `pbm`
  population_balance_fit,  // the same with [calibration]: `calibrate`
  chain,                   // [couple]: `couple`
};

// Both read a copy of the file of their own, so that the tables they look into do not count as
// read when the command's own reading refuses the keys it did not read.
CaseKind case_kind(const std::filesystem::path& file);

// Throws InputError (exit code 2) naming the file, the table that marks the case's kind and the
// command that runs it, unless the kind is one of `accepted`.
void require_case_kind(const std::filesystem::path& file, std::initializer_list<CaseKind> accepted);

}  // namespace comminute::app
