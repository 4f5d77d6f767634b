#pragma once
// A ParameterSource over a plain map, for building breakage models in tests without a case file.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "comminute/breakage/criteria/parameter_source.hpp"
#include "comminute/core/error.hpp"

namespace comminute::breakage::test_support {

class MapParameters final : public ParameterSource {
 public:
  std::map<std::string, double> values;
  std::map<std::string, std::vector<double>> lists;
  std::map<std::string, std::string> words;

  double number(const std::string& key, double lo, double hi, bool lo_open,
                double fallback) const override {
    auto it = values.find(key);
    if (it == values.end()) {
      if (fallback != fallback) fail(key, "required");
      return fallback;
    }
    const double v = it->second;
    if (v < lo || v > hi || (lo_open && v == lo)) fail(key, "out of range");
    return v;
  }
  std::vector<double> numbers(const std::string& key, double, double) const override {
    auto it = lists.find(key);
    if (it == lists.end()) fail(key, "required");
    return it->second;
  }
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback) const override {
    auto it = words.find(key);
    if (it == words.end()) return fallback;
    if (std::find(choices.begin(), choices.end(), it->second) == choices.end())
      fail(key, "not a choice");
    return it->second;
  }
  bool has(const std::string& key) const override {
    return values.count(key) || lists.count(key) || words.count(key);
  }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const override {
    throw Error(key + ": " + message);
  }
};

}  // namespace comminute::breakage::test_support
