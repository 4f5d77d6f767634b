#include "case_loading.hpp"

namespace comminute::app {

LoadedCase load_dem_case(const std::filesystem::path& path) {
  io::CaseFile file = io::CaseFile::load(path);
  io::DemCase dem = io::build_dem_case(file.root());
  file.reject_unknown();
  return {std::move(file), std::move(dem)};
}

}  // namespace comminute::app
