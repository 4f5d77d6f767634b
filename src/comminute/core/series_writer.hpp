#pragma once
// A CSV series that grows row by row while a run advances (csv_table.hpp: header convention and
// number format). The header is written atomically; each row is appended and flushed whole, so a
// killed run keeps every complete row and at most one partial last line (no '\n'), which
// resume() removes. The first column is the time (s), rows are in time order.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "comminute/core/csv_table.hpp"

namespace comminute {

class SeriesWriter {
 public:
  // Throws Error on a column name or unit that would break the CSV.
  SeriesWriter(std::filesystem::path path, std::vector<Column> columns);

  // Fresh run: replaces any existing file by the header alone.
  void start_fresh();
  // Restart from a checkpoint at time t: keeps the header and the complete rows with
  // time <= t, drops the rest (rows written after the checkpoint, a half-written last line).
  // Throws Error if the existing header is not this header. No file: starts fresh.
  void resume(double t);
  // Appends one row and flushes it; throws Error if it has not one cell per column.
  void append(const std::vector<Cell>& cells);

  const std::filesystem::path& path() const { return path_; }
  const std::string& header() const { return header_; }

 private:
  void open_for_append();

  std::filesystem::path path_;
  std::size_t columns_;
  std::string header_;
  std::ofstream out_;
};

}  // namespace comminute
