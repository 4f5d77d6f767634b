#pragma once
// Loading a DEM case for `run` and `check`: every reader takes its tables, then unknown keys are
// rejected.
#include <filesystem>

#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"

namespace comminute::app {

struct LoadedCase {
  CaseFile file;
  io::DemCase dem;
  io::OutputOptions output;  // [output], or the defaults when the table is absent
};

LoadedCase load_dem_case(const std::filesystem::path& path);

}  // namespace comminute::app
