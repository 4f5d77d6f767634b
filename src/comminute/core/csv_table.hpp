#pragma once
// The one way the program writes CSV: a table of named columns with units and rows of cells.
//
// Header convention: every column is `name [unit]`, units SI (`time [s]`, `specific_energy
// [J/kg]`, `t10 [%]`, `[-]` for counts and dimensionless numbers). Cells are printed in full
// precision: a double in the shortest form that reads back to the same double, an integer as is,
// text as is (text holds no comma, quote or line break). A whole table is written through
// AtomicFile (<file>.part, renamed when complete); series that grow row by row use SeriesWriter.
#include <concepts>
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace comminute {

struct Column {
  std::string name;
  std::string unit;  // "-" for counts and dimensionless numbers
  // The header is the name alone (no unit given: the name holds it): only for a file that a
  // reader of this program reads by fixed names (the collision spectrum's energy_J).
  bool bare = false;
  std::string header() const { return bare ? name : name + " [" + unit + "]"; }
};

class Cell {
 public:
  Cell(double v) : v_(v) {}  // NOLINT: implicit on purpose, rows are written as {a, b, c}
  template <std::integral I>
  Cell(I v) {  // NOLINT
    if constexpr (std::is_signed_v<I>)
      v_ = static_cast<std::int64_t>(v);
    else
      v_ = static_cast<std::uint64_t>(v);
  }
  Cell(std::string v);  // NOLINT; throws Error if it holds a comma, quote or line break
  Cell(const char* v) : Cell(std::string(v)) {}  // NOLINT
  void append_to(std::string& out) const;

 private:
  std::variant<double, std::int64_t, std::uint64_t, std::string> v_;
};

// One line of cells, comma-separated, with the trailing '\n'.
std::string csv_line(const std::vector<Cell>& cells);
// The header line of these columns (without '\n'); throws Error on a name or unit that would
// break the CSV.
std::string csv_header(const std::vector<Column>& columns);

class Table {
 public:
  // `name` is the file stem: the table is written as <name>.csv.
  Table(std::string name, std::vector<Column> columns);

  const std::string& name() const { return name_; }
  const std::vector<Column>& columns() const { return columns_; }
  std::size_t rows() const { return lines_.size(); }
  // Throws Error if the row does not have one cell per column.
  void add_row(const std::vector<Cell>& cells);
  // Replaces <directory>/<name>.csv atomically by the header and every row.
  void write(const std::filesystem::path& directory) const;
  void write_file(const std::filesystem::path& file) const;

 private:
  std::string name_;
  std::vector<Column> columns_;
  std::vector<std::string> lines_;  // formatted rows, each ending in '\n'
};

}  // namespace comminute
