#pragma once
// The rows a module samples for one table of fixed width (time, then numbers), kept as one flat
// array so that they checkpoint as one entry; columns flagged as counts are written as integers.
#include <string>
#include <vector>

#include "comminute/core/archive.hpp"
#include "comminute/core/csv_table.hpp"

namespace comminute {

class SampleRows {
 public:
  // columns[0] is the time; `counts[k]` true writes column k as an integer.
  SampleRows(std::vector<Column> columns, std::vector<bool> counts);
  // Appends one row: the time, then one value per further column (throws Error otherwise).
  void add(double time, const std::vector<double>& values);
  std::size_t rows() const { return columns_.empty() ? 0 : flat_.size() / columns_.size(); }
  Table table(const std::string& name) const;
  void save(Archive& a, const std::string& entry) const;
  // Throws Error when the entry does not hold whole rows of finite numbers.
  void load(const Archive& a, const std::string& entry);

 private:
  std::vector<Column> columns_;
  std::vector<bool> counts_;
  std::vector<double> flat_;
};

}  // namespace comminute
