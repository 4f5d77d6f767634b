#pragma once
// Typed, validating access to a TOML case file (toml++).
//
// Every model reads its own keys through a CaseTable. Each read checks the type, the range and
// finiteness, and marks the key as used; after the whole case is built, CaseFile::reject_unknown()
// fails on the first key nobody read (a typo, a key in the wrong table), naming it, its line and
// the nearest known key. Errors are InputError: file, dotted key path, line, value.
//
//   auto file = CaseFile::load("case.toml");
//   CaseTable sim = file.root().table("simulation");
//   double dt = sim.number("time_step", Limits::positive(), 1e-5);   // optional with default
//   double end = sim.number("end_time", Limits::positive());          // required
//   file.reject_unknown();
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "comminute/core/vec3.hpp"

namespace comminute {

// Allowed range of a number: [lo, hi] with optional open ends.
struct Limits {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Limits any() { return {}; }
  static Limits positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Limits non_negative() { return {0.0, std::numeric_limits<double>::infinity()}; }
  static Limits unit_interval() { return {0.0, 1.0}; }                   // [0, 1]
  static Limits open_unit_interval() { return {0.0, 1.0, true, true}; }  // (0, 1)
  static Limits at_least(double v) { return {v, std::numeric_limits<double>::infinity()}; }
  static Limits between(double a, double b) { return {a, b}; }
  bool contains(double v) const;
  std::string describe() const;
};

struct CaseFileState;  // shared by all tables of one file: source text, path, used-key set

class CaseTable {
 public:
  CaseTable(const toml::table* table, std::string path, std::shared_ptr<CaseFileState> file);

  const std::string& path() const { return path_; }  // dotted path of this table ("" = root)
  std::string key_path(std::string_view key) const;
  bool has(std::string_view key) const;
  std::vector<std::string> keys() const;  // in file order is not guaranteed; sorted

  // Numbers (integers are accepted where a float is asked for). NaN/inf are rejected.
  double number(std::string_view key, const Limits& lim = {}) const;
  double number(std::string_view key, const Limits& lim, double fallback) const;
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi) const;
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                       std::int64_t fallback) const;
  bool boolean(std::string_view key) const;
  bool boolean(std::string_view key, bool fallback) const;
  std::string string(std::string_view key) const;
  std::string string(std::string_view key, const std::string& fallback) const;
  // A string that must be one of `choices` (the message lists them).
  std::string choice(std::string_view key, const std::vector<std::string>& choices) const;
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     const std::string& fallback) const;
  Vec3 vec3(std::string_view key, const Limits& lim = {}) const;
  Vec3 vec3(std::string_view key, const Limits& lim, const Vec3& fallback) const;
  std::vector<double> numbers(std::string_view key, const Limits& lim = {}) const;
  std::vector<double> numbers(std::string_view key, const Limits& lim,
                              const std::vector<double>& fallback) const;
  std::vector<std::string> strings(std::string_view key) const;
  // A path relative to the case file's folder (absolute paths are kept).
  std::filesystem::path file_path(std::string_view key) const;
  // A data file to read: file_path() that must name an existing file (not a folder); the error
  // names this case file, the key's line and the key.
  std::filesystem::path input_file(std::string_view key) const;

  CaseTable table(std::string_view key) const;  // required sub-table
  std::optional<CaseTable> optional_table(std::string_view key) const;
  // [[key]] arrays of tables; an absent key gives an empty vector.
  std::vector<CaseTable> tables(std::string_view key) const;

  // Line of the key (or of this table when key is empty); 0 if unknown.
  long line(std::string_view key = {}) const;
  const std::filesystem::path& file() const;
  // Throws InputError for `key` of this table with the given message (value quoted by caller).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  // Marks a key as used without reading it (for keys handled elsewhere).
  void mark_used(std::string_view key) const;

 private:
  const toml::node* get(std::string_view key) const;  // marks used; nullptr if absent
  const toml::node& require(std::string_view key) const;

  const toml::table* table_;
  std::string path_;
  std::shared_ptr<CaseFileState> file_;
};

class CaseFile {
 public:
  // Parses the file; syntax errors become InputError with the line.
  static CaseFile load(const std::filesystem::path& path);
  // Parses TOML text (tests); `name` is used in messages.
  static CaseFile parse(std::string_view text, const std::string& name = "<string>");

  CaseTable root() const;
  const std::filesystem::path& path() const;
  // Throws InputError for the first key (in file order) that no model read.
  void reject_unknown() const;
  // Every key path that was read, for documentation checks.
  std::set<std::string> used_keys() const;
  // The data files the readers named through file_path()/input_file(), by key path, resolved
  // against the case file's folder (e.g. what a population balance reads from a DEM's outputs).
  std::map<std::string, std::filesystem::path> data_files() const;
  // What a checkpoint must agree with to be continued by this case: one (section, hash) per root
  // key, in name order, from the TOML text of that table and the data files its keys named
  // (file_path()). [output] and simulation.end_time are left out: they may change on a restart.
  // Call after the case was read.
  std::vector<std::pair<std::string, std::string>> fingerprint() const;

 private:
  std::shared_ptr<CaseFileState> state_;
};

// Nearest candidate by edit distance (for "did you mean ...?"), empty when none is close.
std::string nearest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace comminute
