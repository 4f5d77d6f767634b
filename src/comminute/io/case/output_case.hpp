#pragma once
// The [output] table of a case file: what a run writes, where and how often (docs/case-file.md,
// section "[output]").
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "comminute/core/cadence.hpp"
#include "comminute/core/case_table.hpp"

namespace comminute::io {

using comminute::Cadence;  // core/cadence.hpp

struct OutputOptions {
  std::filesystem::path directory = "output";
  bool particles = true;      // particle snapshots (particles.pvd)
  Cadence particles_cadence;  // default: 100 snapshots over the run
  bool walls = true;          // wall snapshots with each particle snapshot (walls.pvd)
  double wall_extent = 0;     // m, half-size of drawn infinite planes; 0 = from the particle cloud
  std::optional<std::vector<std::string>> fields;  // per-particle fields; nullopt = all
  Cadence timeseries_cadence;                      // default: 1000 rows over the run
  Cadence checkpoint_cadence;  // default: only at the end of the run and on a stop signal
  // [coarse_graining] scale k: snapshots add the primary diameter d/k (1: none)
  double coarse_scale = 1.0;

  // Where `fields` was given, so that an unknown name (known only once the modules have
  // registered their fields) is reported as an input error at the right line.
  std::filesystem::path case_file;
  long fields_line = 0;
  // The case's fingerprint (CaseFile::fingerprint()), written into every checkpoint so that a
  // restart with another case is refused.
  std::vector<std::pair<std::string, std::string>> case_fingerprint;
};

// Reads the [output] table (`t` is that table). Every key is optional.
OutputOptions read_output_options(const CaseTable& t);
// Defaults when the case has no [output] table: directory "output" next to the case file.
OutputOptions default_output_options(const std::filesystem::path& case_file);

}  // namespace comminute::io
