#pragma once
// Errors. InputError is for anything a user wrote wrong: it names the file, the key path, the
// line (when known) and the offending value, and the command line turns it into a non-zero exit.
#include <stdexcept>
#include <string>

namespace comminute {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputError : public Error {
 public:
  // file: path of the case/data file; key: dotted key path (e.g. "materials.rock.density") or
  // "" for file-level problems; line: 1-based line, 0 if unknown.
  InputError(std::string file, std::string key, long line, const std::string& message);

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  long line() const { return line_; }

 private:
  std::string file_, key_;
  long line_;
};

// A run that went wrong physically (NaN, particle lost, unstable step): names particle and time.
class SimulationError : public Error {
 public:
  using Error::Error;
};

}  // namespace comminute
