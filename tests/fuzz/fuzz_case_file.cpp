// Fuzzes the case-file loader: TOML text -> CaseFile (UTF-8 guard, toml++, key checks) -> the DEM
// case, breakage, texture and [output] readers -> unknown keys -> fingerprint. Any input must end
// in a built case or an InputError/Error, never in a crash, a sanitizer report or a hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "comminute/core/case_table.hpp"
#include "comminute/core/error.hpp"
#include "comminute/io/case/breakage_case.hpp"
#include "comminute/io/case/dem_case.hpp"
#include "comminute/io/case/output_case.hpp"
#include "comminute/io/case/texture_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace comminute;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const CaseFile file = CaseFile::parse(text, "fuzz.toml");
    io::DemCase dem = io::build_dem_case(file.root());
    if (const auto t = file.root().optional_table("output")) (void)io::read_output_options(*t);
    io::add_breakage(file.root(), dem);
    io::add_texture(file.root(), dem);
    io::decide_time_step(dem);
    file.reject_unknown();
    (void)file.fingerprint();
  } catch (const Error&) {
  }
  return 0;
}
