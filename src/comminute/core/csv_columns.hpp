#pragma once
// Reads a numeric CSV file with a header row of column names (lines starting with '#' and blank
// lines are skipped). Columns are fetched by name; a missing column, a short row or a value that
// is not a finite number is an InputError naming the file, the line and the column.
#include <filesystem>
#include <string>
#include <vector>

namespace comminute {

class CsvColumns {
 public:
  // `key` is the case-file key that named the file (for messages).
  static CsvColumns read(const std::filesystem::path& path, const std::string& key = "");

  std::vector<double> column(const std::string& name) const;  // throws when missing
  bool has(const std::string& name) const;
  long line_of_row(std::size_t row) const { return lines_[row]; }

 private:
  std::filesystem::path path_;
  std::string key_;
  long header_line_ = 0;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> rows_;
  std::vector<long> lines_;
};

}  // namespace comminute
