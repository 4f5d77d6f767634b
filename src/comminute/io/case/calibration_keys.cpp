#include "comminute/io/case/calibration_keys.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "comminute/core/error.hpp"

namespace comminute::io {

namespace {

// Sets a number at a dotted key path ("a.b", "a.b[2]", "a.list[0].c") of a parsed document.
void set_number(toml::table& doc, const std::string& key, double value) {
  toml::node_view<toml::node> n = toml::at_path(doc, key);
  if (auto* f = n.as_floating_point()) {
    *f = value;
    return;
  }
  const auto dot = key.find_last_of('.');
  const auto bracket = key.find_last_of('[');
  if (bracket != std::string::npos && (dot == std::string::npos || bracket > dot)) {
    auto* arr = toml::at_path(doc, key.substr(0, bracket)).as_array();
    const auto i = std::stoul(key.substr(bracket + 1));
    arr->replace(arr->cbegin() + static_cast<long>(i), value);
    return;
  }
  toml::table* parent =
      dot == std::string::npos ? &doc : toml::at_path(doc, key.substr(0, dot)).as_table();
  parent->insert_or_assign(key.substr(dot == std::string::npos ? 0 : dot + 1), value);
}

// TOML text of a node, tables inline and arrays on one line: toml++'s own formatter measures
// arrays with a cast that is undefined behaviour for numbers below 0.1 (toml_formatter.inl,
// count_inline_columns: size_t of a negative log10), so the document is written here; scalars
// keep toml++'s printing.
void write_toml_value(std::ostream& os, const toml::node& n);

void write_toml_key(std::ostream& os, std::string_view key) {
  os << toml::value<std::string>(std::string(key));
}

void write_toml_value(std::ostream& os, const toml::node& n) {
  if (const auto* t = n.as_table()) {
    os << '{';
    const char* sep = " ";
    for (auto&& [k, v] : *t) {
      os << sep;
      write_toml_key(os, k.str());
      os << " = ";
      write_toml_value(os, v);
      sep = ", ";
    }
    os << (t->empty() ? "}" : " }");
    return;
  }
  if (const auto* a = n.as_array()) {
    os << '[';
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i) os << ", ";
      write_toml_value(os, *a->get(i));
    }
    os << ']';
    return;
  }
  n.visit([&os](auto&& v) { os << v; });
}

}  // namespace

calibrate::MultiStartOptions read_calibration_options(const CaseTable& c,
                                                      std::size_t n_parameters) {
  calibrate::MultiStartOptions o;
  o.starts = static_cast<std::size_t>(c.integer("starts", 1, 100000, 15));
  o.seed =
      static_cast<std::uint64_t>(c.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1));
  o.threads = static_cast<int>(c.integer("threads", 0, 1024, 0));
  o.simplex_step = c.number("simplex_step", {0, 1, true, false}, 0.1);
  if (c.boolean("adaptive", false))  // Gao & Han coefficients, for many parameters
    o.nelder_mead = calibrate::NelderMeadOptions::adaptive(n_parameters);
  o.nelder_mead.x_tolerance = c.number("x_tolerance", Limits::positive(), 1e-4);
  o.nelder_mead.f_tolerance = c.number("f_tolerance", Limits::non_negative(), 1e-12);
  o.nelder_mead.f_relative_tolerance =
      c.number("f_relative_tolerance", Limits::non_negative(), 1e-6);
  o.nelder_mead.max_evaluations =
      static_cast<std::size_t>(c.integer("max_evaluations", 10, 10000000, 2000));
  return o;
}

FreeKeys read_free_parameters(const CaseTable& c) {
  FreeKeys out;
  out.tables = c.tables("parameter");
  if (out.tables.empty()) c.fail("parameter", "give at least one [[calibration.parameter]]");
  for (const auto& t : out.tables) {
    calibrate::FreeParameter p;
    p.name = t.string("key");
    p.lower = t.number("min");
    p.upper = t.number("max");
    if (!(p.upper > p.lower))
      t.fail("max", fmt::format("max ({}) must exceed min ({})", p.upper, p.lower));
    const std::string scale = t.choice("scale", {"auto", "log", "linear"}, "auto");
    p.scale = scale == "log"      ? calibrate::Scale::log
              : scale == "linear" ? calibrate::Scale::linear
                                  : calibrate::auto_scale(p.lower, p.upper);
    if (p.scale == calibrate::Scale::log && !(p.lower > 0))
      t.fail("min", "log scale needs a positive lower bound");
    // one key, one parameter: a second [[calibration.parameter]] of the same key would silently
    // override the first (the later value wins in every evaluation)
    if (std::find(out.keys.begin(), out.keys.end(), p.name) != out.keys.end())
      t.fail("key", fmt::format("'{}' is already a free parameter", p.name));
    out.keys.push_back(p.name);
    out.params.push_back(p);
  }
  return out;
}

toml::table parse_case_toml(const std::filesystem::path& path) {
  (void)CaseFile::load(path);  // the text checks (UTF-8, keys) before toml++ parses it directly
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(path.string(), "", static_cast<long>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
}

CaseFile case_with_numbers(const toml::table& doc, const std::filesystem::path& path,
                           const std::vector<std::string>& keys,
                           const std::vector<double>& values) {
  toml::table d = doc;
  for (std::size_t i = 0; i < keys.size(); ++i) set_number(d, keys[i], values[i]);
  std::ostringstream s;
  for (auto&& [k, v] : d) {
    write_toml_key(s, k.str());
    s << " = ";
    write_toml_value(s, v);
    s << '\n';
  }
  return CaseFile::parse(s.str(), path.string());
}

std::vector<double> numbers_at(const toml::table& doc, const std::vector<std::string>& keys) {
  std::vector<double> v;
  for (const auto& k : keys) v.push_back(toml::at_path(doc, k).value<double>().value_or(0.0));
  return v;
}

}  // namespace comminute::io
