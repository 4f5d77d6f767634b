// Fuzzes the LAMMPS-style particle data reader ([[insert]] type = "data_file"): any bytes must
// give particles or an InputError naming file and line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "comminute/core/error.hpp"
#include "comminute/io/case/lammps_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace comminute;
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                            ("fuzz_data_" + std::to_string(::getpid()) + ".data");
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    (void)io::read_lammps_data(file, "insert[0].file");
  } catch (const InputError&) {
  }
  return 0;
}
