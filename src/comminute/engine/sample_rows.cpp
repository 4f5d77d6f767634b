#include "comminute/engine/sample_rows.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "comminute/core/error.hpp"

namespace comminute {

SampleRows::SampleRows(std::vector<Column> columns, std::vector<bool> counts)
    : columns_(std::move(columns)), counts_(std::move(counts)) {
  counts_.resize(columns_.size(), false);
}

void SampleRows::add(double time, const std::vector<double>& values) {
  if (values.size() + 1 != columns_.size())
    throw Error(
        fmt::format("a sample of {} values for {} columns", values.size() + 1, columns_.size()));
  flat_.push_back(time);
  flat_.insert(flat_.end(), values.begin(), values.end());
}

Table SampleRows::table(const std::string& name) const {
  Table t(name, columns_);
  const std::size_t width = columns_.size();
  for (std::size_t s = 0; s + width <= flat_.size(); s += width) {
    std::vector<Cell> row;
    for (std::size_t k = 0; k < width; ++k)
      if (counts_[k])
        row.emplace_back(static_cast<std::uint64_t>(flat_[s + k]));
      else
        row.emplace_back(flat_[s + k]);
    t.add_row(row);
  }
  return t;
}

void SampleRows::save(Archive& a, const std::string& entry) const {
  a.put(entry, flat_);
}

void SampleRows::load(const Archive& a, const std::string& entry) {
  flat_ = a.get<double>(entry);
  if (columns_.empty() || flat_.size() % columns_.size() != 0)
    throw Error(fmt::format("checkpoint entry '{}' does not hold whole rows of {} columns", entry,
                            columns_.size()));
  for (double v : flat_)
    if (!std::isfinite(v)) throw Error(fmt::format("checkpoint entry '{}' is not finite", entry));
}

}  // namespace comminute
