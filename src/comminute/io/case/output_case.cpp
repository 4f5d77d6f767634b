#include "comminute/io/case/output_case.hpp"

#include <fmt/format.h>

#include <limits>

namespace comminute::io {

namespace {

Cadence read_cadence(const CaseTable& t, const std::string& series) {
  const std::string interval = series + "_interval", every = series + "_every";
  if (t.has(interval) && t.has(every))
    t.fail(every,
           fmt::format("give either {} or {}, not both", t.key_path(interval), t.key_path(every)));
  Cadence c;
  if (t.has(interval)) c.interval = t.number(interval, Limits::positive());
  if (t.has(every))
    c.steps =
        static_cast<std::uint64_t>(t.integer(every, 1, std::numeric_limits<std::int64_t>::max()));
  return c;
}

}  // namespace

OutputOptions default_output_options(const std::filesystem::path& case_file) {
  OutputOptions o;
  o.directory = case_file.parent_path() / "output";
  o.case_file = case_file;
  return o;
}

OutputOptions read_output_options(const CaseTable& t) {
  OutputOptions o = default_output_options(t.file());
  if (t.has("directory")) o.directory = t.file_path("directory");
  o.particles = t.boolean("particles", true);
  o.particles_cadence = read_cadence(t, "particles");
  o.walls = t.boolean("walls", true);
  o.wall_extent = t.number("wall_extent", Limits::non_negative(), 0.0);
  if (t.has("fields")) {
    o.fields = t.strings("fields");
    o.fields_line = t.line("fields");
  }
  o.timeseries_cadence = read_cadence(t, "timeseries");
  o.checkpoint_cadence = read_cadence(t, "checkpoint");
  return o;
}

}  // namespace comminute::io
