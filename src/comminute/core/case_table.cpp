// Sanitizer builds compile the TOML parser here (src/comminute/CMakeLists.txt), as Debian's
// library is built: assertions off (a Debug build would stop at toml++'s internal assertions,
// e.g. on "[(" where the release parser reports a syntax error), no assumptions (GCC has none).
#ifdef COMMINUTE_TOML_IMPLEMENTATION
#define TOML_IMPLEMENTATION
#define TOML_ASSERT(expr) static_assert(true)
#endif
#include "comminute/core/case_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "comminute/core/case_file_state.hpp"
#include "comminute/core/case_text.hpp"
#include "comminute/core/error.hpp"

namespace comminute {

namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    default:
      return "date/time";
  }
}

// A value as it appears in messages. Not toml++'s printer: in 3.3.0 it has undefined behaviour
// on arrays holding floats below 1 (it sizes them with an unchecked float->integer conversion).
void display(const toml::node& n, std::string& out) {
  if (out.size() > 80) return;
  if (auto t = n.as_table()) {
    out += '{';
    bool first = true;
    for (const auto& [k, v] : *t) {
      out += first ? " " : ", ";
      first = false;
      out += std::string(k.str()) + " = ";
      display(v, out);
    }
    out += " }";
  } else if (auto a = n.as_array()) {
    out += '[';
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (i) out += ", ";
      display(*a->get(i), out);
    }
    out += ']';
  } else if (auto str = n.as_string()) {
    out += '"' + str->get() + '"';
  } else if (auto i = n.as_integer()) {
    out += fmt::format("{}", i->get());
  } else if (auto f = n.as_floating_point()) {
    out += fmt::format("{}", f->get());
  } else if (auto b = n.as_boolean()) {
    out += b->get() ? "true" : "false";
  } else {
    out += "<date/time>";
  }
}

std::string show(const toml::node& n) {
  std::string out;
  display(n, out);
  if (out.size() > 60) out = out.substr(0, 57) + "...";
  return out;
}

std::string join_path(const std::string& base, std::string_view key) {
  return base.empty() ? std::string(key) : base + "." + std::string(key);
}

}  // namespace

bool Limits::contains(double v) const {
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Limits::describe() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  if (has_lo && has_hi)
    return fmt::format("in {}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  if (has_lo) return fmt::format("{} {}", lo_open ? ">" : ">=", lo);
  if (has_hi) return fmt::format("{} {}", hi_open ? "<" : "<=", hi);
  return "finite";
}

CaseTable::CaseTable(const toml::table* table, std::string path,
                     std::shared_ptr<CaseFileState> file)
    : table_(table), path_(std::move(path)), file_(std::move(file)) {}

std::string CaseTable::key_path(std::string_view key) const {
  return join_path(path_, key);
}

bool CaseTable::has(std::string_view key) const {
  return table_->contains(key);
}

std::vector<std::string> CaseTable::keys() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : *table_) out.emplace_back(k.str());
  return out;
}

const std::filesystem::path& CaseTable::file() const {
  return file_->path;
}

long CaseTable::line(std::string_view key) const {
  const toml::node* n = key.empty() ? static_cast<const toml::node*>(table_) : table_->get(key);
  if (n == nullptr) return static_cast<long>(table_->source().begin.line);
  return static_cast<long>(n->source().begin.line);
}

void CaseTable::fail(std::string_view key, const std::string& message) const {
  throw InputError(file_->path.string(), key.empty() ? path_ : key_path(key), line(key), message);
}

void CaseTable::mark_used(std::string_view key) const {
  file_->used.insert(key_path(key));
}

const toml::node* CaseTable::get(std::string_view key) const {
  file_->asked.insert(key_path(key));
  const toml::node* n = table_->get(key);
  if (n != nullptr) file_->used.insert(key_path(key));
  return n;
}

const toml::node& CaseTable::require(std::string_view key) const {
  const toml::node* n = get(key);
  if (n == nullptr) {
    const std::string hint = nearest_name(key, keys());
    if (!hint.empty())
      fail(hint, fmt::format("unknown key (did you mean '{}'? it is required)", key));
    fail({}, fmt::format("missing required key '{}'", key));
  }
  return *n;
}

namespace {
// `element`: the key names an element of an array (e.g. "lo[1]"); errors then point at the
// element's own line, not the table's.
double as_number(const CaseTable& t, std::string_view key, const toml::node& n, const Limits& lim,
                 bool element = false) {
  auto fail = [&](const std::string& message) {
    if (!element) t.fail(key, message);
    throw InputError(t.file().string(), t.key_path(key), static_cast<long>(n.source().begin.line),
                     message);
  };
  double v = 0;
  if (auto f = n.as_floating_point()) {
    v = f->get();
  } else if (auto i = n.as_integer()) {
    v = static_cast<double>(i->get());
  } else {
    fail(fmt::format("expected a number, got {} {}", type_name(n), show(n)));
  }
  if (!std::isfinite(v)) fail(fmt::format("value {} is not a finite number", v));
  if (!lim.contains(v)) fail(fmt::format("value {} out of range: must be {}", v, lim.describe()));
  return v;
}
}  // namespace

double CaseTable::number(std::string_view key, const Limits& lim) const {
  return as_number(*this, key, require(key), lim);
}
double CaseTable::number(std::string_view key, const Limits& lim, double fallback) const {
  const toml::node* n = get(key);
  return n ? as_number(*this, key, *n, lim) : fallback;
}

std::int64_t CaseTable::integer(std::string_view key, std::int64_t lo, std::int64_t hi) const {
  const toml::node& n = require(key);
  auto i = n.as_integer();
  if (!i) fail(key, fmt::format("expected an integer, got {} {}", type_name(n), show(n)));
  if (i->get() < lo || i->get() > hi)
    fail(key, fmt::format("value {} out of range: must be in [{}, {}]", i->get(), lo, hi));
  return i->get();
}
std::int64_t CaseTable::integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                                std::int64_t fallback) const {
  return has(key) ? integer(key, lo, hi) : fallback;
}

bool CaseTable::boolean(std::string_view key) const {
  const toml::node& n = require(key);
  auto b = n.as_boolean();
  if (!b) fail(key, fmt::format("expected true or false, got {} {}", type_name(n), show(n)));
  return b->get();
}
bool CaseTable::boolean(std::string_view key, bool fallback) const {
  return has(key) ? boolean(key) : fallback;
}

std::string CaseTable::string(std::string_view key) const {
  const toml::node& n = require(key);
  auto s = n.as_string();
  if (!s) fail(key, fmt::format("expected a string, got {} {}", type_name(n), show(n)));
  return s->get();
}
std::string CaseTable::string(std::string_view key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string CaseTable::choice(std::string_view key, const std::vector<std::string>& choices) const {
  std::string v = string(key);
  if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
    std::string hint = nearest_name(v, choices);
    fail(key, fmt::format("unknown value \"{}\": expected one of {}{}", v, fmt::join(choices, ", "),
                          hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
  }
  return v;
}
std::string CaseTable::choice(std::string_view key, const std::vector<std::string>& choices,
                              const std::string& fallback) const {
  return has(key) ? choice(key, choices) : fallback;
}

std::vector<double> CaseTable::numbers(std::string_view key, const Limits& lim) const {
  const toml::node& n = require(key);
  auto arr = n.as_array();
  if (!arr)
    fail(key, fmt::format("expected an array of numbers, got {} {}", type_name(n), show(n)));
  std::vector<double> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const toml::node& e = *arr->get(i);
    std::string k = fmt::format("{}[{}]", key, i);
    out.push_back(as_number(*this, k, e, lim, true));
  }
  return out;
}
std::vector<double> CaseTable::numbers(std::string_view key, const Limits& lim,
                                       const std::vector<double>& fallback) const {
  return has(key) ? numbers(key, lim) : fallback;
}

Vec3 CaseTable::vec3(std::string_view key, const Limits& lim) const {
  std::vector<double> v = numbers(key, lim);
  if (v.size() != 3) fail(key, fmt::format("expected 3 numbers [x, y, z], got {}", v.size()));
  return {v[0], v[1], v[2]};
}
Vec3 CaseTable::vec3(std::string_view key, const Limits& lim, const Vec3& fallback) const {
  return has(key) ? vec3(key, lim) : fallback;
}

std::vector<std::string> CaseTable::strings(std::string_view key) const {
  const toml::node& n = require(key);
  auto arr = n.as_array();
  if (!arr) fail(key, fmt::format("expected an array of strings, got {}", type_name(n)));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    auto s = arr->get(i)->as_string();
    if (!s)
      throw InputError(file_->path.string(), fmt::format("{}[{}]", key_path(key), i),
                       static_cast<long>(arr->get(i)->source().begin.line),
                       fmt::format("element {} is not a string", i));
    out.push_back(s->get());
  }
  return out;
}

std::filesystem::path CaseTable::file_path(std::string_view key) const {
  std::filesystem::path p = string(key);
  if (p.empty()) fail(key, "the path is empty");
  if (!p.is_absolute()) p = file_->path.parent_path() / p;
  file_->files[key_path(key)] = p;
  return p;
}

std::filesystem::path CaseTable::input_file(std::string_view key) const {
  const std::filesystem::path p = file_path(key);
  std::error_code ec;
  if (!std::filesystem::exists(p, ec)) fail(key, fmt::format("no such file '{}'", p.string()));
  if (std::filesystem::is_directory(p, ec))
    fail(key, fmt::format("'{}' is a directory, not a data file", p.string()));
  if (!std::filesystem::is_regular_file(p, ec))  // a device or pipe may never end
    fail(key, fmt::format("'{}' is not a regular file", p.string()));
  return p;
}

CaseTable CaseTable::table(std::string_view key) const {
  const toml::node& n = require(key);
  auto t = n.as_table();
  if (!t) fail(key, fmt::format("expected a table [{}], got {}", key_path(key), type_name(n)));
  return CaseTable(t, key_path(key), file_);
}

std::optional<CaseTable> CaseTable::optional_table(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<CaseTable> CaseTable::tables(std::string_view key) const {
  std::vector<CaseTable> out;
  const toml::node* n = get(key);
  if (n == nullptr) return out;
  auto arr = n->as_array();
  if (!arr) {
    if (auto t = n->as_table()) {  // a single [key] table is accepted as a one-element array
      out.emplace_back(t, key_path(key), file_);
      return out;
    }
    fail(key,
         fmt::format("expected an array of tables [[{}]], got {}", key_path(key), type_name(*n)));
  }
  for (std::size_t i = 0; i < arr->size(); ++i) {
    auto t = arr->get(i)->as_table();
    if (!t)
      throw InputError(file_->path.string(), fmt::format("{}[{}]", key_path(key), i),
                       static_cast<long>(arr->get(i)->source().begin.line),
                       fmt::format("element {} is not a table", i));
    out.emplace_back(t, fmt::format("{}[{}]", key_path(key), i), file_);
  }
  return out;
}

CaseFile CaseFile::load(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "", 0, "file not found");
  if (std::filesystem::is_directory(path))
    throw InputError(path.string(), "", 0, "is a directory, not a case file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", 0, "cannot be read");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CaseFile f = parse(text, path.string());
  f.state_->path = path;
  return f;
}
CaseFile CaseFile::parse(std::string_view text, const std::string& name) {
  auto st = std::make_shared<CaseFileState>();
  st->path = name;
  check_case_text(text, name);
  try {
    st->doc = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw InputError(name, "", static_cast<long>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  check_case_keys(st->doc, name);
  CaseFile f;
  f.state_ = st;
  return f;
}

CaseTable CaseFile::root() const {
  return CaseTable(&state_->doc, "", state_);
}
const std::filesystem::path& CaseFile::path() const {
  return state_->path;
}
std::map<std::string, std::filesystem::path> CaseFile::data_files() const {
  return state_->files;
}
std::set<std::string> CaseFile::used_keys() const {
  return state_->used;
}

namespace {
struct Unknown {
  long line;
  std::string path;
  std::vector<std::string> siblings;
};

void collect_unknown(const toml::table& t, const std::string& base, const CaseFileState& st,
                     std::vector<Unknown>& out) {
  // the keys readers asked for in this table, for "did you mean" suggestions
  std::vector<std::string> known;
  const std::string prefix = base.empty() ? "" : base + ".";
  for (auto it = st.asked.lower_bound(prefix); it != st.asked.end(); ++it) {
    if (it->compare(0, prefix.size(), prefix) != 0) break;
    const std::string leaf = it->substr(prefix.size());
    if (leaf.find_first_of(".[") == std::string::npos) known.push_back(leaf);
  }
  for (const auto& [k, v] : t) {
    std::string p = join_path(base, k.str());
    if (!st.used.count(p)) {
      out.push_back({static_cast<long>(v.source().begin.line), p, known});
      continue;
    }
    if (auto sub = v.as_table()) collect_unknown(*sub, p, st, out);
    if (auto arr = v.as_array())
      for (std::size_t i = 0; i < arr->size(); ++i)
        if (auto e = arr->get(i)->as_table())
          collect_unknown(*e, fmt::format("{}[{}]", p, i), st, out);
  }
}
}  // namespace

void CaseFile::reject_unknown() const {
  std::vector<Unknown> unknown;
  collect_unknown(state_->doc, "", *state_, unknown);
  if (unknown.empty()) return;
  auto first = std::min_element(unknown.begin(), unknown.end(),
                                [](const Unknown& a, const Unknown& b) { return a.line < b.line; });
  std::string leaf = first->path.substr(first->path.find_last_of('.') + 1);
  std::string hint = nearest_name(leaf, first->siblings);
  throw InputError(
      state_->path.string(), first->path, first->line,
      fmt::format(
          "unknown key{}{}", hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint),
          unknown.size() > 1 ? fmt::format("; {} unknown keys in all", unknown.size()) : ""));
}

std::string nearest_name(std::string_view name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const auto& c : candidates) {
    // Levenshtein distance
    std::vector<std::size_t> prev(c.size() + 1), cur(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= name.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= c.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (name[i - 1] != c[j - 1])});
      std::swap(prev, cur);
    }
    if (prev[c.size()] < best_d && c != name) {
      best_d = prev[c.size()];
      best = c;
    }
  }
  return best;
}

}  // namespace comminute
