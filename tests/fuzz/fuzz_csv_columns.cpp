// Fuzzes the CSV data reader (measured size distributions, spectra, frequency tables): any bytes
// must give columns or an InputError naming file and line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "comminute/core/csv_columns.hpp"
#include "comminute/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace comminute;
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("fuzz_csv_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    const CsvColumns c = CsvColumns::read(file, "fuzz.file");
    for (const char* name : {"size_m", "cumulative_passing", "energy_J", "x"}) try {
        (void)c.column(name);
      } catch (const InputError&) {
      }
  } catch (const InputError&) {
  }
  return 0;
}
