#include "comminute/core/error.hpp"

#include <fmt/format.h>

namespace comminute {

namespace {
std::string format_input_error(const std::string& file, const std::string& key, long line,
                               const std::string& message) {
  std::string where = file.empty() ? std::string("<input>") : file;
  if (line > 0) where += fmt::format(":{}", line);
  if (!key.empty()) return fmt::format("{}: key '{}': {}", where, key, message);
  return fmt::format("{}: {}", where, message);
}
}  // namespace

InputError::InputError(std::string file, std::string key, long line, const std::string& message)
    : Error(format_input_error(file, key, line, message)),
      file_(std::move(file)),
      key_(std::move(key)),
      line_(line) {}

}  // namespace comminute
