// The fingerprint of a case file: one hash per top-level table (and the data files it names), so
// that a checkpoint can refuse a restart with another case.
#include <fmt/format.h>

#include <fstream>
#include <iterator>

#include "comminute/core/case_file_state.hpp"
#include "comminute/core/case_table.hpp"

namespace comminute {

namespace {

// A canonical text of a TOML value for fingerprints: keys in name order, numbers in their shortest
// exact form, strings with their length. (toml++ 3.3.0's own formatter has undefined behaviour on
// floats below 1, so it is not used.)
void canonical(const toml::node& n, std::string& out) {
  if (auto t = n.as_table()) {
    out += '{';
    for (const auto& [k, v] : *t) {
      out += fmt::format("{}:{}=", k.str().size(), k.str());
      canonical(v, out);
      out += ';';
    }
    out += '}';
  } else if (auto a = n.as_array()) {
    out += '[';
    for (const auto& e : *a) {
      canonical(e, out);
      out += ',';
    }
    out += ']';
  } else if (auto str = n.as_string()) {
    out += fmt::format("s{}:{}", str->get().size(), str->get());
  } else if (auto i = n.as_integer()) {
    out += fmt::format("i{}", i->get());
  } else if (auto f = n.as_floating_point()) {
    out += fmt::format("f{}", f->get());
  } else if (auto b = n.as_boolean()) {
    out += b->get() ? "b1" : "b0";
  } else if (auto d = n.as_date()) {
    const toml::date& v = d->get();
    out += fmt::format("d{}-{}-{}", v.year, v.month, v.day);
  } else if (auto tm = n.as_time()) {
    const toml::time& v = tm->get();
    out += fmt::format("t{}:{}:{}.{}", v.hour, v.minute, v.second, v.nanosecond);
  } else if (auto dt = n.as_date_time()) {
    const toml::date_time& v = dt->get();
    out += fmt::format("D{}-{}-{}T{}:{}:{}.{}Z{}", v.date.year, v.date.month, v.date.day,
                       v.time.hour, v.time.minute, v.time.second, v.time.nanosecond,
                       v.offset ? v.offset->minutes : 100000);
  }
}

}  // namespace

std::vector<std::pair<std::string, std::string>> CaseFile::fingerprint() const {
  std::vector<std::pair<std::string, std::string>> out;
  auto mix = [](std::uint64_t h, std::string_view bytes) {
    for (char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    return h;
  };
  for (const auto& [k, v] : state_->doc) {
    const std::string key(k.str());
    if (key == "output") continue;
    std::string text;
    if (key == "simulation" && v.is_table()) {
      toml::table t = *v.as_table();
      t.erase("end_time");
      canonical(t, text);
    } else {
      canonical(v, text);
    }
    std::uint64_t h = mix(0xcbf29ce484222325ull, text);
    for (const auto& [kp, file] : state_->files) {
      if (kp != key && !kp.starts_with(key + ".") && !kp.starts_with(key + "[")) continue;
      std::ifstream in(file, std::ios::binary);
      const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      h = mix(mix(h, kp), bytes);
    }
    out.emplace_back(key, fmt::format("{:016x}", h));
  }
  return out;
}

}  // namespace comminute
