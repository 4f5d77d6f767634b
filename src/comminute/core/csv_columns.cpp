#include "comminute/core/csv_columns.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "comminute/core/error.hpp"

namespace comminute {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  return out;
}
}  // namespace

CsvColumns CsvColumns::read(const std::filesystem::path& path, const std::string& key) {
  CsvColumns c;
  c.path_ = path;
  c.key_ = key;
  if (!std::filesystem::exists(path)) throw InputError(path.string(), key, 0, "no such CSV file");
  if (std::filesystem::is_directory(path))
    throw InputError(path.string(), key, 0, "is a directory, not a CSV file");
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), key, 0, "cannot open CSV file");
  std::string line;
  long no = 0;
  while (std::getline(in, line)) {
    ++no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto cells = split(t);
    if (c.names_.empty()) {
      c.names_ = cells;
      c.header_line_ = no;
      for (std::size_t k = 0; k < cells.size(); ++k) {
        if (cells[k].empty())
          throw InputError(path.string(), key, no, fmt::format("column {} has no name", k + 1));
        if (std::find(cells.begin(), cells.begin() + static_cast<long>(k), cells[k]) !=
            cells.begin() + static_cast<long>(k))
          throw InputError(path.string(), key, no,
                           fmt::format("column name '{}' appears twice", cells[k]));
      }
      continue;
    }
    if (cells.size() != c.names_.size())
      throw InputError(path.string(), key, no,
                       fmt::format("expected {} values (columns {}), found {}", c.names_.size(),
                                   fmt::join(c.names_, ", "), cells.size()));
    std::vector<double> row;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      double v = 0;
      const auto* end = cells[k].data() + cells[k].size();
      const auto r = std::from_chars(cells[k].data(), end, v);
      if (r.ec != std::errc() || r.ptr != end || !std::isfinite(v))
        throw InputError(
            path.string(), key, no,
            fmt::format("column '{}': '{}' is not a finite number", c.names_[k], cells[k]));
      row.push_back(v);
    }
    c.rows_.push_back(std::move(row));
    c.lines_.push_back(no);
  }
  if (c.names_.empty()) throw InputError(path.string(), key, 0, "empty CSV file (no header)");
  if (c.rows_.empty()) throw InputError(path.string(), key, c.header_line_, "no data rows");
  return c;
}

bool CsvColumns::has(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

std::vector<double> CsvColumns::column(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end())
    throw InputError(
        path_.string(), key_, header_line_,
        fmt::format("missing column '{}' (header has: {})", name, fmt::join(names_, ", ")));
  const auto k = static_cast<std::size_t>(it - names_.begin());
  std::vector<double> out;
  for (const auto& r : rows_) out.push_back(r[k]);
  return out;
}

}  // namespace comminute
