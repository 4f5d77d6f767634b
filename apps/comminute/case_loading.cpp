#include "case_loading.hpp"

#include "comminute/io/case/breakage_case.hpp"

namespace comminute::app {

LoadedCase load_dem_case(const std::filesystem::path& path) {
  CaseFile file = CaseFile::load(path);
  io::DemCase dem = io::build_dem_case(file.root());
  const auto output_table = file.root().optional_table("output");
  io::OutputOptions output = output_table ? io::read_output_options(*output_table)
                                          : io::default_output_options(file.path());
  io::add_breakage(file.root(), dem);
  io::decide_time_step(dem);
  file.reject_unknown();
  return {std::move(file), std::move(dem), std::move(output)};
}

}  // namespace comminute::app
