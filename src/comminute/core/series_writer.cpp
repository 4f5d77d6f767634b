#include "comminute/core/series_writer.hpp"

#include <fmt/format.h>

#include <charconv>
#include <sstream>

#include "comminute/core/atomic_file.hpp"
#include "comminute/core/error.hpp"

namespace comminute {

SeriesWriter::SeriesWriter(std::filesystem::path path, std::vector<Column> columns)
    : path_(std::move(path)), columns_(columns.size()), header_(csv_header(columns)) {}

void SeriesWriter::start_fresh() {
  AtomicFile f(path_, std::ios::binary);
  f.stream() << header_ << '\n';
  f.commit();
  open_for_append();
}

void SeriesWriter::resume(double t) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) {
    start_fresh();
    return;
  }
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  const std::string s = text.str();
  std::size_t eol = s.find('\n');
  if (eol == std::string::npos || s.substr(0, eol) != header_)
    throw Error(
        fmt::format("cannot continue '{}': its header is not this case's header\n"
                    "  found:    {}\n  expected: {}",
                    path_.string(), s.substr(0, eol), header_));
  AtomicFile f(path_, std::ios::binary);
  f.stream() << header_ << '\n';
  // Complete lines only (ending in '\n'); the first field is the time.
  for (std::size_t begin = eol + 1; (eol = s.find('\n', begin)) != std::string::npos;
       begin = eol + 1) {
    const std::string_view line(s.data() + begin, eol - begin);
    double time = 0;
    const auto r = std::from_chars(line.data(), line.data() + line.size(), time);
    if (r.ec != std::errc() || (r.ptr != line.data() + line.size() && *r.ptr != ','))
      throw Error(fmt::format("cannot continue '{}': a row does not start with a time: '{}'",
                              path_.string(), line));
    if (time > t) break;  // rows are in time order: the rest was written after the checkpoint
    f.stream() << line << '\n';
  }
  f.commit();
  open_for_append();
}

void SeriesWriter::open_for_append() {
  out_.close();
  out_.open(path_, std::ios::app | std::ios::binary);
  if (!out_) throw Error(fmt::format("cannot open '{}' for appending", path_.string()));
}

void SeriesWriter::append(const std::vector<Cell>& cells) {
  if (!out_.is_open()) throw Error("SeriesWriter::append before start_fresh() or resume()");
  if (cells.size() != columns_)
    throw Error(fmt::format("series '{}' has {} columns, a row has {} cells", path_.string(),
                            columns_, cells.size()));
  const std::string row = csv_line(cells);
  out_.write(row.data(), static_cast<std::streamsize>(row.size()));
  out_.flush();
  if (!out_) throw Error(fmt::format("write to '{}' failed", path_.string()));
}

}  // namespace comminute
