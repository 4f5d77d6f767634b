#pragma once
// The text of a file of the source tree (docs, examples), "" when it cannot be read.
#include <fstream>
#include <sstream>
#include <string>

namespace comminute::testing {

inline std::string read_source_file(const std::string& relative) {
  std::ifstream in(std::string(COMMINUTE_SOURCE_DIR) + "/" + relative);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace comminute::testing
