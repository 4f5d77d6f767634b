#pragma once
// What a breakage model reads from its case-file table. The breakage room sits above io/, so it
// cannot see CaseTable; io/breakage_case adapts a CaseTable to this interface (errors then
// name file, key and line), and tests use a plain map.
#include <limits>
#include <string>
#include <vector>

namespace comminute::breakage {

class ParameterSource {
 public:
  static constexpr double required = std::numeric_limits<double>::quiet_NaN();
  virtual ~ParameterSource() = default;
  // A number in [lo, hi] (lo excluded when lo_open); `fallback` NaN means the key is required.
  virtual double number(const std::string& key, double lo, double hi, bool lo_open,
                        double fallback) const = 0;
  // A list of numbers in [lo, hi]; required.
  virtual std::vector<double> numbers(const std::string& key, double lo, double hi) const = 0;
  virtual std::string choice(const std::string& key, const std::vector<std::string>& choices,
                             const std::string& fallback) const = 0;
  virtual bool has(const std::string& key) const = 0;
  // Throws InputError for `key` (io) or Error (tests) with the message.
  [[noreturn]] virtual void fail(const std::string& key, const std::string& message) const = 0;
};

}  // namespace comminute::breakage
