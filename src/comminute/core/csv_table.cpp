#include "comminute/core/csv_table.hpp"

#include <fmt/format.h>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute {

namespace {
bool breaks_csv(const std::string& s) {
  return s.find_first_of(",\"\r\n") != std::string::npos;
}
}  // namespace

Cell::Cell(std::string v) {
  if (breaks_csv(v))
    throw Error(fmt::format("'{}' cannot be a CSV cell (holds a comma, quote or line break)", v));
  v_ = std::move(v);
}

void Cell::append_to(std::string& out) const {
  std::visit(
      [&out](const auto& x) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::string>)
          out += x;
        else
          fmt::format_to(std::back_inserter(out), "{}", x);  // doubles: shortest round-trip
      },
      v_);
}

std::string csv_line(const std::vector<Cell>& cells) {
  std::string s;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k > 0) s += ',';
    cells[k].append_to(s);
  }
  s += '\n';
  return s;
}

std::string csv_header(const std::vector<Column>& columns) {
  std::string s;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const Column& c = columns[k];
    if (c.name.empty() || (c.unit.empty() != c.bare) || breaks_csv(c.name) || breaks_csv(c.unit) ||
        c.unit.find_first_of("[]") != std::string::npos)
      throw Error(fmt::format("'{}' [{}] cannot name a CSV column", c.name, c.unit));
    if (k > 0) s += ',';
    s += c.header();
  }
  return s;
}

Table::Table(std::string name, std::vector<Column> columns)
    : name_(std::move(name)), columns_(std::move(columns)) {
  csv_header(columns_);  // checks the names
}

void Table::add_row(const std::vector<Cell>& cells) {
  if (cells.size() != columns_.size())
    throw Error(fmt::format("table '{}' has {} columns, a row has {} cells", name_, columns_.size(),
                            cells.size()));
  lines_.push_back(csv_line(cells));
}

void Table::write(const std::filesystem::path& directory) const {
  write_file(directory / (name_ + ".csv"));
}

void Table::write_file(const std::filesystem::path& file) const {
  AtomicFile f(file, std::ios::binary);
  auto& o = f.stream();
  o << csv_header(columns_) << '\n';
  for (const auto& l : lines_) o.write(l.data(), static_cast<std::streamsize>(l.size()));
  f.commit();
}

}  // namespace comminute
