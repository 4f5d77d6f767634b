#pragma once
// Loading a DEM case for `run` and `check`: every reader takes its tables, then unknown keys are
// rejected.
#include <filesystem>
#include <string>

#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"

namespace comminute::app {

struct LoadedCase {
  CaseFile file;
  io::DemCase dem;
  io::OutputOptions output;  // [output], or the defaults when the table is absent
};

LoadedCase load_dem_case(const std::filesystem::path& path);
// Refuses an output folder that is empty, a file, or not writable (nor creatable), naming the
// case key (or `option` when the folder came from the command line), and output.fields that no
// model of the case provides: what `run` would refuse, `check` refuses too.
void check_output_directory(const LoadedCase& c, const std::string& option = "");

}  // namespace comminute::app
